#!/usr/bin/env bash
# The path count per frame as a bench axis (issue 21): `--sizes A,B --spps 1,2` measures every cell per size
# and spp, with a reference and baselines of its own (the CSV's paths_per_frame is width x height x spp;
# within a group every wavefront cell renders the same image, and groups of another size another one), a
# resume that keeps the cells it has (cells are told apart by size and spp too), and the charts drawn by the
# bench itself: paths_per_frame.png is a PNG. Without matplotlib (RAYLAB_PYTHON pointing at an interpreter
# that lacks it, or at none) the sweep says so once and keeps its CSV, exit 0; a chart that cannot be written
# fails the sweep with exit 1 and keeps the CSV. A size no device runs is refused with exit 2 before
# anything renders.
set -eu
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
have_matplotlib=0
/usr/bin/python3 -c 'import matplotlib' 2>/dev/null && have_matplotlib=1
sweep=(--cases cornell@front --strategies fixed --compaction none --sizes 24x16,48x32 --spps 1,2 --bounces 2
       --timed-frames 1 --warmup 0 --reference-spp 2 --rounds 1)

RAYLAB_VALIDATE=1 "$raylab" bench "${sweep[@]}" --out-dir "$dir/whole" >"$dir/whole.log" 2>&1 ||
  { cat "$dir/whole.log"; exit 1; }
python3 - "$dir/whole" <<'PY'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1] + '/results.csv')))
groups = [(r['width'], r['height'], r['spp_per_frame']) for r in rows]
# size-major, then spp; megakernel, none, fixed in each group
assert groups == [g for g in (('24', '16', '1'), ('24', '16', '2'), ('48', '32', '1'), ('48', '32', '2')) for _ in range(3)], groups
assert [r['label'] for r in rows] == ['megakernel', 'none', 'fixed/radix grid=auto clamp=off compaction=none'] * 4, [r['label'] for r in rows]
for r in rows:
    assert int(r['paths_per_frame']) == int(r['width']) * int(r['height']) * int(r['spp_per_frame']), r
records = [json.loads(l) for l in open(sys.argv[1] + '/results.jsonl')]
assert sorted(j['paths_per_frame'] for j in records) == sorted(int(r['paths_per_frame']) for r in rows)
# Sorting never changes the image: one error per group. Each size has its own reference and error.
errors = {}
for r in rows:
    if r['kernel'] == 'wavefront':
        errors.setdefault((r['width'], r['spp_per_frame']), set()).add(r['final_rel_mse'])
assert all(len(e) == 1 for e in errors.values()), errors
assert errors[('24', '1')] != errors[('48', '1')], errors
print('ok: %d cells over %d path counts' % (len(rows), len({r['paths_per_frame'] for r in rows})))
PY
grep -q '^\[1/12 .*\] round 1/1 cornell@front 24x16 spp=1 b=2 megakernel' "$dir/whole.log" ||
  { echo "FAIL: the progress line does not name the size and spp"; cat "$dir/whole.log"; exit 1; }

