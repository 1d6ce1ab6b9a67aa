#!/usr/bin/env bash
# Call 1 (about 4 minutes): what bounds the radix scatter (issue 36).
# Part 1: the sort pipelines as the compiler built them (registers, shared memory; RAYLAB_SHADER_STATS=1), for
# this build and the variants below. Part 2: sortbench at the frame's counts, 23-bit uniform keys, every dispatch timed,
# work groups of 128 and 256 invocations by 4 and 8 keys an invocation (occupancy), this build against
# the variants, two rounds interleaved: `leader` (RL_RANK_LEADER_ATOMIC: the ballots, then only the lowest lane
# of each digit advances its running count, by a shared atomic, and a shuffle hands the count to its peers: no
# subgroup barrier a key where this build takes two), `separate` (RL_SCATTER_SEPARATE_TILE: the reordered tile
# behind the histograms instead of over them, so each key and value goes to shared memory once its place is
# known: no values held in registers, one barrier less a tile) and `both`; few-valued keys at the default shape.
# Pack: bash .ci/device-build; NO_TESTS=1 bash .ci/device-pack leader=... separate=... both=... (builds with those
# defines in shaders/sort_radix_tile.glsl).
source docs/results/device-unpack.sh
t0=$SECONDS
variants="base leader separate both"
for v in $variants; do
  B=$(packedRaylab $v)
  echo "== $B" >> $OUT/shader-stats.txt
  RAYLAB_SHADER_STATS=1 timeout 60 $B sortbench --n 8388608 --bits 23 --sort radix --repeat 20 \
    >> $OUT/shader-stats.txt 2>&1 || echo "shader-stats $B exit $?" >> $OUT/errors.txt
done
echo "stats: $((SECONDS - t0)) s"; t0=$SECONDS
for round in 1 2; do
  for v in $variants; do
    B=$(packedRaylab $v)
    for shape in 256:8 256:4 128:8 128:4 few; do
      g=${shape%%:*} k=${shape#*:} dist=uniform
      [ $shape = few ] && { g=256 k=8 dist=few; }
      sortbenchRows shape round,variant,group,kpt $round,$v,$g,$k $B --n 921600,2097152,8388608 --bits 23 \
        --dist $dist --sort radix --radix-group $g --radix-kpt $k --repeat 20
    done
  done
done
echo "sortbench: $((SECONDS - t0)) s"; t0=$SECONDS
