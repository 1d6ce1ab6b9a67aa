#!/usr/bin/env bash
# Issue 36: the radix sort's tile (keys per invocation, 256 invocations a group) was tuned at 2^21 uniform pairs
# (gpu_sort.cpp: 8 fastest on an H100). The frame sorts up to 8.4M clustered two-point keys, where keys + sort
# are 2.1-2.7x the bandwidth floor (../radix-rotation). Part 1: sortbench over counts and tiles (24-bit keys,
# uniform and few-valued); part 2: the frame with binaries of main built at 8, 12 and 16 keys per invocation
# (.dev/kpt12, .dev/kpt16), 720p and 4096x2048, two interleaved rounds. On an H200 (issue 35's confirmation
# comes first there) it runs ../lavapipe-presplit-rules/run-h200.sh instead.
source docs/results/device-unpack.sh
if grep -q H200 $OUT/gpu.txt; then
  bash docs/results/lavapipe-presplit-rules/run-h200.sh
  exit 0
fi
B=build-device/raylab
t0=$SECONDS
for dist in uniform few; do
  for kpt in 4 8 12 16 20; do
    timeout 40 $B sortbench --n 921600,2097152,8388608 --bits 24 --dist $dist --sort radix --radix-kpt $kpt \
      --repeat 20 --csv /tmp/sb.csv > /dev/null 2>&1 || echo "sortbench $dist $kpt exit $?" >> $OUT/errors.txt
    appendRows /tmp/sb.csv $OUT/sortbench.csv dist,kpt $dist,$kpt
  done
done
echo "sortbench: $((SECONDS - t0)) s" >> $OUT/times.txt; t0=$SECONDS
benchBinaries frame.csv "$S@CameraMain,temple@hall,clutter:1000000" 720p,4096x2048 120 \
  kpt8=$B kpt12=.dev/kpt12/raylab kpt16=.dev/kpt16/raylab
echo "frames: $((SECONDS - t0)) s" >> $OUT/times.txt
echo done
