#!/usr/bin/env bash
# Window vs headless at 320x180, 4 bounces, per strategy (issue 18's table). Validation off.
set -eu
repo=$(cd "$(dirname "$0")/../../../.." && pwd)
raylab=${RAYLAB:-$repo/build/raylab}  # run it in an empty folder: the logs, stats and PNGs go there
frames=16
strategies="none fixed average gaussian two-point"
{ echo "set bounces 4"; for s in $strategies; do printf 'set strategy %s\nwait %d\n' "$s" "$frames"; done; printf 'set sort-policy auto\nwait 10\nquit\n'; } > script.txt
export RAYLAB_VALIDATE=0
export XDG_CONFIG_HOME=$PWD/cfg
bash "$repo/tests/cli/on_xvfb.sh" 1280x720x24 $raylab --reset --window-size 320x180 --scale 1 --frame-log log.jsonl --script script.txt > window.log 2>&1
for s in $strategies; do $raylab render --size 320x180 --bounces 4 --strategy $s --frames $frames --stats $s.json --out $s.png > $s.log 2>&1; done
$raylab render --size 320x180 --bounces 4 --strategy two-point --sort-policy auto --frames 10 --stats auto.json --out auto.png > auto.log 2>&1
