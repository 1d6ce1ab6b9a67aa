#!/usr/bin/env bash
# `raylab study temple --thesis` end to end on the default device at a tiny size (--sizes 64x32): both sweeps'
# folders, thesis.md and thesis.html with every view and method, the thesis's published ratios where the
# thesis gives them (fixed's path tracer 25.90 / 41.08 = 0.63 on average, its warp 9.1 -> 19.5 threads), our
# ratios recomputed here from the CSVs (the path tracer being trace + shade), and a finding for each claim.
# Refusals: another scene, and settings the thesis fixes.
set -u
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
"$raylab" study cornell --thesis >"$dir/refuse1" 2>&1
[ $? -eq 2 ] && grep -q "re-measures the source study's temple views" "$dir/refuse1" || { echo "FAIL: --thesis on cornell"; cat "$dir/refuse1"; fail=1; }
"$raylab" study temple --thesis --bounces 8 >"$dir/refuse2" 2>&1
[ $? -eq 2 ] && grep -q "takes the thesis's own settings" "$dir/refuse2" || { echo "FAIL: --thesis --bounces"; cat "$dir/refuse2"; fail=1; }

timeout 600 "$raylab" study temple --thesis --sizes 64x32 --rounds 1 --out-dir "$dir/t" >"$dir/log" 2>&1
rc=$?
[ $rc -eq 0 ] || { echo "FAIL: the thesis study exited $rc"; tail -20 "$dir/log"; exit 1; }
for f in thesis-keys/results.csv thesis-gaussian/results.csv thesis.md thesis.html; do
  [ -s "$dir/t/$f" ] || { echo "FAIL: no $f"; fail=1; }
done
python3 - "$dir/t" <<'PY' || fail=1
import csv, sys
out = sys.argv[1]
md = open(out + "/thesis.md").read()
rows = {}
for sweep in ("thesis-keys", "thesis-gaussian"):
    for r in csv.DictReader(open(f"{out}/{sweep}/results.csv")):
        if r["kernel"] != "wavefront":
            continue
        pt = sum(float(r[k]) for k in ("trace_ms", "shade_ms", "trace+shade_ms") if r[k])  # empty: not run
        rows[(r["view"].strip('"'), r["strategy"], "-" if r["strategy"] == "none" else r["sort"])] = pt
sections = md.split("\n## ")
ok = True
def check(cond, what):
    global ok
    if not cond:
        print("FAIL:", what)
        ok = False
for view in ("alley", "hall", "openings", "mean of the three views"):
    part = next((s for s in sections if s.startswith(view)), None)
    check(part is not None, f"no section for {view}")
    if part is None:
        continue
    table = [l.split("|")[1:-1] for l in part.splitlines() if l.startswith("| ") and "method" not in l]
    names = {(c[0].strip(), c[1].strip()) for c in table}
    want = {("none", "-")} | {(s, o) for s in ("fixed", "origin-direction", "average", "gaussian") for o in ("bitonic", "radix")}
    check(names == want, f"{view}: methods {sorted(names)}")
    if view.startswith("mean"):
        fixed = [c for c in table if c[0].strip() == "fixed"]
        check(all(c[4].strip() == "0.63" for c in fixed), "the thesis's fixed ratio 25.90/41.08 is not 0.63")
        check(all(c[6].strip() == "19.5" for c in fixed), "the thesis's fixed threads per warp (mean 19.5) missing")
        continue
    base = rows[(view, "none", "-")]
    for c in table:
        key = (view, c[0].strip(), c[1].strip())
        pt = rows[key]
        check(abs(float(c[2]) - pt) <= 0.006 + 1e-3 * pt, f"{key}: path tracer {c[2]}, CSV {pt:.3f}")
        check(abs(float(c[3]) - pt / base) <= 0.006, f"{key}: ratio {c[3]}, CSV {pt / base:.3f}")
findings = [l for l in md.split("## Findings")[1].splitlines() if l.startswith("- ")]
check(len(findings) >= 6, f"{len(findings)} findings")
check(all(("hold" in f or "here (bitonic)" in f) for f in findings), "a finding says neither that it holds nor that it does not")
html = open(out + "/thesis.html").read()
check(html.count("<table>") == 4 and "Findings" in html, "thesis.html lacks its tables or findings")
sys.exit(0 if ok else 1)
PY
[ $fail -eq 0 ] && echo "ok: the thesis's table beside ours, recomputed from the CSVs"
exit $fail
