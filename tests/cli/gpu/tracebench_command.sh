#!/usr/bin/env bash
# raylab tracebench (issue 35): each kind of ray timed alone through each tree asked, with the validation layer
# on; its table and CSV say how many rays of each kind were traced (camera: one a pixel; bounce: one a camera
# hit; shadow: at most one a camera hit; the same rays through every tree), and the GPU's answers agree with
# Embree's on the sample it checks. Each row's traversal steps and virtual warp efficiency are in range, and
# the camera rays row by row (--order scanline) take the same steps in all as in tiles, in other warps; the
# bounce rays sorted by two-point keys (--sort-rays) too, in warps that waste fewer lanes (the lab's premise), and
# in another order by their top bits alone (--sort-bits).
# --kinds picks kinds, in their order.
set -eu
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
RAYLAB_VALIDATE=1 "$raylab" tracebench --scene temple --view hall --size 96x64 --repeat 2 --warmup 1 \
  --bvhs sbvh,wide --csv "$dir/t.csv" >"$dir/out.txt" 2>&1 || { echo "FAIL: tracebench exited $?"; cat "$dir/out.txt"; exit 1; }
python3 - "$dir/t.csv" <<'PY'
import csv, sys
table = list(csv.DictReader(open(sys.argv[1])))
assert [(r["bvh"], r["kind"]) for r in table] == [(b, k) for b in ("sbvh", "wide") for k in ("camera", "bounce", "shadow")], table
for bvh in ("sbvh", "wide"):
    rows = {r["kind"]: r for r in table if r["bvh"] == bvh}
    cam, bounce, shadow = (int(rows[k]["rays"]) for k in ("camera", "bounce", "shadow"))
    hits = round(float(rows["camera"]["hit_fraction"]) * cam)
    assert cam == 96 * 64, cam
    assert bounce == hits, (bounce, hits)
    assert 0 < shadow <= hits, (shadow, hits)
    for k, r in rows.items():
        assert float(r["median_ms"]) > 0 and float(r["rays_per_second"]) > 0, r
        assert int(r["checked"]) == min(4096, int(r["rays"])), r
        assert int(r["disagreements"]) * 1000 <= int(r["checked"]), r
        assert float(r["mean_steps"]) >= 1 and 0 < float(r["warp_efficiency"]) <= 1, r
        assert r["width"] == "96" and r["height"] == "64" and r["view"] == "hall" and r["order"] == "tiles", r
    print("ok:", bvh, "rays", cam, bounce, shadow)
same = lambda k: {r["rays"] for r in table if r["kind"] == k}
assert all(len(same(k)) == 1 for k in ("camera", "bounce", "shadow")), "the trees traced different rays"
PY
"$raylab" tracebench --scene temple --view hall --size 96x64 --repeat 1 --warmup 0 --kinds camera --order scanline \
  --csv "$dir/s.csv" >/dev/null
python3 - "$dir/t.csv" "$dir/s.csv" <<'PY'
import csv, sys
tiles = next(r for r in csv.DictReader(open(sys.argv[1])) if r["bvh"] == "sbvh" and r["kind"] == "camera")
rows = next(csv.DictReader(open(sys.argv[2])))
assert rows["order"] == "scanline" and rows["rays"] == tiles["rays"], rows
assert rows["mean_steps"] == tiles["mean_steps"], (rows["mean_steps"], tiles["mean_steps"])
assert rows["warp_efficiency"] != tiles["warp_efficiency"], "the order changed no warp"
print("ok: camera steps", rows["mean_steps"], "warp efficiency tiles", tiles["warp_efficiency"], "rows", rows["warp_efficiency"])
PY
"$raylab" tracebench --scene temple --view hall --size 96x64 --repeat 1 --warmup 0 --sort-rays two-point \
  --csv "$dir/o.csv" >/dev/null
