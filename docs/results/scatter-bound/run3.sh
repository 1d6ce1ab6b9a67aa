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
    B=.dev/$v/raylab; [ $v = base ] && B=build-device/raylab
    RAYLAB_DIAG_NOCHECK=1 timeout 30 $B sortbench --n 2097152,8388608 --bits 23 --sort radix --repeat 20 \
      --csv /tmp/sb.csv --steps /tmp/st.csv > /tmp/sb.log 2>&1 \
      || { echo "sortbench $v exit $?" >> $OUT/errors.txt; tail -3 /tmp/sb.log >> $OUT/errors.txt; }
    appendRows /tmp/sb.csv $OUT/diag.csv round,variant $round,$v
    appendRows /tmp/st.csv $OUT/diag-steps.csv round,variant $round,$v
  done
done
