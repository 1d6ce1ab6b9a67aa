#!/usr/bin/env bash
# Call 2 of 2 (about 6 minutes): the frame with the scatter ranking by the partition (the packed build's default on
# NVIDIA: RadixRank::Auto) against the ballots (`ballot`, the parent commit's build): benchBinaries (4 bounces, two-point, radix,
# split), the binaries interleaved over two rounds.
source docs/results/device-unpack.sh
benchBinaries frame.csv "$S@CameraMain,temple@hall,clutter:1000000" 720p,4096x2048 140 \
  ballot=.dev/ballot/raylab partition=build-device/raylab
