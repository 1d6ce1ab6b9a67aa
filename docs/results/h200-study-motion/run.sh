#!/usr/bin/env bash
# Issue 37: the study's motion section on the H200 (it had run only on lavapipe). `raylab study clutter
# --quick` (the GPU quick preset: 512x256, 2048x1024, 4096x2048; 4 bounces; fixed and two-point; 3 rounds;
# every built-in path of the room cut to its first 60 frames), from build be1a27d. The device has no
# matplotlib: the report is made afterwards here, from the packed folder (README.md says how).
source docs/results/device-unpack.sh
start=$(date +%s)
timeout 480 build-device/raylab study clutter --quick --out-dir /tmp/study > $OUT/study.log 2>&1
echo "study: exit $?, $(( $(date +%s) - start )) s" >> $OUT/times.txt
tar -cJf $OUT/study.tar.xz -C /tmp study
echo done
