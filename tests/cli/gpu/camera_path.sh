#!/usr/bin/env bash
# `raylab render --camera-path`: one stats frame per path frame with its camera and cut flag, the cut where
# the path has it; bad paths and flags that make no sense with a path exit 2 with a short message.
set -eu
raylab="$1"
src="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
small=(--size 48x24 --bounces 2)

RAYLAB_VALIDATE=1 "$raylab" render --camera-path builtin:cut --frames 4 "${small[@]}" --out "$dir/b.png" \
  --stats "$dir/b.json" >/dev/null 2>&1
# A file path with a cut at frame 2, capped at 4 of its 6 frames.
RAYLAB_VALIDATE=1 "$raylab" render --camera-path "$src/tests/data/camera_paths/cut_at_2.json" --frames 4 \
  --strategy average "${small[@]}" --out "$dir/f.png" --stats "$dir/f.json" >/dev/null 2>&1
python3 - "$dir/b.json" "$dir/f.json" <<'PY'
import json, sys
b, f = (json.load(open(p)) for p in sys.argv[1:3])
for doc in (b, f):
    frames = doc['frames']
    assert len(frames) == 4, len(frames)
    assert [x['path_frame'] for x in frames] == [0, 1, 2, 3]
    for x in frames:
        assert len(x['camera']['position']) == 3 and len(x['camera']['target']) == 3 and x['camera']['fov'] > 0, x['camera']
        assert x['frame'] == 0, 'every path frame is a fresh image'
assert b['view'] == 'builtin:cut' and b['camera_path']['path_frames'] == 240
assert [x['cut'] for x in b['frames']] == [False] * 4  # its first cut is at frame 30
assert [x['cut'] for x in f['frames']] == [False, False, True, False], [x['cut'] for x in f['frames']]
assert f['frames'][2]['camera']['position'] == [-15, 1.7000000476837158, 8], f['frames'][2]['camera']
assert f['frames'][2]['bounces'][1]['sort_reason'] is not None
print('ok: camera paths')
PY

# Refusals: exit 2, at most 5 lines, naming the problem.
refuse() {
  local want="$1"; shift
  local out rc=0
  out=$("$raylab" render --size 16x8 --out "$dir/x.png" "$@" 2>&1) || rc=$?
  [ "$rc" = 2 ] || { echo "FAIL: exit $rc for $*: $out"; exit 1; }
  [ "$(wc -l <<<"$out")" -le 5 ] || { echo "FAIL: too long for $*: $out"; exit 1; }
  grep -qF -- "$want" <<<"$out" || { echo "FAIL: no '$want' for $*: $out"; exit 1; }
}
refuse "not_increasing.json: keyframe 2: frame 10 is not after keyframe 1's frame 10" \
  --camera-path "$src/tests/data/camera_paths/not_increasing.json"
refuse "line 2, column" --camera-path "$src/tests/data/camera_paths/syntax_error.json"
refuse "cannot open" --camera-path "$dir/missing.json"
refuse "the built-in paths of temple are: orbit, walk, cut" --camera-path builtin:list
refuse "did you mean builtin:walk?" --camera-path builtin:wallk
refuse "not both" --camera-path builtin:orbit --camera "0 5 0 0 5 -1"
refuse "not both" --camera-path builtin:orbit --view hall
refuse "--time-budget does not apply" --camera-path builtin:orbit --time-budget 2
refuse "needs a value" --camera-path
[ ! -e "$dir/x.png" ] || { echo "FAIL: a refused render wrote its image"; exit 1; }
echo "ok: refusals"
