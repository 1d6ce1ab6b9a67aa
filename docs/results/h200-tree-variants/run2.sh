#!/usr/bin/env bash
# Call C: issue 35's frame trace rates (render --bounces 2 split, unsorted) for the tree variants: r0 (ba3d351),
# r5 (--bvh-reinsert 5), pre (presplit.patch, area 0.001), pre5 (both); issue 36's real-time table with the
# bounce loop holding one traversal (.dev/loop/raylab); presplit builds on 16 cores.
source docs/results/device-unpack.sh
B=build-device/raylab
t0=$SECONDS
run() {  # name cfg size mk scene args...
  local name=$1 cfg=$2 size=$3 mk=$4; shift 4
  local exe=$B extra="" pre=""
  case $cfg in r5) extra="--bvh-reinsert 5";; pre) exe=.dev/presplit/raylab; pre="RL_PRESPLIT_AREA=1 RL_PRESPLIT=0.001";;
    pre5) exe=.dev/presplit/raylab; pre="RL_PRESPLIT_AREA=1 RL_PRESPLIT=0.001"; extra="--bvh-reinsert 5";; esac
  env $pre $exe render "$@" $extra --size $size --bounces 2 --strategy none --compaction none \
    --trace-shade split --frames 10 --stats /tmp/out/$name-$cfg-sbvh-$size-r$round.json --detail-every 0 \
    --out /tmp/x.png > /dev/null 2>&1 || echo "failed: $name $cfg $size" >> $OUT/errors.txt
  [ $mk = mk ] || return 0
  env $pre $exe render "$@" $extra --size $size --bounces 4 --kernel megakernel --frames 10 \
    --stats /tmp/mk/$name-$cfg-sbvh-$size-r$round.json --detail-every 0 --out /tmp/x.png \
    > /dev/null 2>&1 || echo "failed: mk $name $cfg $size" >> $OUT/errors.txt
}
mkdir -p /tmp/mk /tmp/out
for round in 1 2; do
  for cfg in r0 r5 pre pre5; do
    run sponza $cfg 2048x1024 mk --scene $S --view CameraMain
    run sponza $cfg 4096x2048 - --scene $S --view CameraMain
    run hall $cfg 2048x1024 - --scene temple --view hall
    run openings $cfg 2048x1024 - --scene temple --view openings
    run detail $cfg 2048x1024 - --scene temple-detail:1000000 --view hall
    run clutter $cfg 2048x1024 mk --scene clutter:1000000
  done
done
tar -cJf $OUT/trees.tar.xz -C /tmp out mk
echo "trees: $((SECONDS - t0)) s" >> $OUT/times.txt; t0=$SECONDS
timeout 200 .dev/loop/raylab bench --cases temple@alley,temple@hall,temple@openings,$S@CameraMain,clutter:1000000 \
  --strategies two-point --sizes 512x256,720p,1080p --bounces 4 --trace-shades split,loop \
  --rounds 2 --timed-frames 6 --warmup 2 --reference-spp 4 --no-charts --out-dir /tmp/rt > /tmp/rt.log 2>&1 \
  || echo "realtime bench exit $?" >> $OUT/errors.txt
cp /tmp/rt/results.csv $OUT/realtime.csv 2>/dev/null
tail -c 100000 /tmp/rt.log | xz > $OUT/realtime.log.xz
echo "realtime: $((SECONDS - t0)) s" >> $OUT/times.txt; t0=$SECONDS
echo "scene,cfg,sbvh_build_ms,sbvh_sah_cost,sbvh_references,wall_s" > $OUT/build.csv
for scene in "$S" temple-detail:10000000; do
  for cfg in pre pre5; do
    extra=""; [ $cfg = pre5 ] && extra="--bvh-reinsert 5"
    s0=$SECONDS
    RL_PRESPLIT_AREA=1 RL_PRESPLIT=0.001 timeout 100 .dev/presplit/raylab render --scene "$scene" --size 64x32 $extra --stats /tmp/b.json --out /tmp/b.png > /dev/null 2>&1 || echo "build $scene $cfg exit $?" >> $OUT/errors.txt
    python3 -c "import json,sys; d=json.load(open('/tmp/b.json')); print(','.join([sys.argv[1].split('/')[-1], sys.argv[2]] + [str(d.get(k)) for k in ('sbvh_build_ms','sbvh_sah_cost','sbvh_references')] + [sys.argv[3]]))" "$scene" $cfg $((SECONDS - s0)) >> $OUT/build.csv || true
  done
done
echo "builds: $((SECONDS - t0)) s" >> $OUT/times.txt
echo done
