#!/usr/bin/env bash
# `raylab study` end to end on the default device, kept tiny with --sizes/--bounces/--strategies: one bench
# folder per size, a progress line per size with the time left once one size is done, and report.html from
# them with both path counts and a verdict. --quick cuts the motion sweep to the built-in cut path's first
# frames (its cut at frame 30 and the frames after it): the report's "Under a moving camera" table has the
# auto row with numbers (path time, prediction error, auto against the better of always and never, the
# recovery after the cut). Without matplotlib the results stay and the study says so. A camera path file that
# is not there is refused (exit 2) before anything is made.
set -u
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
timeout 600 "$raylab" study temple@hall --quick --sizes 32x16,64x32 --bounces 3 --strategies two-point --rounds 1 \
  --camera-path builtin:cut --out-dir "$dir/s" >"$dir/log" 2>&1
rc=$?
fail=0
[ $rc -eq 0 ] || { echo "FAIL: study exited $rc"; tail -20 "$dir/log"; exit 1; }
for size in 32x16 64x32; do
  [ -s "$dir/s/size-$size/results.csv" ] && [ -s "$dir/s/size-$size/results.jsonl" ] ||
    { echo "FAIL: no results for $size"; fail=1; }
done
[ -s "$dir/s/motion-cut/motion.json" ] || { echo "FAIL: no motion.json of the cut path"; fail=1; }
grep -q "size 32x16 (1 of 2, 0 done)" "$dir/log" || { echo "FAIL: no progress line for the first size"; fail=1; }
grep -Eq "size 64x32 \(2 of 2, 1 done\), [0-9]+ s so far, about [0-9]+ s left" "$dir/log" ||
  { echo "FAIL: no time left after the first size"; grep "raylab study" "$dir/log"; fail=1; }
grep -q "camera path builtin:cut (1 of 1)" "$dir/log" || { echo "FAIL: no progress line for the camera path"; fail=1; }
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  grep -q "temple@hall, 3 bounces</b>: sorting" "$dir/s/report.html" 2>/dev/null || { echo "FAIL: no verdict in report.html"; fail=1; }
  grep -q "<td>512</td>" "$dir/s/report.html" && grep -q "<td>2k</td>" "$dir/s/report.html" ||
    { echo "FAIL: the report lacks a path count"; fail=1; }
  /usr/bin/python3 - "$dir/s" <<'PY' || fail=1
import os, re, sys
out = sys.argv[1]
page = open(os.path.join(out, "report.html")).read()
assert "<h2>Under a moving camera</h2>" in page, "no motion section"
section = page[page.index("<h2>Under a moving camera</h2>"):page.index("<h2>Device")]
assert "temple along builtin:cut (40 frames, 64x32, 3 bounces" in section, section[:400]
rows = [re.findall(r"<td>(.*?)</td>", r) for r in re.findall(r"<tr>(.*?)</tr>", section)]
auto = [r for r in rows if len(r) == 7 and r[1] == "auto"]
assert auto, rows
label, policy, total, mean, error, against, recovery = auto[0]
for figure in (total, mean, error):
    float(figure)  # a number, not n/a
assert re.fullmatch(r"[+-]\d+\.\d% against (always|never) \((faster|within 2%|not within 2%)\)", against), against
assert re.fullmatch(r"@30: (\d+|never) \((\d+|never)\)", recovery), recovery
assert any(r[1] == "unsorted (never)" for r in rows if len(r) == 7), rows
for chart in re.findall(r'<a href="([^"]+\.png)">', section):
    assert os.path.getsize(os.path.join(out, chart)) > 0, chart
assert len(re.findall(r'<a href="([^"]+\.png)">', section)) == 2, section
print("ok: motion section,", total, "ms along the path for auto,", against)
PY
else
  grep -q "no report: matplotlib is missing" "$dir/log" || { echo "FAIL: a missing matplotlib went unsaid"; fail=1; }
fi
# A path file that is not there: exit 2 naming it, before the study makes its folder.
"$raylab" study cornell --quick --camera-path "$dir/none.json" --out-dir "$dir/bad" >"$dir/bad.log" 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q "camera-path: cannot open '$dir/none.json'" "$dir/bad.log" && [ ! -e "$dir/bad" ] ||
  { echo "FAIL: a missing path file: exit $rc"; cat "$dir/bad.log"; fail=1; }
[ $fail -eq 0 ] && echo "ok: study of two sizes and a camera path, progress with time left, report"
exit $fail
