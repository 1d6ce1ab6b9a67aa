#!/usr/bin/env bash
# For the next device session (about 3 minutes; a binary with `sortbench --steps` and `--radix-tiles`, 2026-12-05
# or later). Part 1: where does
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
# Part 2: several tiles a work group (--radix-tiles T: T consecutive tiles counted and scattered by one group, so
# the count table has 1/T the columns, and the histogram and the scatter read and write it 1/T as often). Does it
# take the scan and the table's scattered reads off the sort at the frame's sizes? If it pays there, it becomes
# the default (the invariant tests then render with it).
for dist in uniform few; do
  for tiles in 1 2 4 8 16; do
    timeout 60 $B sortbench --n 921600,2097152,8388608 --bits 23 --dist $dist --sort radix --radix-tiles $tiles \
      --repeat 10 --csv /tmp/sb.csv --steps /tmp/st.csv > /dev/null 2>&1 \
      || echo "sortbench tiles $dist $tiles exit $?" >> $OUT/errors.txt
    appendRows /tmp/sb.csv $OUT/tiles.csv dist,tiles $dist,$tiles
    appendRows /tmp/st.csv $OUT/tiles-steps.csv dist,tiles $dist,$tiles
  done
done
echo done
