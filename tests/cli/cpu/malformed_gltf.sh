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
# Strips and fans render (tests/cli/gpu/primitive_modes.sh): that needs the Vulkan driver.
[ "$count" -ge 8 ] || { echo "FAIL: only $count malformed fixtures"; fail=1; }
exit $fail
