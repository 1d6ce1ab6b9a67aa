#!/usr/bin/env bash
# `raylab render` writes a PNG of the requested size and a stats JSON, with validation on.
set -eu
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
RAYLAB_VALIDATE=1 "$raylab" render --scene temple --view openings --size 37x23 --frames 2 \
  --out "$dir/a.png" --stats "$dir/a.json"
python3 - "$dir/a.png" "$dir/a.json" <<'PY'
import json, struct, sys
png = open(sys.argv[1], 'rb').read()
assert png[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
w, h = struct.unpack('>II', png[16:24])
assert (w, h) == (37, 23), (w, h)
stats = json.load(open(sys.argv[2]))
assert stats['settings']['width'] == 37 and len(stats['frames']) == 2
assert stats['rays_traced'] > 37 * 23, stats['rays_traced']
print('ok', w, h, stats['rays_per_second'])
PY

# A time budget accumulates frames until it is spent (here 1.5 s: more than one 16x8 frame, far fewer than
# the ceiling --frames gives), and says so.
out=$(RAYLAB_VALIDATE=1 "$raylab" render --size 16x8 --time-budget 1.5 --frames 100000 --out "$dir/b.png" --stats "$dir/b.json" 2>&1)
python3 - "$dir/b.json" <<'PY'
import json, sys
frames = len(json.load(open(sys.argv[1]))['frames'])
assert 1 < frames < 100000, frames
print('ok: time budget', frames, 'frames')
PY
grep -q "accumulating for 1.5 s" <<<"$out" || { echo "FAIL: no budget message"; echo "$out"; exit 1; }
