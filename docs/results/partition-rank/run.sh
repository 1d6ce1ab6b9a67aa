#!/usr/bin/env bash
# Call 1 of 2 (about 3 minutes): the radix scatter ranking by subgroupPartitionNV (RadixRank::Partition), which
# the packed build took by default wherever the device has VK_NV_shader_subgroup_partitioned (RadixRank::Auto).
# Part 1: the GPU tests of sorting and the invariant under the new default, with synchronization validation
# (GpuSortTest.OtherRankingMatchesStableSort runs the ballots there). Part 2: sortbench, ballot against
# partition at the frame's counts (0.9M-8.4M pairs), 23-bit keys, uniform and few-valued, every dispatch timed,
# two rounds interleaved. Pack: bash .ci/device-build; bash .ci/device-pack ballot=<a build of the parent commit>.
source docs/results/device-unpack.sh
t0=$SECONDS
RAYLAB_VALIDATE=1 timeout 150 build-device/tests/raylab_gpu_tests \
  --gtest_filter='SortInvariant*:*GpuSort*:*Invariant*:*SortPolicy*' --gtest_brief=1 \
  > $OUT/gpu-tests.log 2>&1; echo "exit $?" >> $OUT/gpu-tests.log
echo "tests: $((SECONDS - t0)) s"; t0=$SECONDS
# `leader` (when packed as .dev/leader/raylab): the partition ranking where only the lowest lane of each digit reads
# and advances its running count and a shuffle hands it to its peers (one subgroup barrier a key, not two).
ranks="ballot partition"; [ -x .dev/leader/raylab ] && ranks="ballot partition leader"
for round in 1 2; do
  for rank in $ranks; do
    for dist in uniform few; do
      B=build-device/raylab; r=$rank; [ $rank = leader ] && { B=.dev/leader/raylab; r=partition; }
      sortbenchRows rank round,variant $round,$rank $B --n 921600,2097152,4194304,8388608 --bits 23 --dist $dist \
        --sort radix --radix-rank $r --repeat 20
    done
  done
done
echo "sortbench: $((SECONDS - t0)) s"
