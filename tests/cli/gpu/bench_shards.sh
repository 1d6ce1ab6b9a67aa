#!/usr/bin/env bash
# A sweep spread over shards (issue 22): `--shard i/K` runs the cells n with n mod K = i, and
# `--merge DIR...` rebuilds the one sweep from the K folders: with K = 2 and K = 3 the merged cell set and
# every non-timing column equal the unsharded run's, and the merged folder is one a later --resume accepts
# as finished. Refused with exit 2: a shard missing, one given twice, shards of another sweep or of another
# revision, a shard past K. The sweep runs with --compaction none and no length-cache strategy, as
# bench_resume.sh does, so that no cell's figures depend on the cells run before it. Two rounds: a shard
# holds every round of its cells, and a merge needs them all.
set -eu
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
sweep=(--cases cornell@front --strategies dead-last,fixed,two-point --compaction none --sizes 16x8,24x16 --bounces 2
       --timed-frames 1 --warmup 0 --reference-spp 1 --no-charts --rounds 2)
cells=10  # 2 sizes x (megakernel, none, dead-last, fixed, two-point)
rounds=2

"$raylab" bench "${sweep[@]}" --out-dir "$dir/whole" >"$dir/whole.log" 2>&1 || { cat "$dir/whole.log"; exit 1; }
for k in 2 3; do
  for ((i = 0; i < k; ++i)); do
    "$raylab" bench "${sweep[@]}" --shard $i/$k --out-dir "$dir/k$k-$i" >"$dir/k$k-$i.log" 2>&1 ||
      { cat "$dir/k$k-$i.log"; exit 1; }
    want=$(( (cells - i + k - 1) / k * rounds ))
    [ "$(wc -l <"$dir/k$k-$i/results.jsonl")" -eq $want ] || { echo "FAIL: shard $i/$k has not $want cell rounds"; exit 1; }
  done
  shards=()
  for ((i = k - 1; i >= 0; --i)); do shards+=("$dir/k$k-$i"); done  # in any order
  "$raylab" bench --merge "${shards[@]}" --out-dir "$dir/merged$k" --no-charts >"$dir/merge$k.log" 2>&1 ||
    { cat "$dir/merge$k.log"; exit 1; }
  python3 - "$dir/whole" "$dir/merged$k" "$dir" $k <<'PY'
import csv, json, sys
whole, merged, top, k = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
def timing(c):
    return (c.endswith('_ms') or c.startswith('frame_ms') or c.startswith('trace_after_first_ms')
            or c.endswith('rays_per_second') or c.endswith('_us'))
a = list(csv.DictReader(open(whole + '/results.csv')))
b = list(csv.DictReader(open(merged + '/results.csv')))
assert len(a) == len(b) == 10, (len(a), len(b))
for x, y in zip(a, b):
    diff = {c: (x[c], y[c]) for c in x if not timing(c) and x[c] != y[c]}
    assert not diff, (x['label'], diff)
assert all(r['rounds'] == '2' for r in b), [r['rounds'] for r in b]
cells = [(json.loads(l)['cell'], json.loads(l)['round']) for l in open(merged + '/results.jsonl')]
assert cells == [(n, r) for n in range(10) for r in range(2)], cells
assert [json.loads(l)['cell'] for l in open(merged + '/cells.jsonl')] == list(range(10))
# Each shard ran exactly its cells, every round: n mod K = i.
for i in range(k):
    got = sorted((json.loads(l)['cell'], json.loads(l)['round']) for l in open('%s/k%d-%d/results.jsonl' % (top, k, i)))
    assert got == [(n, r) for n in range(10) if n % k == i for r in range(2)], (i, k, got)
assert json.load(open(merged + '/sweep.json'))['shard'] == '0/1'
print('ok: K=%d merged, %d cells, non-timing columns equal the unsharded run' % (k, len(b)))
PY
done
# The merged folder is the whole sweep, finished: a resume measures nothing.
"$raylab" bench --resume "$dir/merged2" >"$dir/resume.log" 2>&1 || { cat "$dir/resume.log"; exit 1; }
grep -q "resuming $dir/merged2: $((cells * rounds)) of $((cells * rounds)) cell rounds done" "$dir/resume.log" || { cat "$dir/resume.log"; exit 1; }

. "$(dirname "$0")/../refuse.sh"
refuse bench "a missing shard" "shard 1/3 is missing" --merge "$dir/k3-0" "$dir/k3-2" --out-dir "$dir/m"
refuse bench "a shard twice" "shard 0/2 is given twice" --merge "$dir/k2-0" "$dir/k2-0" --out-dir "$dir/m"
refuse bench "shards of two splits" "shards of one split have one K" --merge "$dir/k2-0" "$dir/k3-1" --out-dir "$dir/m"
"$raylab" bench "${sweep[@]}" --strategies fixed --shard 1/2 --out-dir "$dir/other" >"$dir/other.log" 2>&1 ||
  { cat "$dir/other.log"; exit 1; }
refuse bench "another sweep" "holds a different sweep" --merge "$dir/k2-0" "$dir/other" --out-dir "$dir/m"
cp -r "$dir/k2-1" "$dir/oldrev"
python3 - "$dir/oldrev/sweep.json" <<'PY'
import json, sys
record = json.load(open(sys.argv[1]))
record['git_revision'] = '0000000'
json.dump(record, open(sys.argv[1], 'w'))
PY
refuse bench "another revision" "was measured at revision 0000000" --merge "$dir/k2-0" "$dir/oldrev" --out-dir "$dir/m"
head -n 1 "$dir/k2-1/results.jsonl" >"$dir/oldrev/results.jsonl"
cp "$dir/k2-1/sweep.json" "$dir/oldrev/"
refuse bench "an unfinished shard" "has 1 of its 10 cell rounds; missing cell" --merge "$dir/k2-0" "$dir/oldrev" --out-dir "$dir/m"
[ ! -e "$dir/m" ] || { echo "FAIL: a refused merge wrote $dir/m"; exit 1; }
refuse bench "a shard past K" "--shard expects i/K" "${sweep[@]}" --shard 3/3 --out-dir "$dir/m"
refuse bench "a resume as another shard" "it holds shard 1/2 of its sweep, not 0/2" "${sweep[@]}" --shard 0/2 --resume "$dir/k2-1"