python3 - "$dir/o.csv" <<'PY'
import csv, sys
rows = {r["kind"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert list(rows) == ["camera", "bounce", "bounce-sorted", "shadow"], list(rows)
b, s = rows["bounce"], rows["bounce-sorted"]
assert s["rays"] == b["rays"] and s["mean_steps"] == b["mean_steps"] and s["hit_fraction"] == b["hit_fraction"], (b, s)
assert float(s["warp_efficiency"]) > float(b["warp_efficiency"]), (b["warp_efficiency"], s["warp_efficiency"])
assert s["sort_bits"] == "0", s
print("ok: bounce warp efficiency", b["warp_efficiency"], "sorted by two-point", s["warp_efficiency"])
PY
# --sort-bits 8: the sort compares the keys' top 8 bits, as the path sorter's would: the same rays in another
# order (two-point keys have 23 bits on the hall's grid, so ignoring 16 of them merges many).
"$raylab" tracebench --scene temple --view hall --size 96x64 --repeat 1 --warmup 0 --sort-rays two-point \
  --sort-bits 8 --kinds bounce-sorted --csv "$dir/b.csv" >/dev/null
python3 - "$dir/o.csv" "$dir/b.csv" <<'PY'
import csv, sys
full = next(r for r in csv.DictReader(open(sys.argv[1])) if r["kind"] == "bounce-sorted")
cut = next(csv.DictReader(open(sys.argv[2])))
assert cut["sort_bits"] == "8" and cut["rays"] == full["rays"] and cut["mean_steps"] == full["mean_steps"], (full, cut)
assert cut["warp_efficiency"] != full["warp_efficiency"], "ignoring 16 key bits changed no warp"
print("ok: sorted by the top 8 bits", cut["warp_efficiency"], "by all", full["warp_efficiency"])
PY
grep -q "^wide *shadow .* ok (" "$dir/out.txt" || { echo "FAIL: no checked shadow row"; cat "$dir/out.txt"; exit 1; }
"$raylab" tracebench --scene cornell --size 32x16 --kinds shadow,camera --repeat 1 --warmup 0 --csv "$dir/k.csv" >/dev/null
[ "$(cut -d, -f2 "$dir/k.csv" | tail -n +2 | tr '\n' ' ')" = "shadow camera " ] ||
  { echo "FAIL: --kinds shadow,camera gave"; cat "$dir/k.csv"; exit 1; }
# --bounce-depth 2: bounce and shadow rays from the first bounce's hits (traced in tracebench): no more rays than
# the first bounce had, other steps, and sorting them still fills warps better (the later bounces the frames sort).
"$raylab" tracebench --scene temple --view hall --size 96x64 --repeat 1 --warmup 0 --sort-rays two-point \
  --bounce-depth 2 --csv "$dir/d.csv" >/dev/null
python3 - "$dir/o.csv" "$dir/d.csv" <<'PY'
import csv, sys
one = {r["kind"]: r for r in csv.DictReader(open(sys.argv[1]))}
two = {r["kind"]: r for r in csv.DictReader(open(sys.argv[2]))}
assert one["bounce"]["bounce_depth"] == "1" and two["bounce"]["bounce_depth"] == "2", two["bounce"]
assert two["camera"]["rays"] == one["camera"]["rays"] and two["camera"]["mean_steps"] == one["camera"]["mean_steps"]
assert 0 < int(two["bounce"]["rays"]) <= int(one["bounce"]["rays"]), (one["bounce"]["rays"], two["bounce"]["rays"])
assert two["bounce"]["mean_steps"] != one["bounce"]["mean_steps"], "the same bounce at depth 2"
assert float(two["bounce-sorted"]["warp_efficiency"]) > float(two["bounce"]["warp_efficiency"]), two
print("ok: second bounce", two["bounce"]["rays"], "rays, warp efficiency", two["bounce"]["warp_efficiency"], "sorted",
      two["bounce-sorted"]["warp_efficiency"])
PY
# --sort-earlier: the first bounce traced in two-point order, so the second bounce's rays come in the order it left:
# other rays than by pixel (their directions follow the slots), the column says so, and sorting them again still pays.
"$raylab" tracebench --scene temple --view hall --size 96x64 --repeat 1 --warmup 0 --sort-rays two-point \
  --bounce-depth 2 --sort-earlier --kinds bounce,bounce-sorted --csv "$dir/e2.csv" >/dev/null
python3 - "$dir/d.csv" "$dir/e2.csv" <<'PY'
import csv, sys
pixel = {r["kind"]: r for r in csv.DictReader(open(sys.argv[1]))}
carried = {r["kind"]: r for r in csv.DictReader(open(sys.argv[2]))}
assert pixel["bounce"]["sort_earlier"] == "0" and carried["bounce"]["sort_earlier"] == "1", carried["bounce"]
assert carried["bounce"]["warp_efficiency"] != pixel["bounce"]["warp_efficiency"], "the earlier sort changed no warp"
assert float(carried["bounce-sorted"]["warp_efficiency"]) > float(carried["bounce"]["warp_efficiency"]), carried
print("ok: second bounce in the first sort's order", carried["bounce"]["warp_efficiency"], "sorted again",
      carried["bounce-sorted"]["warp_efficiency"])
PY
# --fetches: the CPU twin walks the same rays in the same steps as the shader (its mean steps are the GPU's),
# a warp reads fewer distinct things than its lanes in all, and the sorted rays' warps fewer than the unsorted
# ones' from the same reads in all; without it the columns are -1.
"$raylab" tracebench --scene temple --view hall --size 96x64 --repeat 1 --warmup 0 --sort-rays two-point \
  --bvhs sbvh,binary --kinds bounce,bounce-sorted,shadow --fetches --csv "$dir/f.csv" >"$dir/f.txt"
grep -q "^reads (CPU twin" "$dir/f.txt" || { echo "FAIL: no reads table"; cat "$dir/f.txt"; exit 1; }
python3 - "$dir/f.csv" "$dir/o.csv" <<'PY'
import csv, sys
rows = {(r["bvh"], r["kind"]): r for r in csv.DictReader(open(sys.argv[1]))}
for (bvh, kind), r in rows.items():
    f = {k: float(r[k]) for k in ("cpu_mean_steps", "mean_steps", "nodes_per_ray", "warp_nodes_per_ray",
                                  "entries_per_ray", "warp_entries_per_ray", "window_megabytes")}
    assert abs(f["cpu_mean_steps"] - f["mean_steps"]) <= 1e-3 * f["mean_steps"], (bvh, kind, f)
    assert 0 < f["warp_nodes_per_ray"] < f["nodes_per_ray"] and 0 < f["warp_entries_per_ray"] < f["entries_per_ray"], f
    assert f["window_megabytes"] > 0, f
for bvh in ("sbvh", "binary"):
    b, s = rows[(bvh, "bounce")], rows[(bvh, "bounce-sorted")]
    assert b["nodes_per_ray"] == s["nodes_per_ray"] and b["window_megabytes"] == s["window_megabytes"], (b, s)
    assert float(s["warp_nodes_per_ray"]) < float(b["warp_nodes_per_ray"]), (b["warp_nodes_per_ray"], s["warp_nodes_per_ray"])
plain = next(csv.DictReader(open(sys.argv[2])))
assert all(plain[k] == "-1.0000" for k in ("cpu_mean_steps", "warp_nodes_per_ray")), plain
print("ok: fetches", {k: rows[k]["warp_nodes_per_ray"] for k in rows})
PY
# --export: each kind's rays (32 bytes a ray, as many as the table says) and the cornell box's triangles (48
# bytes each), the camera rays unit length and unbounded; a folder that cannot be made: exit 1.
"$raylab" tracebench --scene cornell --size 32x16 --kinds camera,shadow --repeat 1 --warmup 0 --csv "$dir/e.csv" \
  --export "$dir/exp/a" >/dev/null
python3 - "$dir/e.csv" "$dir/exp/a" <<'PY'
import csv, math, os, struct, sys
rows = {r["kind"]: int(r["rays"]) for r in csv.DictReader(open(sys.argv[1]))}
d = sys.argv[2]
assert sorted(os.listdir(d)) == ["rays-camera.bin", "rays-shadow.bin", "triangles.bin"], os.listdir(d)
for kind, n in rows.items():
    assert os.path.getsize(f"{d}/rays-{kind}.bin") == 32 * n, (kind, n)
tris = os.path.getsize(f"{d}/triangles.bin")
assert tris > 0 and tris % 48 == 0, tris
ray = struct.unpack("<8f", open(f"{d}/rays-camera.bin", "rb").read(32))
assert ray[3] == 0 and abs(math.hypot(*ray[4:7]) - 1) < 1e-5 and ray[7] > 1e29, ray
print("ok: exported", rows, tris // 48, "triangles")
PY
set +e
"$raylab" tracebench --scene cornell --size 32x16 --repeat 1 --export /proc/raylab-nope >"$dir/exp.log" 2>&1; rc=$?
set -e
[ $rc -eq 1 ] && grep -q "cannot write /proc/raylab-nope" "$dir/exp.log" || { echo "FAIL: --export /proc: exit $rc"; cat "$dir/exp.log"; exit 1; }
# A CSV that cannot be written: exit 1, naming it.
set +e
"$raylab" tracebench --scene cornell --size 32x16 --repeat 1 --csv /dev/full >"$dir/full.log" 2>&1; rc=$?
set -e
[ $rc -eq 1 ] && grep -q "cannot write /dev/full" "$dir/full.log" || { echo "FAIL: /dev/full: exit $rc"; cat "$dir/full.log"; exit 1; }
echo "ok: tracebench"
