#!/usr/bin/env bash
# Absurd or malformed command-line values give a usage message and exit code 2, never a crash or a hang.
set -u
raylab="$1"
fail=0
expect() {
  local want="$1"; shift
  local out
  out=$(timeout 60 "$raylab" "$@" 2>&1); local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL: raylab $* exited $got, expected $want"; echo "$out" | head -5; fail=1
  elif [ "$want" -eq 2 ] && ! grep -qi "usage\|must be\|expects\|unknown\|needs" <<<"$out"; then
    echo "FAIL: raylab $* gave no usage message"; fail=1
  fi
}
expect 2 render --size 0x100
expect 2 render --size 100
expect 2 render --size 100000x100
expect 2 render --size -5x10
expect 2 render --bounces 0
expect 2 render --bounces 1000
expect 2 render --spp abc
expect 2 render --frames 1.5
expect 2 render --seed -1
expect 2 render --kernel gpu
expect 2 render --strategy fastest
expect 2 render --sort quick
expect 2 render --grid 0
expect 2 render --grid 4x4
expect 2 render --grid 5000
expect 2 render --clamp nan
expect 2 render --clamp -1
expect 2 render --fixed-factor inf
expect 2 render --ema-alpha 0
expect 2 render --exposure
expect 2 render --no-such-flag
expect 2 render --scene nonsense
expect 2 render --view nowhere
expect 2 frobnicate
expect 3 render --scene /nonexistent/missing.gltf
exit $fail
