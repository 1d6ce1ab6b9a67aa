#!/usr/bin/env bash
# For the next device session (about 2 minutes; pack with bash .ci/device-build; bash .ci/device-pack): does the
# radix scatter's ranking by subgroupPartitionNV (sortbench --radix-rank partition: one match instruction a key
# where the ballots take eight) make the sort faster? The scatter is 70% of a pass and moves its bytes at 0.48
# TB/s of the H100's 3.35 (README, part 1), so its ranking, not its memory traffic, is the suspect. First the GPU
# tests of it (they skip on lavapipe, which lacks the extension), then ballot against partition at the frame's
# counts, 23-bit keys, uniform and few-valued, every dispatch timed, two rounds interleaved. If it pays, the frame
# should rank that way wherever the device can (GpuSorter's default), measured with benchBinaries.
source docs/results/device-unpack.sh
RAYLAB_VALIDATE=1 timeout 120 build-device/tests/raylab_gpu_tests --gtest_filter='GpuSortTest.Partitioned*' \
  > $OUT/gpu-tests.log 2>&1; echo "exit $?" >> $OUT/gpu-tests.log
for round in 1 2; do
  for rank in ballot partition; do
    for dist in uniform few; do
      timeout 90 build-device/raylab sortbench --n 921600,2097152,4194304,8388608 --bits 23 --dist $dist --sort radix \
        --radix-rank $rank --repeat 20 --csv /tmp/sb.csv --steps /tmp/st.csv > /dev/null 2>&1 \
        || echo "sortbench $rank $dist exit $?" >> $OUT/errors.txt
      appendRows /tmp/sb.csv $OUT/rank.csv round,rank,dist $round,$rank,$dist
      appendRows /tmp/st.csv $OUT/rank-steps.csv round,rank,dist $round,$rank,$dist
    done
  done
done
echo done
