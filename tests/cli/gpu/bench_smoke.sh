#!/usr/bin/env bash
# `raylab bench` runs a tiny sweep end to end: baselines plus the asked strategies, every cell in the CSV and
# the JSONL, one identical final image error for every wavefront cell (sorting never changes the image),
# and a usage error (exit 2) for a bad sweep value. Then the scene-scale sweep at tiny sizes: a case per
# --scale-tris size and a group per --bounces count, rows that carry the triangle count and BVH bytes, and
# the crossover charts drawn from them.
set -eu
raylab="$1"
source_dir="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
RAYLAB_VALIDATE=1 "$raylab" bench --cases cornell@front --strategies dead-last,gaussian --sorts radix,bitonic \
  --gauss-resets 20,inf --sort-bits-list 0,8 --size 24x16 --timed-frames 2 --warmup 0 --reference-spp 2 --rounds 1 --out-dir "$dir" > "$dir/log" 2>&1
python3 - "$dir" <<'PY'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1] + '/results.csv')))
labels = [r['label'] for r in rows]
# megakernel, none, dead-last x 2 sorts x 2 sorted key bits, gaussian x 2 sorts x 2 resets x 2 sorted key bits
assert labels[:2] == ['megakernel', 'none'], labels
assert len(rows) == 2 + 4 + 8, labels
assert any('reset=inf' in l for l in labels), labels
assert sum(r['sort_bits'] == '8' and 'bits=8' in r['label'] for r in rows) == 6, labels
jsonl = [json.loads(l) for l in open(sys.argv[1] + '/results.jsonl')]
assert len(jsonl) == len(rows)
errors = {r['final_rel_mse'] for r in rows if r['kernel'] == 'wavefront'}
assert len(errors) == 1, errors
for r in rows:
    assert float(r['frame_ms_median']) > 0, r
print('ok', len(rows), 'cells')
PY
set +e
"$raylab" bench --sorts quick > /dev/null 2>&1
[ $? -eq 2 ] || { echo "FAIL: bad --sorts did not exit 2"; exit 1; }
set -e

# The fusion axis: one cell per fusion, the CSV's fusion column, and the same image in each.
RAYLAB_VALIDATE=1 "$raylab" bench --cases temple@openings --strategies fixed --fusions none,keys,gather,both \
  --size 24x16 --bounces 3 --timed-frames 1 --warmup 0 --reference-spp 1 --no-detail --out-dir "$dir/fusion" \
  > "$dir/fusion.log" 2>&1 || { cat "$dir/fusion.log"; exit 1; }
python3 - "$dir/fusion" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1] + '/results.csv')) if r['strategy'] == 'fixed']
assert sorted(r['fusion'] for r in rows) == ['both', 'gather', 'keys', 'none'], [r['fusion'] for r in rows]
assert len({r['final_rel_mse'] for r in rows}) == 1, [r['final_rel_mse'] for r in rows]
for r in rows:
    # A stage a cell does not run is not measured: an empty cell, not 0.
    assert (r['reorder_ms'] != '') == (r['fusion'] in ('none', 'keys')), r
    assert (r['keys_ms'] != '') == (r['fusion'] in ('none', 'gather')), r
    assert all(float(r[k]) > 0 for k in ('reorder_ms', 'keys_ms') if r[k]), r
print('ok: fusions', sorted(r['fusion'] for r in rows))
PY

# The compaction axis: the unsorted baseline and the auto-policy cells once each way, the CSV's compaction
# column, and the same image in each.
RAYLAB_VALIDATE=1 "$raylab" bench --cases temple@openings --strategies fixed --sort-policies auto \
  --compactions none,shade --size 24x16 --bounces 3 --timed-frames 1 --warmup 0 --reference-spp 1 --no-detail \
  --out-dir "$dir/compaction" > "$dir/compaction.log" 2>&1 || { cat "$dir/compaction.log"; exit 1; }
