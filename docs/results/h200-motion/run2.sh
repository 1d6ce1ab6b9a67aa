#!/usr/bin/env bash
# Issue 37, the clutter room's 4096x2048 cells that run.sh's time limits cut off: the same bench (4 bounces, one
# round, 4 warm-up frames, two-point, average and gaussian under always and auto, the megakernel and the
# unsorted wavefront) at 4096x2048 only, over the built-in cut (`bash run2.sh cut`) or pan (`bash run2.sh pan`),
# one device call each; gaussian at the study's reset threshold 20 only. Packing as run.sh.
source docs/results/device-unpack.sh  # also sets S (Sponza), makes /tmp/out, writes $OUT/gpu.txt
name=clutter-$1-4096
nvidia-smi --query-gpu=timestamp,clocks.sm,clocks_throttle_reasons.active --format=csv -lms 250 > $OUT/clocks.csv 2>&1 &
clock=$!
start=$(date +%s)
timeout 540 build-device/raylab bench --cases clutter --camera-path builtin:$1 --sizes 4096x2048 --bounces 4 \
  --rounds 1 --warmup 4 --strategies two-point,average,gaussian --sort-policies always,auto --no-charts \
  --out-dir /tmp/$name > $OUT/log.txt 2>&1
echo "$name: exit $? after $(( $(date +%s) - start )) s" >> $OUT/log.txt
kill $clock
tar -cJf $OUT/$name.tar.xz -C /tmp $name
echo done
