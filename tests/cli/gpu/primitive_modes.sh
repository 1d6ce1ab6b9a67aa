#!/usr/bin/env bash
# glTF primitive modes through `raylab render`: triangle strips and fans (unindexed, u8, u16, u32 indices)
# render; points and lines exit 3 naming their mode. A gpu test because the strips and fans render.
set -u
raylab="$1"; root="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
for shape in strip fan; do for form in none u8 u16 u32; do
  f="$root/tests/data/modes/${shape}_$form.gltf"
  out=$(timeout 120 "$raylab" render --scene "$f" --size 8x8 --out "$dir/m.png" 2>&1) ||
    { echo "FAIL: $(basename "$f") did not render: $(tail -1 <<<"$out")"; fail=1; }
done; done
for mode in points:POINTS lines:LINES line_loop:LINE_LOOP line_strip:LINE_STRIP; do
  out=$(timeout 120 "$raylab" render --scene "$root/tests/data/modes/${mode%%:*}.gltf" --size 8x8 --out "$dir/m.png" 2>&1); code=$?
  if [ "$code" -ne 3 ] || ! grep -q "${mode#*:} (" <<<"$out"; then echo "FAIL: ${mode%%:*}.gltf exited $code: $out"; fail=1; fi
done
exit $fail
