#!/usr/bin/env bash
# app/study/study_report.py over two tiny bench sweeps (two image sizes, two bounce counts): one self-contained
# HTML file (every chart a data: URL, nothing fetched), the verdict for each bounce count, the crossover
# table with both path counts, the image check passing; then the same report over a copy whose sorted cell
# claims another relative MSE must say the invariant is broken, and a folder without results exits 2.
set -u
raylab="$1"
repo="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
/usr/bin/python3 -c "import matplotlib" 2>/dev/null || { echo "skip: python3-matplotlib is not installed"; exit 0; }
report() { /usr/bin/python3 "$repo/app/study/study_report.py" "$@"; }
for size in 32x16 64x32; do
  "$raylab" bench --cases temple@hall --strategies two-point --bounces 2,3 --size "$size" --timed-frames 2 \
    --warmup 1 --reference-spp 2 --rounds 2 --out-dir "$dir/b-$size" >"$dir/b-$size.log" 2>&1 ||
    { echo "FAIL: bench $size exited $?"; tail -5 "$dir/b-$size.log"; exit 1; }
done
report "$dir/study.html" "$dir/b-32x16" "$dir/b-64x32" >"$dir/report.log" 2>&1 || { echo "FAIL: report exited $?"; cat "$dir/report.log"; exit 1; }
fail=0
check() { grep -q -- "$1" "$dir/study.html" || { echo "FAIL: the report lacks: $2"; fail=1; }; }
check "temple@hall, 2 bounces</b>: sorting " "the verdict at 2 bounces"
check "temple@hall, 3 bounces</b>: sorting " "the verdict at 3 bounces"
check "<td>512</td>" "the 512-path row" ; check "<td>2k</td>" "the 2048-path row"
check 'src="data:image/png;base64,' "an embedded chart"
check "sorted cells have their unsorted baseline's relative MSE" "a passing image check"
check "measured in 2 interleaved round" "the round count"
grep -Eq "[0-9]+\.[0-9]{2} \[[0-9]+\.[0-9]{2}-[0-9]+\.[0-9]{2}\]" "$dir/study.html" || { echo "FAIL: no spread over the rounds"; fail=1; }
grep -Eq '(src|href)="(https?:|//)' "$dir/study.html" && { echo "FAIL: the report fetches something"; fail=1; }
# Opened in headless Chromium, every chart of the report is decoded and shown (issue 22); skipped, saying so,
# where Chromium is not installed.
shown=$(/usr/bin/python3 "$repo/tests/tools/chromium_images.py" "$dir/study.html" 2>"$dir/chromium.log")
case $? in
  0) read -r images rendered <<<"$shown"
     charts=$(grep -o 'src="data:image/png;base64,' "$dir/study.html" | wc -l)
     [ "$images" -eq "$charts" ] && [ "$rendered" -eq "$charts" ] && [ "$charts" -ge 3 ] ||
       { echo "FAIL: Chromium shows $rendered of $images images, the report embeds $charts charts"; fail=1; } ;;
  2) echo "skip (Chromium check): $(cat "$dir/chromium.log")" ;;
  *) echo "FAIL: Chromium could not load the report: $(cat "$dir/chromium.log")"; fail=1 ;;
esac
# A sorted cell whose image differs from the unsorted one must be reported.
mkdir "$dir/broken"
cp "$dir/b-64x32/sweep.json" "$dir/broken/"
/usr/bin/python3 - "$dir/b-64x32/cells.jsonl" "$dir/broken/cells.jsonl" <<'PY'
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
sorted_rows = [r for r in rows if r["settings"]["strategy"] != "none" and r["settings"]["kernel"] == "wavefront"]
sorted_rows[0]["result"]["final_rel_mse"] *= 1.5
with open(sys.argv[2], "w") as f:
    f.writelines(json.dumps(r) + "\n" for r in rows)
PY
report "$dir/broken.html" "$dir/broken" >/dev/null 2>&1 || { echo "FAIL: the report over the broken copy exited $?"; fail=1; }
grep -q "the invariant is broken" "$dir/broken.html" || { echo "FAIL: a sorted cell with another image went unreported"; fail=1; }
mkdir "$dir/empty"
report "$dir/none.html" "$dir/empty" >"$dir/empty.log" 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q "no cells.jsonl or results.jsonl" "$dir/empty.log" || { echo "FAIL: an empty folder gave exit $rc: $(cat "$dir/empty.log")"; fail=1; }
[ $fail -eq 0 ] && echo "ok: one self-contained report with verdicts, both path counts, the image check; a broken invariant and an empty folder caught"
exit $fail
