#!/usr/bin/env bash
# `raylab study` end to end on the default device, kept tiny with --sizes/--bounces/--strategies: one bench
# folder per size, a progress line per size with the time left once one size is done, and report.html from
# them with both path counts and a verdict. Without matplotlib the results stay and the study says so.
set -u
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
timeout 600 "$raylab" study temple@hall --sizes 32x16,64x32 --bounces 2 --strategies two-point --rounds 1 --out-dir "$dir/s" \
  >"$dir/log" 2>&1
rc=$?
fail=0
[ $rc -eq 0 ] || { echo "FAIL: study exited $rc"; tail -20 "$dir/log"; exit 1; }
for size in 32x16 64x32; do
  [ -s "$dir/s/size-$size/results.csv" ] && [ -s "$dir/s/size-$size/results.jsonl" ] ||
    { echo "FAIL: no results for $size"; fail=1; }
done
grep -q "size 32x16 (1 of 2, 0 done)" "$dir/log" || { echo "FAIL: no progress line for the first size"; fail=1; }
grep -Eq "size 64x32 \(2 of 2, 1 done\), [0-9]+ s so far, about [0-9]+ s left" "$dir/log" ||
  { echo "FAIL: no time left after the first size"; grep "raylab study" "$dir/log"; fail=1; }
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  grep -q "temple@hall, 2 bounces</b>: sorting" "$dir/s/report.html" 2>/dev/null || { echo "FAIL: no verdict in report.html"; fail=1; }
  grep -q "<td>512</td>" "$dir/s/report.html" && grep -q "<td>2k</td>" "$dir/s/report.html" ||
    { echo "FAIL: the report lacks a path count"; fail=1; }
else
  grep -q "no report: matplotlib is missing" "$dir/log" || { echo "FAIL: a missing matplotlib went unsaid"; fail=1; }
fi
[ $fail -eq 0 ] && echo "ok: study of two sizes, progress with time left, report"
exit $fail
