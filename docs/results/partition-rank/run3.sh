#!/usr/bin/env bash
# Not run yet (no device time was left; for the next session). Call 3 (about 6 minutes): the whole GPU test
# binary at this revision (synchronization validation on), the sort pipelines' registers (at the end), and the
# reorder with fewer sorted bits: --sort-bits 16 orders the two-point key's top 16 bits (two radix passes where
# its 23 bits and the dead bit take three), against all bits, the frame bench at 720p and 4096x2048.
source docs/results/device-unpack.sh
t0=$SECONDS
RAYLAB_VALIDATE=1 timeout 240 build-device/tests/raylab_gpu_tests --gtest_brief=1 > $OUT/gpu-tests-all.log 2>&1
echo "exit $?" >> $OUT/gpu-tests-all.log
echo "tests: $((SECONDS - t0)) s"; t0=$SECONDS
timeout 300 build-device/raylab bench --cases "$S@CameraMain,temple@hall,clutter:1000000" --sizes 720p,4096x2048 \
  --bounces 4 --strategies two-point --sorts radix --trace-shades split --sort-bits-list 0,16 --rounds 2 --no-detail \
  --no-charts --out-dir /tmp/bits > $OUT/bits.log 2>&1 || echo "bench exit $?" >> $OUT/bits.log
cp /tmp/bits/results.csv $OUT/bits.csv
echo "bits: $((SECONDS - t0)) s"
# The radix sort's pipelines as the compiler built them (registers, shared memory: VK_KHR_pipeline_executable_
# properties), for the question the partition left open: is the scatter bound by occupancy?
RAYLAB_SHADER_STATS=1 timeout 60 build-device/raylab sortbench --n 8388608 --bits 23 --sort radix --repeat 20 \
  > $OUT/shader-stats.txt 2>&1 || echo "shader-stats exit $?" >> $OUT/shader-stats.txt
