#!/usr/bin/env bash
# Call 3 (about 1 minute): speed-of-light diagnostics of the scatter (not sorts: their output is wrong on purpose,
# sortbench's check switched off in those builds by RAYLAB_DIAG_NOCHECK). `coalesced` (RL_DIAG_COALESCED_WRITES):
# every tile writes its reordered keys and values to its own place, contiguous, instead of to 256 digit runs.
# `norank` (RL_DIAG_NO_RANK): no ranking; the tile goes through shared memory in its own order. `neither`: both.
# sortbench, uniform 23-bit keys, every dispatch timed, two rounds interleaved.
# Pack: bash .ci/device-build; NO_TESTS=1 bash .ci/device-pack coalesced=... norank=... neither=...
source docs/results/device-unpack.sh
for round in 1 2; do
  for v in base coalesced norank neither; do
    RAYLAB_DIAG_NOCHECK=1 sortbenchRows diag round,variant $round,$v $(packedRaylab $v) --n 2097152,8388608 --bits 23 --sort radix \
      --repeat 20
  done
done
