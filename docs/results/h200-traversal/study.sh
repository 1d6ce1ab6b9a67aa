#!/usr/bin/env bash
# Issue 35, the sorting answer over the new trace (sbvh, a leaf visited like a node), one device call per bounce
# count: bash study.sh 4, then bash study.sh 8. The bench over the study's scenes (Sponza, the temple's hall and
# openings, temple-detail:1000000 from the hall, the clutter room at 1e6 triangles) at 2.1M and 8.4M paths:
# the megakernel, the unsorted wavefront and two-point sorting, trace and shade split and fused, three
# interleaved rounds, no counting frame, a 4-spp reference (the figures here are times). With 4 bounces it also
# times the builds of temple-detail:10000000 (--stats of a 64x32 render: bvh_build_ms, sbvh_build_ms).
source docs/results/device-unpack.sh  # also sets S (Sponza), makes /tmp/out, writes $OUT/gpu.txt
b=$1
if [ "$b" = 4 ]; then
  build-device/raylab render --scene temple-detail:10000000 --view hall --size 64x32 --stats $OUT/detail10m.json \
    --detail-every 0 --out /tmp/x.png > $OUT/detail10m.log 2>&1 || echo "detail10m exit $?" >> $OUT/errors.txt
fi
timeout ${BENCH_LIMIT:-480} build-device/raylab bench \
  --cases "$S@CameraMain,temple@hall,temple@openings,temple-detail:1000000@hall,clutter:1000000" \
  --sizes 2048x1024,4096x2048 --bounces $b --strategies two-point --trace-shades split,fused --rounds 3 \
  --reference-spp 4 --no-detail --no-charts --out-dir /tmp/bench$b > /tmp/bench$b.log 2>&1 \
  || echo "bench exit $?" >> $OUT/errors.txt
cp /tmp/bench$b/results.csv $OUT/study-$b.csv 2>/dev/null
tail -c 200000 /tmp/bench$b.log > $OUT/study-$b.log
tar -cJf $OUT/study-$b.tar.xz -C /tmp bench$b
echo done
