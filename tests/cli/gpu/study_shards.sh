#!/usr/bin/env bash
# A study spread over shards (issue 22): `raylab study ... --shard i/K` runs the study cells g with
# g mod K = i (each size's bench told its part) and writes no report; `raylab study --merge DIR...` merges
# each size with bench's merge and makes the report. With K = 2 and K = 3 the merged cell set and every non-timing
# column (but those that differ between two unsharded runs too) equal the unsharded study's. Refused with
# exit 2: a shard missing, one given twice, shards of two splits, a folder that is no study. Kept tiny as study_command.sh is.
set -eu
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
study=(temple@hall --sizes 32x16,64x32 --bounces 2 --strategies two-point --rounds 1 --no-motion)  # study_command.sh has the motion sweeps

"$raylab" study "${study[@]}" --out-dir "$dir/whole" >"$dir/whole.log" 2>&1 || { cat "$dir/whole.log"; exit 1; }
# Shard 1 picks its device by number, as the README's GNU parallel line does (where this machine has one
# device: elsewhere device 0 need not be the default the other runs use).
ndevices=$("$raylab" devices | grep -c '^[0-9]*: ' || true)
for k in 2 3; do
  shards=()
  for i in $(seq 0 $((k - 1))); do
    device=""
    [ $i -eq 1 ] && [ "$ndevices" -eq 1 ] && device="--device 0"
    out="$dir/k$k-$i"
    "$raylab" study "${study[@]}" --shard $i/$k $device --out-dir "$out" >"$out.log" 2>&1 || { cat "$out.log"; exit 1; }
    grep -q "no report from one shard" "$out.log" && grep -q "raylab study --merge DIR... --out-dir OUT" "$out.log" ||
      { echo "FAIL: shard $i/$k did not say how to merge"; cat "$out.log"; exit 1; }
    [ ! -e "$out/report.html" ] || { echo "FAIL: shard $i/$k wrote a report"; exit 1; }
    shards=("$out" "${shards[@]}")  # merged in reverse: the order of the folders must not matter
  done
  "$raylab" study --merge "${shards[@]}" --out-dir "$dir/merged$k" >"$dir/merge$k.log" 2>&1 || { cat "$dir/merge$k.log"; exit 1; }
  grep -q "study: merged $k shards of 2 sizes" "$dir/merge$k.log" || { cat "$dir/merge$k.log"; exit 1; }
  python3 - "$dir" $k <<'PY'
import csv, json, sys
top, k = sys.argv[1], int(sys.argv[2])
# Timing columns, and the ones that differ between two unsharded runs of this study too (checked on
# lavapipe): the coherence figures (the study compacts paths, and the order compaction's atomics leave
# differs run to run on a multi-threaded device) and the auto policy's decisions and what follows from them
# (it decides from measured stage times). bench_shards.sh checks those equal too, with --compaction none
# and no auto policy.
# The commands a frame issues follow the auto policy's plan (a sorted bounce adds keys, sort, reorder).
RUN_DEPENDENT = {'simt_efficiency', 'virtual_warp_efficiency', 'virtual_warp_efficiency_after_first', 'sorted_after',
                 'prediction_error_mean', 'prediction_error_median', 'cell_hit_rate',
                 'dispatches', 'indirect_dispatches', 'barriers', 'size_writes'}
def timing(c):
    return (c.endswith('_ms') or c.endswith('_us') or c.startswith('frame_ms') or c.endswith('rays_per_second')
            or c in RUN_DEPENDENT)
total = 0
for size in ('32x16', '64x32'):
    a = list(csv.DictReader(open('%s/whole/size-%s/results.csv' % (top, size))))
    b = list(csv.DictReader(open('%s/merged%d/size-%s/results.csv' % (top, k, size))))
    assert len(a) == len(b) > 0, (size, len(a), len(b))
    for x, y in zip(a, b):
        diff = {c: (x[c], y[c]) for c in x if not timing(c) and x[c] != y[c]}
        assert not diff, (size, x['label'], diff)
    cells = [json.loads(l)['cell'] for l in open('%s/merged%d/size-%s/results.jsonl' % (top, k, size))]
    assert cells == list(range(len(a))), cells
    own = [sorted(json.loads(l)['cell'] for l in open('%s/k%d-%d/size-%s/results.jsonl' % (top, k, i, size)))
           for i in range(k)]
    assert sorted(sum(own, [])) == cells, own
    # The study's cell g (the sizes in order) is in shard g mod K.
    for i in range(k):
        assert all((total + n) % k == i for n in own[i]), (size, i, total, own[i])
    total += len(a)
print('ok: K=%d merged, %d cells, non-timing columns equal the unsharded study' % (k, total))
PY
done
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  grep -q "temple@hall, 2 bounces</b>: sorting" "$dir/merged3/report.html" || { echo "FAIL: no verdict in the merged report"; exit 1; }
else
  grep -q "no report: matplotlib is missing" "$dir/merge3.log" || { echo "FAIL: a missing matplotlib went unsaid"; exit 1; }
fi

. "$(dirname "$0")/../refuse.sh"
refuse study "a missing shard" "shard 1/3 is missing" --merge "$dir/k3-0" "$dir/k3-2" --out-dir "$dir/m"
refuse study "a shard twice" "shard 0/2 is given twice" --merge "$dir/k2-0" "$dir/k2-0" --out-dir "$dir/m"
refuse study "shards of two splits" "shards of one split have one K" --merge "$dir/k2-0" "$dir/k3-1" --out-dir "$dir/m"
refuse study "a folder that is no study" "no study.json there" --merge "$dir/k2-0" "$dir/whole/size-32x16" --out-dir "$dir/m"
refuse study "a shard past K" "--shard expects i/K" "${study[@]}" --shard 2/2 --out-dir "$dir/m"
refuse study "a device number past the devices" "--device '$ndevices' is unknown" "${study[@]}" --device $ndevices --out-dir "$dir/m"
[ ! -e "$dir/m" ] || { echo "FAIL: a refused merge wrote $dir/m"; exit 1; }
echo "ok: study shards merged"
