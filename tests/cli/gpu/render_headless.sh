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

# --detail-every N: the detailed figures on frames 0, N, 2N..., "not measured" (null) on the others, whose
# measuring passes (instrument_ms) are absent too; work_ms is the frame without them.
RAYLAB_VALIDATE=1 "$raylab" render --scene temple --view hall --size 40x20 --frames 4 --strategy average \
  --detail-every 2 --out "$dir/d.png" --stats "$dir/d.json" >/dev/null
python3 - "$dir/d.json" <<'PY'
import json, sys
frames = json.load(open(sys.argv[1]))['frames']
assert [f['detailed'] for f in frames] == [True, False, True, False], [f['detailed'] for f in frames]
for f in frames:
    b1 = f['bounces'][1]
    measured = [b1[k] is not None for k in ('virtual_warp_efficiency', 'mean_traversal_steps', 'prediction_error_median', 'cell_hit_rate', 'distinct_keys')]
    measured.append(f['length_cache_occupancy'] is not None)
    assert measured == [f['detailed']] * len(measured), (f['frame'], measured)
    assert abs(f['work_ms'] + f['instrument_ms'] - f['gpu_frame_ms']) < 1e-6 * f['gpu_frame_ms'] + 1e-9, f
    counters = sum(s['ms'] for s in f['stages'] if s['stage'] == 'counters')
    assert abs(counters - f['instrument_ms']) < 1e-9, (counters, f['instrument_ms'])
print('ok: --detail-every 2')
PY
out=$("$raylab" render --size 16x8 --detail-every 2 --out "$dir/e.png" 2>&1) && { echo "FAIL: --detail-every without --stats ran"; exit 1; }
grep -q "needs --stats" <<<"$out" || { echo "FAIL: $out"; exit 1; }

# A time budget accumulates frames until it is spent and says so; the stats name what ended the render. No
# assertion on how many frames fit: that is the machine's speed (a loaded 2-core machine under ASan took
# longer than the whole budget for the first frame). A budget far beyond --frames leaves the frames to end it.
out=$(RAYLAB_VALIDATE=1 "$raylab" render --size 16x8 --time-budget 1.5 --frames 100000 --out "$dir/b.png" --stats "$dir/b.json" 2>&1)
RAYLAB_VALIDATE=1 "$raylab" render --size 16x8 --time-budget 3600 --frames 2 --out "$dir/c.png" --stats "$dir/c.json" >/dev/null 2>&1
python3 - "$dir/b.json" "$dir/c.json" <<'PY'
import json, sys
b, c = (json.load(open(p)) for p in sys.argv[1:3])
assert b['stopped_by'] == 'time budget' and 1 <= len(b['frames']) < 100000, (b['stopped_by'], len(b['frames']))
assert c['stopped_by'] == 'frames' and len(c['frames']) == 2, (c['stopped_by'], len(c['frames']))
print('ok: time budget', len(b['frames']), 'frames')
PY
grep -q "accumulating for 1.5 s" <<<"$out" || { echo "FAIL: no budget message"; echo "$out"; exit 1; }

# --bvh wide renders with the wide BVH: the stats say so, give its size, and count its own (fewer) steps per
# camera ray than the binary tree's for the same frame (tests/gpu/bvh/test_bvh_wide_render.cpp compares the images).
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