if [ $have_matplotlib -eq 1 ]; then
  chart="$dir/whole/paths_per_frame.png"
  [ -s "$chart" ] || { echo "FAIL: the bench drew no paths_per_frame.png"; ls "$dir/whole"; cat "$dir/whole.log"; exit 1; }
  [ "$(head -c 8 "$chart" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || { echo "FAIL: $chart is no PNG"; exit 1; }
  grep -q "bench: charts in $dir/whole" "$dir/whole.log" || { echo "FAIL: the charts were not reported"; exit 1; }
  echo "ok: the bench drew paths_per_frame.png"
else
  echo "SKIP: /usr/bin/python3 has no matplotlib: the bench's charts are not checked"
  grep -q "no charts: matplotlib is missing" "$dir/whole.log" || { echo "FAIL: not said"; cat "$dir/whole.log"; exit 1; }
fi

# A resume keeps the cells it has: the first 5 of 12 (into the second group), then the other 7 are measured
# and the folder ends with the uninterrupted sweep's cells and non-timing columns.
mkdir "$dir/part"
cp "$dir/whole/sweep.json" "$dir/part/"
head -n 5 "$dir/whole/results.jsonl" >"$dir/part/results.jsonl"
"$raylab" bench "${sweep[@]}" --no-charts --resume "$dir/part" >"$dir/resume.log" 2>&1 || { cat "$dir/resume.log"; exit 1; }
grep -q "resuming $dir/part: 5 of 12 cell rounds done" "$dir/resume.log" || { echo "FAIL: resume"; cat "$dir/resume.log"; exit 1; }
[ "$(grep -c '^\[' "$dir/resume.log")" -eq 7 ] || { echo "FAIL: the resume did not measure 7 cells"; cat "$dir/resume.log"; exit 1; }
python3 - "$dir/whole" "$dir/part" <<'PY'
import csv, sys
def timing(c):
    return (c.endswith('_ms') or c.startswith('frame_ms') or c.startswith('trace_after_first_ms')
            or c.endswith('rays_per_second') or c.endswith('_us'))
a = list(csv.DictReader(open(sys.argv[1] + '/results.csv')))
b = list(csv.DictReader(open(sys.argv[2] + '/results.csv')))
assert len(a) == len(b) == 12
for x, y in zip(a, b):
    diff = {c: (x[c], y[c]) for c in x if not timing(c) and x[c] != y[c]}
    assert not diff, (x['label'], x['width'], x['spp_per_frame'], diff)
print('ok: resumed a size sweep, 12 cells equal')
PY
# Another size list is another sweep: refused.
set +e
"$raylab" bench "${sweep[@]}" --sizes 24x16,40x32 --resume "$dir/part" >"$dir/other.log" 2>&1
rc=$?
set -e
[ $rc -eq 2 ] && grep -q "a different sweep" "$dir/other.log" || { echo "FAIL: other sizes resumed (exit $rc)"; cat "$dir/other.log"; exit 1; }

small=(--cases cornell@front --strategies fixed --sizes 16x8,24x16 --bounces 1 --timed-frames 1 --warmup 0
       --reference-spp 1 --no-detail)
# No interpreter, or one without matplotlib (Debian's without its site packages): said once, the CSV kept,
# exit 0.
printf '#!/bin/sh\nexec /usr/bin/python3 -S "$@"\n' >"$dir/bare-python"
chmod +x "$dir/bare-python"
for python in "$dir/no-such-python" "$dir/bare-python"; do
  set +e
  RAYLAB_PYTHON=$python "$raylab" bench "${small[@]}" --out-dir "$dir/nopy" >"$dir/nopy.log" 2>&1
  rc=$?
  set -e
  [ $rc -eq 0 ] && [ -s "$dir/nopy/results.csv" ] || { echo "FAIL: with $python: exit $rc"; cat "$dir/nopy.log"; exit 1; }
  [ "$(grep -c 'no charts' "$dir/nopy.log")" -eq 1 ] || { echo "FAIL: with $python: not said once"; cat "$dir/nopy.log"; exit 1; }
  grep -q "is not installed\|matplotlib is missing" "$dir/nopy.log" || { echo "FAIL: no reason"; cat "$dir/nopy.log"; exit 1; }
  rm -rf "$dir/nopy"
done
echo "ok: without python3 or matplotlib the sweep says so once and keeps its CSV"

# A chart that cannot be written (a link to /dev/full, written in place) fails the sweep, exit 1, naming
# it; the CSV and JSONL stay.
if [ $have_matplotlib -eq 1 ]; then
  mkdir "$dir/full"
  ln -s /dev/full "$dir/full/paths_per_frame.png"
  set +e
  "$raylab" bench "${small[@]}" --out-dir "$dir/full" >"$dir/full.log" 2>&1
  rc=$?
  set -e
  [ $rc -eq 1 ] && [ -s "$dir/full/results.csv" ] && [ -s "$dir/full/results.jsonl" ] ||
    { echo "FAIL: a chart write failure: exit $rc"; cat "$dir/full.log"; exit 1; }
  grep -q "cannot write $dir/full/paths_per_frame.png: No space left on device" "$dir/full.log" &&
    grep -q "the charts failed: the script bench_charts.py exited 1; the results are kept in $dir/full/results.csv" "$dir/full.log" ||
    { echo "FAIL: the chart failure was not reported"; cat "$dir/full.log"; exit 1; }
  echo "ok: a chart that cannot be written fails the sweep (exit 1) and keeps the CSV"
fi

# Sizes past the limits: exit 2, before any rendering (no output folder is made).
for bad in "--sizes 0x0" "--sizes 512x256,100000x100000" "--sizes 8192x8192 --spps 2"; do
  set +e
  # shellcheck disable=SC2086
  "$raylab" bench --cases cornell@front $bad --out-dir "$dir/bad" >"$dir/bad.log" 2>&1
  rc=$?
  set -e
  [ $rc -eq 2 ] && [ ! -e "$dir/bad" ] && grep -q "^raylab bench: --sizes" "$dir/bad.log" ||
    { echo "FAIL: $bad: exit $rc"; cat "$dir/bad.log"; exit 1; }
done
echo "ok: absurd sizes refused with exit 2 before rendering"
