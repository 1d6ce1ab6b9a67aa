#!/usr/bin/env bash
# One device call (about 6 minutes) at the revision that makes two radix tiles a work group the default
# (kDefaultRadixTilesPerGroup). Part 1: the GPU tests of sorting and the invariant, with synchronization
# validation (the layer travels as a Debian package in .dev/carry/gl), and the two tests that failed on the H100 at
# fe2275f. Part 2: issue 36's table at this revision: the frame bench of the scenes kept for checking and the
# clutter room, 512x256 to 4096x2048, megakernel, unsorted and two-point sorted wavefronts (radix, split), two
# interleaved rounds in one bench.
source docs/results/device-unpack.sh
t0=$SECONDS
RAYLAB_VALIDATE=1 timeout 150 build-device/tests/raylab_gpu_tests \
  --gtest_filter='SortInvariant*:*GpuSort*:*Invariant*:*SortPolicy*:EmbreeHits.*:HeatmapProduct.*' --gtest_brief=1 \
  > $OUT/gpu-tests.log 2>&1; echo "exit $?" >> $OUT/gpu-tests.log
echo "tests: $((SECONDS - t0)) s"; t0=$SECONDS
timeout 330 build-device/raylab bench --cases "$S@CameraMain,temple@hall,temple-detail:1000000@hall,clutter:1000000" \
  --sizes 512x256,720p,1080p,4096x2048 --bounces 4 --strategies two-point --sorts radix --trace-shades split \
  --rounds 2 --no-detail --no-charts --out-dir /tmp/study > $OUT/study.log 2>&1 || echo "study exit $?" >> $OUT/study.log
cp /tmp/study/results.csv $OUT/study.csv
echo "study: $((SECONDS - t0)) s"
