#!/usr/bin/env bash
# Device session: the shard proofs (issue 22), shader statistics and the wide-traversal variants on Sponza (issue 20).
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
mkdir -p .dev/lib && cp build-device/lib/* .dev/lib/
S=.dev/sponza/Sponza.gltf
nvidia-smi --query-gpu=name,driver_version --format=csv > $OUT/gpu.txt 2>&1
( time timeout 70 bash tests/cli/gpu/bench_shards.sh build-device/raylab && time timeout 110 bash tests/cli/gpu/study_shards.sh build-device/raylab ) > $OUT/shards.log 2>&1
echo "shards rc=$?" >> $OUT/shards.log
{
for v in base wideonly; do for bvh in binary wide; do
  RAYLAB_SHADER_STATS=1 .dev/bin/raylab-$v render --scene $S --size 256x128 --frames 1 --bvh $bvh --strategy fixed --out /tmp/s.png 2>&1 | grep -E "shader-stats (trace|shade)" | sed "s/^/$v $bvh /"
done; done
} > $OUT/shader-stats.txt 2>&1
for v in base wideonly wideonly-ifif wideonly-ifif-rcp; do
  bvhs=wide; [ $v = base ] && bvhs=binary,wide
  ( time timeout 60 .dev/bin/raylab-$v bench --cases $S@CameraMain --strategies two-point \
    --bvhs $bvhs --trace-shades split --sizes 4096x2048 --bounces 4 --timed-frames 8 --warmup 3 --reference-spp 1 \
    --no-detail --no-charts --out-dir /tmp/v-$v ) > /tmp/v-$v.log 2>&1
  tail -3 /tmp/v-$v.log >> $OUT/variants.log
  sed "s/^/$v,/" /tmp/v-$v/results.csv >> $OUT/variants.csv
done
echo done
