#!/usr/bin/env bash
# `raylab bench` runs a tiny sweep end to end: baselines plus the asked strategies, every cell in the CSV and
# the JSONL, one identical final image error for every wavefront cell (sorting never changes the image),
# and a usage error (exit 2) for a bad sweep value.
set -eu
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
RAYLAB_VALIDATE=1 "$raylab" bench --cases cornell@front --strategies dead-last,gaussian --sorts radix,bitonic \
  --gauss-resets 20,inf --sort-bits-list 0,8 --size 24x16 --timed-frames 2 --warmup 0 --reference-spp 2 --out-dir "$dir" > "$dir/log" 2>&1
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
