#!/usr/bin/env bash
# Camera paths in the window (issue 37). A script records a path by pressing the record hotkey (K) while it
# moves the camera; the window saves NAME.path.json and its sidecar NAME.json beside the screenshots. The
# saved file replays with `raylab render --camera-path` at a small size, and every one of its frames is the
# unsorted frame bit for bit under sorting key strategies (the invariant, frame by frame through
# --frame-digests). The window then plays the saved path (--camera-path): its render of the last path frame is
# byte for byte render's last frame of the same path. A path that cannot be read is refused with exit 2.
set -eu
raylab="$1"
source "$(dirname "$0")/../window_test_setup.sh"  # skips without a window; temporary folder; validation on
size=(--window-size 320x180 --scale 0.25)  # an 80x45 render
cat >record.txt <<'S'
set bounces 2
set strategy average
camera 0 4 -29 0 6 -66
wait 1
press K
wait 1
camera 2 4.5 -33 0 6 -66 fov 40
wait 1
camera 5 5 -37 -2 6 -66
wait 1
press K
wait 1
quit
S
timeout 600 bash "$on_xvfb" 1280x720x24 "$raylab" "${size[@]}" --screenshot-dir shots --script record.txt \
  >record.log 2>&1 || { echo "FAIL: the recording run exited $?"; tail -20 record.log; exit 1; }
path=$(ls shots/path-*.path.json)
sidecar=${path%.path.json}.json
[ -f "$sidecar" ] || { echo "FAIL: no sidecar beside $path"; ls shots; exit 1; }
grep -q "saved $path" record.log || { echo "FAIL: the window did not say where the path went"; tail record.log; exit 1; }
read -r frames jump < <(python3 - "$path" "$sidecar" <<'PY'
import json, os, sys
path, side = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
k = path['keyframes']
assert path['frames'] == len(k) >= 3, (path['frames'], len(k))
assert [x['frame'] for x in k] == list(range(len(k)))  # one keyframe per UI frame, numbered from 0
assert k[0]['position'] == [0, 4, -29] and k[0]['target'] == [0, 6, -66], k[0]
assert k[-1]['position'] == [5, 5, -37] and k[-1]['target'] == [-2, 6, -66], k[-1]
assert any(x['position'] == [2, 4.5, -33] and x['fov'] == 40 for x in k), 'the middle camera was not recorded'
assert side['kind'] == 'camera-path' and side['camera_path'] == os.path.basename(sys.argv[1]), side
assert side['path_frames'] == len(k) and side['settings']['frames'] == len(k)
assert side['settings']['strategy'] == 'average' and side['settings']['bounces'] == 2
assert side['camera']['position'] == [0, 4, -29], side['camera']
assert 'replay' in side and 'image' not in side
# The first frame of the last camera: the frame before it shows another camera, so a shot of it tells
# whether the window's path frames are render's, not one frame off.
print(len(k), next(i for i, x in enumerate(k) if x['position'] == [5, 5, -37]))
PY
)
[ -n "${jump:-}" ] || { echo "FAIL: the saved path or its sidecar"; exit 1; }

# The replay, unsorted and with sorting strategies: the same frames, bit for bit, every path frame.
for s in none average two-point gaussian; do
  "$raylab" render --settings "$sidecar" --camera-path "$path" --size 48x24 --strategy $s --sort radix \
    --sort-policy always --stats "$s.json" --frame-digests --out "$s.png" >"$s.log" 2>&1 ||
    { echo "FAIL: render --camera-path $path ($s) exited $?"; tail "$s.log"; exit 1; }
done
python3 - "$frames" none.json average.json two-point.json gaussian.json <<'PY'
import json, sys
frames = int(sys.argv[1])
runs = {name: json.load(open(name)) for name in sys.argv[2:]}
digests = {name: [f['radiance_digest'] for f in doc['frames']] for name, doc in runs.items()}
unsorted = digests['none.json']
assert len(unsorted) == frames, (len(unsorted), frames)
assert len(set(unsorted)) >= 3, 'the replayed frames should differ where the camera moved: %s' % unsorted
for name, doc in runs.items():
    assert [f['path_frame'] for f in doc['frames']] == list(range(frames)), name
    assert digests[name] == unsorted, '%s differs from unsorted at path frames %s' % (
        name, [i for i, (a, b) in enumerate(zip(digests[name], unsorted)) if a != b])
    if name != 'none.json':
        assert all(b['sort_reason'] == 'always' for f in doc['frames'] for b in f['bounces'][:1]), name
print('ok: %d path frames, sorted = unsorted for every strategy' % frames)
PY

# The window plays the saved path: after path frames 0..J-1, its shot is path frame J, the last of a render of
# J+1 frames (and the first of the last camera, which frame J-1 does not show).
printf 'wait %d\nscreenshot played\nquit\n' "$jump" >play.txt
timeout 600 bash "$on_xvfb" 1280x720x24 "$raylab" "${size[@]}" --camera-path "$path" --screenshot-dir shots \
  --script play.txt >play.log 2>&1 || { echo "FAIL: the playing run exited $?"; tail -20 play.log; exit 1; }
"$raylab" render --settings shots/played.json --camera-path "$path" --frames $((jump + 1)) --out replayed.png \
  >replayed.log 2>&1 ||
  { echo "FAIL: render of the played shot's settings exited $?"; tail replayed.log; exit 1; }
cmp -s shots/played.png replayed.png || { echo "FAIL: the window's path frame $jump is not render's"; exit 1; }
"$raylab" render --settings shots/played.json --camera-path "$path" --frames "$jump" --out before.png >/dev/null 2>&1
! cmp -s shots/played.png before.png || { echo "FAIL: path frames $((jump - 1)) and $jump look alike: the check is blind"; exit 1; }
echo "ok: the window plays the path as render replays it (path frame $jump of $frames)"

# A path the window cannot play: exit 2 before any window, naming it.
rc=0
out=$(timeout 300 bash "$on_xvfb" 1280x720x24 "$raylab" "${size[@]}" --camera-path missing.json --script play.txt 2>&1) || rc=$?
[ "$rc" = 2 ] && grep -q "cannot open 'missing.json'" <<<"$out" || { echo "FAIL: exit $rc for a missing path: $out"; exit 1; }
echo "ok: a missing path is refused"