python3 - "$dir/compaction" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1] + '/results.csv')) if r['kernel'] == 'wavefront']
got = sorted((r['strategy'], r['compaction']) for r in rows)
assert got == [('fixed', 'none'), ('fixed', 'shade'), ('none', 'none'), ('none', 'shade')], got
assert len({r['final_rel_mse'] for r in rows}) == 1, [r['final_rel_mse'] for r in rows]
assert any(r['label'] == 'none compaction=none' for r in rows), [r['label'] for r in rows]
print('ok: compactions', got)
PY

RAYLAB_VALIDATE=1 "$raylab" bench --scale-tris 1e4,2e4 --bounces 1,2 --strategies two-point --size 16x8 \
  --timed-frames 1 --warmup 0 --reference-spp 1 --no-detail --out-dir "$dir/scale" > "$dir/scale.log" 2>&1 ||
  { cat "$dir/scale.log"; exit 1; }
python3 - "$dir/scale" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1] + '/results.csv')))
# 2 sizes x 2 bounce counts x (megakernel, none, two-point), size-major, then bounce count
assert len(rows) == 12, [(r['scene'], r['bounces'], r['label']) for r in rows]
assert [r['scene'] for r in rows] == ['temple-detail:1e4'] * 6 + ['temple-detail:2e4'] * 6, [r['scene'] for r in rows]
assert [r['bounces'] for r in rows] == (['1'] * 3 + ['2'] * 3) * 2, [r['bounces'] for r in rows]
assert {r['view'] for r in rows} == {'hall'}
facts = {}
for r in rows:
    facts.setdefault(r['scene'], set()).add((int(r['triangles']), int(r['bvh_nodes']), int(r['bvh_bytes'])))
small, large = facts['temple-detail:1e4'], facts['temple-detail:2e4']
assert len(small) == 1 and len(large) == 1, facts  # one scene per case
(t1, n1, b1), (t2, n2, b2) = small.pop(), large.pop()
assert abs(t1 - 1e4) <= 100 and abs(t2 - 2e4) <= 200, (t1, t2)
assert n1 > 0 and b1 > 48 * t1 and b2 > b1 and n2 > n1, (n1, b1, n2, b2)
for scene in facts:
    for bounces in ('1', '2'):
        errors = {r['final_rel_mse'] for r in rows if r['scene'] == scene and r['bounces'] == bounces and r['kernel'] == 'wavefront'}
        assert len(errors) == 1, (scene, bounces, errors)  # sorted renders the unsorted image
print('ok: scale sweep', t1, t2, 'triangles, BVH', b1, b2, 'bytes')
PY
if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  /usr/bin/python3 "$source_dir/app/bench/bench_charts.py" "$dir/scale" > /dev/null
  for chart in crossover_triangles_hall.png crossover_bounces_hall.png stages_temple-detail-1e4-hall-b2.png; do
    [ -s "$dir/scale/$chart" ] || { echo "FAIL: bench_charts.py drew no $chart"; ls "$dir/scale"; exit 1; }
  done
  # The stacked stages are the CSV's stage columns (renderer/stages.h's order) that some cell timed.
  /usr/bin/python3 - "$source_dir/app/bench" "$dir/scale" <<'PY'
import json, sys
sys.path.insert(0, sys.argv[1])
folder = sys.argv[2]
sys.argv = sys.argv[:1]
import bench_charts
_, _, stages = bench_charts.load(folder)
timed = set()
for line in open(folder + '/results.jsonl'):
    timed.update(json.loads(line)['result']['stage_ms'])
assert set(stages) == timed and len(stages) >= 3, (stages, timed)
header = open(folder + '/results.csv').readline().strip().split(',')
columns = [header.index(s + '_ms') for s in stages]
assert columns == sorted(columns), (header, stages)  # in the CSV's (kStages') order
assert bench_charts.stage_columns(['frame_ms_median', 'trace_ms', 'heatmap_ms', 'x'], {'heatmap', 'trace'}) == ['trace', 'heatmap']
print('ok: stacked stages', stages)
PY
else
  echo "matplotlib missing: the crossover charts are not checked"
fi
