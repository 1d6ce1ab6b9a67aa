#!/usr/bin/env bash
# For a session with the device (about 4 minutes): the sort making its own values (SortValues::Indices: the keys
# stage writes no payload, the first radix pass reads none; .dev/indices/raylab) against the build before it
# (build-device/raylab, 7e508fc: the keys stage writes slot i, every pass reads it), in the frame at real-time and
# study sizes, 4 bounces, two-point keys, radix; binaries interleaved, two rounds each. What to read: the `keys`
# and `sort` stage columns (8 bytes a live path less per sorted bounce between them) and the frame.
source docs/results/device-unpack.sh
CASES="$S@CameraMain,temple@hall,clutter:1000000"
t0=$SECONDS
benchBinaries values.csv "$CASES" 720p,1080p,4096x2048 140 given=build-device/raylab indices=.dev/indices/raylab
echo "benches: $((SECONDS - t0)) s" >> $OUT/times.txt
echo done
