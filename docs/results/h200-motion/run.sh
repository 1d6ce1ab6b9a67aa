#!/usr/bin/env bash
# Issue 37 on the H200, one device call (about 6-7 minutes of GPU time; not run yet): `raylab bench
# --camera-path` on the clutter room and Sponza at 2048x1024 and 4096x2048 (2.1M and 8.4M paths), 4
# bounces, over a 240-frame walk and a 240-frame cut path, one round (the detailed replay: its times are
# work times, the detail passes left out, app/bench/bench_path.h). Cells: the megakernel, the unsorted wavefront,
# two-point, average and gaussian under always and auto (auto against the better of always and never =
# unsorted over the whole path); on the cut paths also gaussian's reset threshold 5, 20 (the study's) and
# inf. The clutter room has no walk of its own: its built-in pan (along the shelves) is its walk. Sponza's
# walk and cut are the JSON paths beside this script (the nave from CameraMain to the far end; CameraMain and
# CameraAlcove alternating every 30 frames).
# Packing as in ../h200-true-figures/run.sh: .dev/bins.tar.xz holds build-device/raylab (built from this
# branch), its tinygltf and TBB, .dev/sponza (Sponza's glTF and bin) and the Debian packages raylab needs
# there in .dev/carry/gl; carry it and build-device/lib/libembree3.so.3.xz. Writes 7 files into $OUT:
# gpu.txt, clocks.csv, log.txt and one bench folder per scene and path, packed (results.csv, cells.jsonl,
# path_frames.jsonl, motion.json, motion.md and the charts).
tar -xJf .dev/bins.tar.xz
for f in .dev/carry/gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
B=build-device/raylab
here=docs/results/h200-motion
nvidia-smi --query-gpu=name,driver_version --format=csv > $OUT/gpu.txt 2>&1
nvidia-smi --query-gpu=timestamp,clocks.sm,clocks_throttle_reasons.active --format=csv -lms 250 > $OUT/clocks.csv 2>&1 &
clock=$!
common="--sizes 2048x1024,4096x2048 --bounces 4 --rounds 1 --warmup 4 --strategies two-point,average,gaussian
        --sort-policies always,auto"
# name  case  path  extra axes  seconds at most (each bench is cut off there, keeping what it measured)
runs=(
  "clutter-cut    clutter                 builtin:cut               --gauss-resets=5,20,inf 110"
  "sponza-cut     .dev/sponza/Sponza.gltf $here/sponza_cut.json     --gauss-resets=5,20,inf 130"
  "clutter-walk   clutter                 builtin:pan               --gauss-resets=20       80"
  "sponza-walk    .dev/sponza/Sponza.gltf $here/sponza_walk.json    --gauss-resets=20       95"
)
for run in "${runs[@]}"; do
  read -r name scene path extra limit <<<"$run"
  start=$(date +%s)
  timeout $limit $B bench --cases $scene --camera-path $path $common ${extra/=/ } --out-dir /tmp/$name \
    >> $OUT/log.txt 2>&1
  echo "$name: exit $? after $(( $(date +%s) - start )) s" >> $OUT/log.txt
  tar -cJf $OUT/$name.tar.xz -C /tmp $name
done
kill $clock
echo done
