#!/usr/bin/env bash
# Window against headless at 320x180, 4 bounces (issue 18's table), measured so that the machine's drift
# cancels: each method's window run and its headless run are adjacent in time (a pair), in ABBA order over
# ROUNDS rounds (window first in even rounds, headless first in odd ones), and analyse.py takes the median of
# the pairs' ratios. The first procedure (../archive/lavapipe-window-quiet/measure.sh) ran all window frames, then
# all headless ones, 1-2 minutes apart: the same headless frame moved by 12% between its runs.
# Run it in an empty folder: RAYLAB=path/to/raylab ROUNDS=5 bash measure.sh; then python3 analyse.py.
set -eu
repo=$(cd "$(dirname "$0")/../../.." && pwd)
raylab=${RAYLAB:-$repo/build/raylab}
rounds=${ROUNDS:-5}
frames=16
methods="none fixed average gaussian two-point auto"
export RAYLAB_VALIDATE=0
export XDG_CONFIG_HOME=$PWD/cfg

settings() {  # the method's render flags / script lines
  case $1 in auto) echo "--strategy two-point --sort-policy auto" ;; *) echo "--strategy $1" ;; esac
}
window() {  # method round
  local dir=r$2 script
  script=$dir/$1.script
  { echo "set bounces 4"
    [ "$1" = auto ] && printf 'set strategy two-point\nset sort-policy auto\n' || echo "set strategy $1"
    printf 'wait %d\nquit\n' "$frames"; } > "$script"
  bash "$repo/tests/cli/on_xvfb.sh" 1280x720x24 "$raylab" --reset --window-size 320x180 --scale 1 \
    --frame-log "$dir/$1.window.jsonl" --script "$script" > "$dir/$1.window.log" 2>&1
}
headless() {
  # shellcheck disable=SC2046
  "$raylab" render --size 320x180 --bounces 4 $(settings "$1") --frames $frames --stats "r$2/$1.json" \
    --out "r$2/$1.png" > "r$2/$1.log" 2>&1
}
for ((r = 0; r < rounds; ++r)); do
  mkdir -p r$r
  for m in $methods; do
    if ((r % 2 == 0)); then window $m $r; headless $m $r; else headless $m $r; window $m $r; fi
  done
  echo "round $r done"
done
