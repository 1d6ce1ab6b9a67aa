#!/usr/bin/env bash
# Issue 34 on the H200, one device call: `render --stats` of sorted Sponza frames at 4096x2048, 4 bounces,
# 40 frames, with the detailed figures on every frame, on every second frame (the same render's frames
# without details beside them), and on none; the plain render without --stats for its wall time; the SM
# clock sampled throughout. The tracked tree is 53.5 MB of the 64 MiB a device call carries, so the rest
# travels packed: .dev/bins.tar.xz holds build-device/raylab, its tinygltf and TBB, .dev/sponza (Sponza's glTF
# and bin, no textures) and the two Debian packages raylab needs there (the Vulkan loader, stb) in
# .dev/carry/gl; carry it and build-device/lib/libembree3.so.3.xz.
tar -xJf .dev/bins.tar.xz
for f in .dev/carry/gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
B=build-device/raylab
S=.dev/sponza/Sponza.gltf
nvidia-smi --query-gpu=name,driver_version --format=csv > $OUT/gpu.txt 2>&1
nvidia-smi --query-gpu=timestamp,clocks.sm,clocks_throttle_reasons.active --format=csv -lms 250 > $OUT/clocks.csv 2>&1 &
clock=$!
common="--scene $S --view CameraMain --size 4096x2048 --bounces 4 --frames 40"
for strategy in two-point average; do
  for every in 1 2 0; do
    /usr/bin/time -f "%e s wall" $B render $common --strategy $strategy --stats /tmp/$strategy-every$every.json \
      --detail-every $every --out /tmp/x.png > /tmp/log 2>&1
    echo "$strategy --detail-every $every: $(tail -1 /tmp/log)" >> $OUT/walls.txt
  done
  /usr/bin/time -f "%e s wall" $B render $common --strategy $strategy --out /tmp/x.png > /tmp/log 2>&1
  echo "$strategy without --stats: $(tail -1 /tmp/log)" >> $OUT/walls.txt
done
kill $clock
tar -cJf $OUT/stats.tar.xz -C /tmp two-point-every1.json two-point-every2.json two-point-every0.json \
  average-every1.json average-every2.json average-every0.json
echo done
