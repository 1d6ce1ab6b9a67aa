#!/usr/bin/env bash
# Is the binary trace slowed by the wide traversal compiled beside it (traverseSceneBvh's uniform branch on
# GpuScene::bvhLayout keeps both loops in every tracing pipeline, and a pipeline's registers are those of its
# larger path)? One device call: the pair-node binary (.dev/new) against a throwaway build whose
# traverseSceneBvh calls the binary loop only (.dev/hack, not committed), Sponza CameraMain, the trace
# command at 2048x1024 and 4096x2048 and whole frames, three interleaved rounds.
tar -xJf .dev/bins.tar.xz
for f in .dev/carry/gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
for d in new hack; do mkdir -p .dev/$d/lib && cp build-device/lib/*.so* .dev/$d/lib/; done
S=.dev/sponza/Sponza.gltf
mkdir -p /tmp/out
for round in 1 2 3; do
  for bin in new hack; do
    for size in 2048x1024 4096x2048; do
      .dev/$bin/raylab render --scene $S --view CameraMain --size $size --bounces 2 --strategy none --compaction none \
        --trace-shade split --bvh binary --frames 12 --stats /tmp/out/trace-$bin-binary-$size-r$round.json \
        --detail-every 0 --out /tmp/x.png > /dev/null 2>&1 || echo "failed: $bin $size" >> $OUT/errors.txt
      for strategy in none two-point; do
        name=$([ $strategy = none ] && echo unsorted || echo sorted)
        .dev/$bin/raylab render --scene $S --view CameraMain --size $size --bounces 4 --strategy $strategy --bvh binary \
          --frames 12 --stats /tmp/out/$name-$bin-binary-$size-r$round.json --detail-every 0 --out /tmp/x.png \
          > /dev/null 2>&1 || echo "failed: $name $bin $size" >> $OUT/errors.txt
      done
    done
  done
done
tar -cJf $OUT/stats.tar.xz -C /tmp out
echo done
