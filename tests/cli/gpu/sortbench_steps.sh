#!/usr/bin/env bash
# raylab sortbench --steps (issue 36: where a sort's time goes): with the validation layer on, every dispatch of
# the radix sort is a row of the steps CSV, in the order the sort records them: the small sort alone up to its
# threshold; above it histogram, scan and scatter for each 8-bit pass (23-bit keys and the dead key's bit: three
# passes; 7 bits: one pass and the copy back). Each step's time lies inside its sort's (one run: the same
# timestamps), and its share is its time over the sort's. bitonic has no steps: asking for them with it is a
# usage error.
set -eu
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
run() {  # bits, then the file stem
  "$raylab" sortbench --validate --n 1000,20000 --bits "$1" --sort radix --repeat 1 --csv "$dir/$2.csv" \
    --steps "$dir/$2-steps.csv" >"$dir/$2.txt" 2>&1 || { echo "FAIL: sortbench --bits $1 exited $?"; cat "$dir/$2.txt"; exit 1; }
}
run 23 three
run 7 one
python3 - "$dir" <<'PY'
import csv, sys
d = sys.argv[1]
for stem, passes in (("three", 3), ("one", 1)):
    sorts = {int(r["n"]): r for r in csv.DictReader(open(f"{d}/{stem}.csv"))}
    steps = list(csv.DictReader(open(f"{d}/{stem}-steps.csv")))
    assert all(r["check"] == "ok" for r in sorts.values()), sorts
    by_n = {n: [r for r in steps if int(r["n"]) == n] for n in sorts}
    assert [r["step"] for r in by_n[1000]] == ["small"], by_n[1000]
    want = [f"{s}/{p}" for p in range(passes) for s in ("histogram", "scan", "scatter")] + (["copy"] if passes == 1 else [])
    assert [r["step"] for r in by_n[20000]] == want, [r["step"] for r in by_n[20000]]
    for n, rows in by_n.items():
        total = float(sorts[n]["median_ms"])
        spent = sum(float(r["median_ms"]) for r in rows)
        assert all(float(r["median_ms"]) >= 0 for r in rows), rows
        assert 0 < spent <= total * 1.0001 + 1e-6, (n, spent, total)
        for r in rows:
            assert abs(float(r["share"]) - float(r["median_ms"]) / total) < 1e-3, r
            assert r["bits"] == ("23" if passes == 3 else "7") and r["dist"] == "uniform", r
    print("ok:", stem, [r["step"] for r in by_n[20000]])
PY
grep -q "scatter/2" "$dir/three.txt" || { echo "FAIL: the table lists no steps"; cat "$dir/three.txt"; exit 1; }
if "$raylab" sortbench --n 1000 --sort both --steps "$dir/x.csv" >"$dir/bad.txt" 2>&1; then
  echo "FAIL: --steps with bitonic was accepted"; exit 1
fi
grep -q "not bitonic" "$dir/bad.txt" || { echo "FAIL: no reason given"; cat "$dir/bad.txt"; exit 1; }
[ ! -e "$dir/x.csv" ] || { echo "FAIL: a refused run wrote its steps"; exit 1; }
echo "ok: sortbench --steps"
