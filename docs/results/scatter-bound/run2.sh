#!/usr/bin/env bash
# Call 2 (about 7 minutes): call 1 found the scatter at 69 registers a thread (3 work groups of 256 an SM) and no
# faster with the ranking's barriers gone (`leader`), smaller tiles or smaller groups. So: does hiding the loads'
# latency pay? `early` (RL_SCATTER_EARLY_VALUES: a tile's values are loaded with its keys, before the ranking, not
# after it), `prefetch` (RL_SCATTER_PREFETCH_KEYS: the group's next tile's keys are loaded while this tile is
# ranked and scattered), `earlypre` (both). Part 1: registers. Part 2: sortbench, 23-bit keys, uniform and
# few-valued, two rounds interleaved. Part 3: the frame (4 bounces, two-point, radix, split), two rounds
# interleaved. Part 4 (if time is left): --sort-bits 16 (two passes) against all bits (three) at the frame.
# Pack: bash .ci/device-build; NO_TESTS=1 bash .ci/device-pack early=... prefetch=... earlypre=...
source docs/results/device-unpack.sh
t0=$SECONDS
variants="base early prefetch earlypre"
for v in $variants; do
  echo "== $v" >> $OUT/shader-stats2.txt
  RAYLAB_SHADER_STATS=1 timeout 30 $(packedRaylab $v) sortbench --n 8388608 --bits 23 --sort radix --repeat 5 2>&1 \
    | grep scatter >> $OUT/shader-stats2.txt
done
for round in 1 2; do
  for v in $variants; do
    for dist in uniform few; do
      sortbenchRows prefetch round,variant $round,$v $(packedRaylab $v) --n 921600,2097152,8388608 --bits 23 \
        --dist $dist --sort radix --repeat 20
    done
  done
done
echo "sortbench: $((SECONDS - t0)) s"; t0=$SECONDS
benchBinaries frame.csv "$S@CameraMain,temple@hall,clutter:1000000" 720p,4096x2048 100 \
  base=build-device/raylab early=.dev/early/raylab prefetch=.dev/prefetch/raylab earlypre=.dev/earlypre/raylab
echo "frame: $((SECONDS - t0)) s"; t0=$SECONDS
timeout 120 build-device/raylab bench --cases "$S@CameraMain,temple@hall,clutter:1000000" --sizes 720p,4096x2048 \
  --bounces 4 --strategies two-point --sorts radix --trace-shades split --sort-bits-list 0,16 --rounds 1 --no-detail \
  --no-charts --out-dir /tmp/bits > $OUT/bits.log 2>&1 || echo "bits exit $?" >> $OUT/errors.txt
cp /tmp/bits/results.csv $OUT/bits.csv
echo "bits: $((SECONDS - t0)) s"
