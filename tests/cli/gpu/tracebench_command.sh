#!/usr/bin/env bash
# raylab tracebench (issue 35): each kind of ray timed alone, with the validation layer on; its table and CSV
# say how many rays of each kind were traced (camera: one a pixel; bounce: one a camera hit; shadow: at most
# one a camera hit), and the GPU's answers agree with Embree's on the sample it checks. --kinds picks kinds.
set -eu
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
RAYLAB_VALIDATE=1 "$raylab" tracebench --scene temple --view hall --size 96x64 --repeat 2 --warmup 1 \
  --csv "$dir/t.csv" >"$dir/out.txt" 2>&1 || { echo "FAIL: tracebench exited $?"; cat "$dir/out.txt"; exit 1; }
python3 - "$dir/t.csv" <<'PY'
import csv, sys
rows = {r["kind"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert list(rows) == ["camera", "bounce", "shadow"], list(rows)
cam, bounce, shadow = (int(rows[k]["rays"]) for k in ("camera", "bounce", "shadow"))
hits = round(float(rows["camera"]["hit_fraction"]) * cam)
assert cam == 96 * 64, cam
assert bounce == hits, (bounce, hits)
assert 0 < shadow <= hits, (shadow, hits)
for k, r in rows.items():
    assert float(r["median_ms"]) > 0 and float(r["rays_per_second"]) > 0, r
    assert int(r["checked"]) == min(4096, int(r["rays"])), r
    assert int(r["disagreements"]) * 1000 <= int(r["checked"]), r
    assert r["width"] == "96" and r["height"] == "64" and r["view"] == "hall", r
print("ok: rays", cam, bounce, shadow)
PY
grep -q "^shadow .* ok (" "$dir/out.txt" || { echo "FAIL: no checked shadow row"; cat "$dir/out.txt"; exit 1; }
"$raylab" tracebench --scene cornell --size 32x16 --kinds shadow,camera --repeat 1 --warmup 0 --csv "$dir/k.csv" >/dev/null
[ "$(cut -d, -f1 "$dir/k.csv" | tail -n +2 | tr '\n' ' ')" = "shadow camera " ] ||
  { echo "FAIL: --kinds shadow,camera gave"; cat "$dir/k.csv"; exit 1; }
# A CSV that cannot be written: exit 1, naming it.
set +e
"$raylab" tracebench --scene cornell --size 32x16 --repeat 1 --csv /dev/full >"$dir/full.log" 2>&1; rc=$?
set -e
[ $rc -eq 1 ] && grep -q "cannot write /dev/full" "$dir/full.log" || { echo "FAIL: /dev/full: exit $rc"; cat "$dir/full.log"; exit 1; }
echo "ok: tracebench"
