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

# --bvh wide renders with the wide BVH: the stats say so, give its size, and count its own (fewer) steps per
# camera ray than the binary tree's for the same frame (tests/gpu/test_bvh_wide_render.cpp compares the images).
for bvh in binary wide; do
  RAYLAB_VALIDATE=1 "$raylab" render --bvh $bvh --scene temple --view hall --size 33x17 --out "$dir/$bvh.png" \
    --stats "$dir/$bvh.json" >/dev/null
done
python3 - "$dir/binary.json" "$dir/wide.json" <<'PY'
import json, sys
b, w = (json.load(open(p)) for p in sys.argv[1:3])
assert b['settings']['bvh'] == 'binary' and w['settings']['bvh'] == 'wide', (b['settings']['bvh'], w['settings']['bvh'])
assert 0 < w['wide_bvh_nodes'] < w['bvh_nodes'], (w['wide_bvh_nodes'], w['bvh_nodes'])
assert w['wide_bvh_tree_bytes'] > 0
steps = lambda s: s['frames'][0]['bounces'][0]['mean_traversal_steps']
assert 0 < steps(w) < 0.7 * steps(b), (steps(w), steps(b))
assert w['rays_traced'] == b['rays_traced'] or abs(w['rays_traced'] - b['rays_traced']) < 0.01 * b['rays_traced']
print('ok: wide BVH, mean camera-ray steps %.2f against binary %.2f' % (steps(w), steps(b)))
PY
