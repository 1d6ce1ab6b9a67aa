#!/usr/bin/env bash
# Every malformed glTF fixture makes `raylab render` exit with code 3 and a message naming the file.
set -u
raylab="$1"; root="$2"
fail=0; count=0
for f in "$root"/tests/data/malformed/*; do
  count=$((count + 1))
  out=$(timeout 120 "$raylab" render --scene "$f" --size 8x8 --out /tmp/raylab-malformed.png 2>&1); code=$?
  name=$(basename "$f")
  if [ "$code" -ne 3 ]; then echo "FAIL: $name exited $code, expected 3"; echo "$out" | tail -3; fail=1
  elif ! grep -q "$name" <<<"$out"; then echo "FAIL: $name: message does not name the file: $out"; fail=1
  else echo "ok: $name: $(tail -1 <<<"$out")"; fi
done
# Strips and fans render; points and lines exit 3 naming their mode.
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for shape in strip fan; do for form in none u8 u16 u32; do
  f="$root/tests/data/modes/${shape}_$form.gltf"
  out=$(timeout 120 "$raylab" render --scene "$f" --size 8x8 --out "$dir/m.png" 2>&1) ||
    { echo "FAIL: $(basename "$f") did not render: $(tail -1 <<<"$out")"; fail=1; }
done; done
for mode in points:POINTS lines:LINES line_loop:LINE_LOOP line_strip:LINE_STRIP; do
  out=$(timeout 120 "$raylab" render --scene "$root/tests/data/modes/${mode%%:*}.gltf" --size 8x8 --out "$dir/m.png" 2>&1); code=$?
  if [ "$code" -ne 3 ] || ! grep -q "${mode#*:} (" <<<"$out"; then echo "FAIL: ${mode%%:*}.gltf exited $code: $out"; fail=1; fi
done
[ "$count" -ge 8 ] || { echo "FAIL: only $count malformed fixtures"; fail=1; }
exit $fail
