#!/usr/bin/env bash
# Issue 40: a study spread over the GPUs of one host, one shard per GPU, side by side, then merged, against the
# same study unsharded on one GPU of that host. Checks: the merged cell set and every non-timing column equal
# the unsharded run's; each shard's rows name a different device (device_uuid); the wall times; per-cell frame
# time ratios sharded / unsharded (median and spread). Usage:
#   run.sh RAYLAB K STUDY_ARGS...      e.g. run.sh build-device/raylab 2 clutter@overview
# ALLOW_ONE_DEVICE=1 lets every shard run on device 0 (a check of the script on one GPU or lavapipe: the
# device check then only reports). Results go to ${OUT:-/tmp}/multi-gpu-K.
set -euo pipefail
raylab=$1 k=$2
shift 2
out=${OUT:-/tmp}/multi-gpu-$k
rm -rf "$out" && mkdir -p "$out"
start=$SECONDS
"$raylab" study "$@" --out-dir "$out/whole" > "$out/whole.log" 2>&1
whole=$((SECONDS - start))
start=$SECONDS
pids=()
for ((i = 0; i < k; i++)); do
  device=$([ "${ALLOW_ONE_DEVICE:-0}" = 1 ] && echo 0 || echo $i)
  "$raylab" study "$@" --shard $i/$k --device $device --out-dir "$out/s$i" > "$out/s$i.log" 2>&1 &
  pids+=($!)
done
for p in "${pids[@]}"; do wait "$p"; done
sharded=$((SECONDS - start))
"$raylab" study --merge $(for ((i = 0; i < k; i++)); do echo "$out/s$i"; done) --out-dir "$out/merged" > "$out/merge.log" 2>&1
echo "wall: unsharded ${whole} s, $k shards side by side ${sharded} s" | tee "$out/walls.txt"
python3 - "$out" "$k" "${ALLOW_ONE_DEVICE:-0}" <<'PY'
import csv, glob, os, statistics, sys
out, k, one = sys.argv[1], int(sys.argv[2]), sys.argv[3] == '1'
# Columns that follow timing, not the sweep: times, the device, and what depends on the order threads ran in:
# compaction packs the live paths in the order its atomics give (the warp figures read slots in that order),
# and auto's plan follows the costs it measured (sorted_after).
timing = lambda c: (c.endswith('_ms') or '_ms_' in c or c.startswith('frame_ms') or c.startswith('device')
                    or c in ('rays_per_second', 'final_rel_mse', 'sorted_after', 'simt_efficiency',
                             'virtual_warp_efficiency', 'virtual_warp_efficiency_after_first'))
def rows(top):
    r = {}
    for f in sorted(glob.glob(os.path.join(top, 'size-*', 'results.csv'))):
        for row in csv.DictReader(open(f)):
            r[(os.path.basename(os.path.dirname(f)), row['label'], row['bounces'])] = row
    return r
whole, merged = rows(os.path.join(out, 'whole')), rows(os.path.join(out, 'merged'))
assert set(whole) == set(merged), ('cell sets differ', set(whole) ^ set(merged))
for key, w in whole.items():
    m = merged[key]
    diff = [c for c in w if not timing(c) and w[c] != m.get(c)]
    assert not diff, (key, [(c, w[c], m.get(c)) for c in diff])
uuids = {}
for i in range(k):
    for key, row in rows(os.path.join(out, 's%d' % i)).items():
        uuids.setdefault(i, set()).add(row.get('device_uuid', ''))
per_shard = [sorted(uuids.get(i, [])) for i in range(k)]
distinct = len({u for s in per_shard for u in s}) == k and all(len(s) == 1 for s in per_shard)
print('devices per shard:', per_shard, '(each its own)' if distinct else '(NOT each its own)')
assert distinct or one, 'shards did not each run on their own device'
ratios = [float(merged[key]['frame_ms_median']) / float(w['frame_ms_median']) for key, w in whole.items()]
q = statistics.quantiles(ratios, n=4) if len(ratios) > 1 else ratios * 3
print('per-cell frame time, sharded / unsharded: median %.4f, IQR %.4f-%.4f, min %.4f, max %.4f over %d cells' % (
    statistics.median(ratios), q[0], q[2], min(ratios), max(ratios), len(ratios)))
print('ok: merged cell set and non-timing columns equal the unsharded run')
PY
