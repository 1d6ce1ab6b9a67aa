#!/usr/bin/env bash
# A bench sweep survives being killed (issue 23): results.jsonl gets each cell as it ends, so a sweep
# SIGKILLed after some cells and then run with `--resume DIR` measures only the missing cells (a cut-off
# last line is dropped) and ends with the same cells and the same non-timing columns as a sweep that was
# never interrupted. `--resume` refuses, with exit 2, a different sweep or a folder of another revision.
# bench_charts.py, run on the finished folder, stops non-zero naming a chart it cannot write (the sweeps run
# with --no-charts, so that the script draws every chart itself).
#
# Timing columns, which no two runs share: frame_ms_*, trace_after_first_ms, every *_ms stage column,
# rays_per_second (and the trace's), bvh_build_ms, sbvh_build_ms, scene_load_ms, tracer_setup_ms, empty_dispatch_us (fixed_cost_ms). Everything else (settings, labels,
# triangles and BVH bytes, final_rel_mse, key bits, prediction and coherence figures) must match. The
# sweep runs with --compaction none: with compaction the packing order of the live paths (one atomic per
# subgroup) follows what the tracer ran before, so the SIMT and virtual warp efficiency of cells whose order
# no sort fixes (none, dead-last) differ where a resumed sweep starts; its image, and so final_rel_mse, does
# not. Strategies without a length cache only: a cache learns over the warm-up, which is timed (>= 0.5 s).
# Two rounds: a record is one round of one cell, and the resume runs the rounds the kill left out.
set -eu
raylab="$1"
source_dir="$2"
dir=$(mktemp -d)
pid=
trap '[ -n "$pid" ] && kill -9 $pid 2>/dev/null; rm -rf "$dir"' EXIT
sweep=(--cases cornell@front --strategies dead-last,fixed,two-point --compaction none --size 32x16 --timed-frames 1 --no-charts
       --warmup 0 --reference-spp 1 --rounds 2)
cells=5  # megakernel, none, dead-last, fixed, two-point
records=$((cells * 2))

"$raylab" bench "${sweep[@]}" --out-dir "$dir/whole" >"$dir/whole.log" 2>&1 || { cat "$dir/whole.log"; exit 1; }

# Killed once the first cell is in results.jsonl: every cell warms up for at least half a second, so the
# sweep cannot have ended by then.
"$raylab" bench "${sweep[@]}" --out-dir "$dir/part" >"$dir/part.log" 2>&1 &
pid=$!
for _ in $(seq 1 1200); do
  [ -s "$dir/part/results.jsonl" ] && break
  kill -0 $pid 2>/dev/null || break
  sleep 0.05
done
kill -9 $pid
wait $pid 2>/dev/null || true
pid=
lines=$(wc -l <"$dir/part/results.jsonl")
[ "$lines" -ge 1 ] && [ "$lines" -lt $records ] || { echo "FAIL: killed with $lines of $records cell rounds"; cat "$dir/part.log"; exit 1; }
[ ! -e "$dir/part/results.csv" ] || { echo "FAIL: a results.csv from the killed sweep"; exit 1; }
printf '{"cell": %d, "label": "two-p' "$lines" >>"$dir/part/results.jsonl"  # what a kill mid-append leaves

"$raylab" bench "${sweep[@]}" --resume "$dir/part" >"$dir/resume.log" 2>&1 || { cat "$dir/resume.log"; exit 1; }
grep -q "resuming $dir/part: $lines of $records cell rounds done ($cells cells x 2 rounds) (a cut-off last line dropped)" "$dir/resume.log" ||
  { echo "FAIL: the resume did not say what it kept"; cat "$dir/resume.log"; exit 1; }
measured=$(grep -c '^\[' "$dir/resume.log")
[ "$measured" -eq $((records - lines)) ] || { echo "FAIL: the resume measured $measured cell rounds, not $((records - lines))"; exit 1; }

python3 - "$dir/whole" "$dir/part" <<'PY'
import csv, json, sys
whole, part = sys.argv[1], sys.argv[2]
records = [json.loads(line) for line in open(part + '/results.jsonl')]
assert sorted((r['cell'], r['round']) for r in records) == [(c, r) for c in range(5) for r in range(2)], records
def timing(column):
    return (column.endswith('_ms') or column.startswith('frame_ms') or column.startswith('trace_after_first_ms')
            or column.endswith('rays_per_second') or column.endswith('_us'))
a = list(csv.DictReader(open(whole + '/results.csv')))
b = list(csv.DictReader(open(part + '/results.csv')))
assert [r['label'] for r in a] == [r['label'] for r in b], ([r['label'] for r in a], [r['label'] for r in b])
compared = [c for c in a[0] if not timing(c)]
for x, y in zip(a, b):
    diff = {c: (x[c], y[c]) for c in compared if x[c] != y[c]}
    assert not diff, (x['label'], diff)
print('ok: killed and resumed, %d cells, %d non-timing columns equal' % (len(b), len(compared)))
PY

# Another sweep into the same folder, or the same sweep recorded at another revision: refused, exit 2.
set +e
"$raylab" bench "${sweep[@]}" --strategies fixed --resume "$dir/part" >"$dir/other.log" 2>&1
rc=$?
set -e
[ $rc -eq 2 ] || { echo "FAIL: a different sweep was resumed (exit $rc)"; cat "$dir/other.log"; exit 1; }
grep -q "a different sweep from the one recorded" "$dir/other.log" || { echo "FAIL: no reason"; cat "$dir/other.log"; exit 1; }
python3 - "$dir/part/sweep.json" <<'PY'
import json, sys
record = json.load(open(sys.argv[1]))
record['git_revision'] = '0000000'
json.dump(record, open(sys.argv[1], 'w'))
PY
set +e
"$raylab" bench "${sweep[@]}" --resume "$dir/part" >"$dir/revision.log" 2>&1
rc=$?
set -e
[ $rc -eq 2 ] || { echo "FAIL: a folder of another revision was resumed (exit $rc)"; cat "$dir/revision.log"; exit 1; }
grep -q "measured at revision 0000000" "$dir/revision.log" || { echo "FAIL: no reason"; cat "$dir/revision.log"; exit 1; }
echo "ok: --resume refuses another sweep and another revision with exit 2"

# The charts are written with the same care (app/checked_write.py): one that cannot be written (here a link
# to /dev/full, written in place) stops bench_charts.py non-zero, naming it.
if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  chart="$dir/whole/coherence_cornell-front.png"
  ln -s /dev/full "$chart"
  set +e
  /usr/bin/python3 "$source_dir/app/bench/bench_charts.py" "$dir/whole" >"$dir/charts.log" 2>&1
  rc=$?
  set -e
  [ $rc -ne 0 ] && grep -q "cannot write $chart: No space left on device" "$dir/charts.log" ||
    { echo "FAIL: bench_charts.py exited $rc on a chart it could not write"; cat "$dir/charts.log"; exit 1; }
  [ -c /dev/full ] || { echo "FAIL: /dev/full was replaced"; exit 1; }
  [ -s "$dir/whole/stages_cornell-front.png" ] || { echo "FAIL: the charts before it were not written"; exit 1; }
  echo "ok: bench_charts.py exits $rc naming the chart it could not write"
else
  echo "matplotlib missing: the charts' write failure is not checked"
fi
