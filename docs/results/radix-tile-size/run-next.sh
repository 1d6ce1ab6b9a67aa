#!/usr/bin/env bash
# For the next device session (about 2 minutes, any binary of main): where does the radix sort of uniform keys
# fall off (README: 0.22 ms at 2^21 pairs, 2.82 ms at 8.4M, 13x for 4x)? sortbench over counts from 1M to 8.4M,
# 24-bit uniform and few-valued keys, at the default tile and with 128- and 512-invocation groups (8 keys each).
# A knee near 3M pairs (in and out keys and values past the H100's 50 MB L2) points at the scatter's partial
# writes leaving the L2; a knee elsewhere, or none, at something else.
source docs/results/device-unpack.sh
B=build-device/raylab
N=1048576,2097152,3145728,4194304,5242880,6291456,8388608
for dist in uniform few; do
  for group in 128 256 512; do
    timeout 60 $B sortbench --n $N --bits 24 --dist $dist --sort radix --radix-group $group --radix-kpt 8 \
      --repeat 10 --csv /tmp/sb.csv > /dev/null 2>&1 || echo "sortbench $dist $group exit $?" >> $OUT/errors.txt
    appendRows /tmp/sb.csv $OUT/knee.csv dist,group $dist,$group
  done
done
echo done
