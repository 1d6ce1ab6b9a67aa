#!/usr/bin/env bash
# The documented limits themselves are accepted (bad_arguments.sh checks the values past them are refused);
# a gpu test because it renders, and the Vulkan driver cannot be leak-checked.
set -u
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
for flags in "--ema-alpha 0.001" "--ema-alpha 1" "--bounces 32" "--spp 64" "--gauss-outlier 0.5"; do
  # shellcheck disable=SC2086
  out=$("$raylab" render $flags --size 8x4 --out "$dir/limit.png" 2>&1); code=$?
  if [ "$code" -ne 0 ]; then echo "FAIL: render $flags exited $code"; echo "$out" | tail -3; fail=1
  else echo "ok: render $flags"; fi
done
exit $fail
