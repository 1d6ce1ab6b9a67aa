#!/usr/bin/env bash
# For the next device session (about 2 minutes; a binary with `sortbench --steps`, 2026-12-05 or later): where does
# the radix sort of uniform keys fall off (README: 0.22 ms at 2^21 pairs, 2.82 ms at 8.4M, 13x for 4x), and which
# dispatch takes the time? sortbench over counts from 1M to 8.4M, 23-bit keys (three passes, as the frame's
# two-point keys), uniform and few-valued, with 64-, 128- and 256-invocation groups (8 keys each: tiles of 512,
# 1024 and 2048), every dispatch timed (--steps). A knee near 3M pairs (a pass's keys and values in and out past
# the H100's 50 MB L2) in the scatter alone points at its partial writes leaving the L2, more so if smaller tiles
# (shorter runs) fall further; a knee in the histogram or the scan, or none, at something else.
source docs/results/device-unpack.sh
B=build-device/raylab
N=1048576,2097152,3145728,4194304,5242880,6291456,8388608
for dist in uniform few; do
  for group in 64 128 256; do
    timeout 60 $B sortbench --n $N --bits 23 --dist $dist --sort radix --radix-group $group --radix-kpt 8 \
      --repeat 10 --csv /tmp/sb.csv --steps /tmp/st.csv > /dev/null 2>&1 \
      || echo "sortbench $dist $group exit $?" >> $OUT/errors.txt
    appendRows /tmp/sb.csv $OUT/knee.csv dist,group $dist,$group
    appendRows /tmp/st.csv $OUT/steps.csv dist,group $dist,$group
  done
done
echo done
