#!/usr/bin/env bash
# Steps a ray through the spatial-split tree as Embree builds it and after reinsertion (--bvh-reinsert N), on the
# study's scenes (tracebench, 1024x512: camera, bounce and shadow rays, checked against Embree), and what the
# reinsertion costs the build (render --stats: sbvh_build_ms, sbvh_sah_cost). Steps and warp efficiency do not depend
# on the device; lavapipe's times mean nothing here. Run from the repository root after building.
set -eu
S=../shared/scenes/Sponza/Sponza.gltf
out=docs/results/lavapipe-tree-steps
rm -f $out/steps.csv $out/build.csv
for c in "temple hall" "temple openings" "$S CameraMain" "temple-detail:1000000 hall" "clutter:1000000 overview"; do
  set -- $c
  for n in 0 5 16; do
    ./build/raylab tracebench --scene "$1" --view "$2" --size 1024x512 --bvh-reinsert $n --repeat 1 --warmup 0 \
      --check 4096 --csv /tmp/ts.csv > /tmp/ts.txt 2>&1 || { echo "tracebench $c $n failed"; cat /tmp/ts.txt; exit 1; }
    [ -s $out/steps.csv ] || head -1 /tmp/ts.csv | sed 's/^/bvh_reinsert,/' > $out/steps.csv
    tail -n +2 /tmp/ts.csv | sed "s/^/$n,/" >> $out/steps.csv
  done
done
echo "scene,bvh_reinsert,sbvh_build_ms,sbvh_sah_cost,sbvh_nodes,sbvh_references" > $out/build.csv
for scene in temple "$S" temple-detail:1000000 clutter:1000000; do
  for n in 0 5 16; do
    ./build/raylab render --scene "$scene" --size 64x32 --bvh-reinsert $n --stats /tmp/tb.json --out /tmp/tb.png >/dev/null 2>&1
    python3 -c "import json,sys; d=json.load(open('/tmp/tb.json')); print(','.join([sys.argv[1].split('/')[-1], sys.argv[2]] + [str(d[k]) for k in ('sbvh_build_ms','sbvh_sah_cost','sbvh_nodes','sbvh_references')]))" "$scene" $n >> $out/build.csv
  done
done
