#!/usr/bin/env bash
# The heatmap readout follows the real pointer (issue 18): xdotool moves the X pointer over the window and
# the frame log's `hover` (the pixel the readout shows) must follow it, scaled from window to render pixels.
# A 1280x720 window renders 320x180 (--scale 0.25); Xvfb starts the pointer at the screen's centre, so the
# readout shows the image centre (160, 90) until the pointer moves. That is where the pointer is, not a
# stale value: moved to (600, 300) and (840, 300) of the window, both over the image and clear of the
# panels (wider since issue 38), it must read (150, 75) and (210, 75). Over the heatmap legend (600, 650) the readout has no pixel (null).
set -eu
raylab="$1"
source "$(dirname "$0")/../window_test_setup.sh"  # skips without a window; temporary folder; validation on
command -v xdotool >/dev/null || { echo "skip: xdotool is not installed (apt-get install xdotool)"; exit 0; }
printf 'set heatmap traversal-steps\nwait 100000\n' >script.txt
cat >drive.sh <<'DRIVE'
set -u
raylab=$1
"$raylab" --reset --window-size 1280x720 --scale 0.25 --frame-log log.jsonl --script script.txt >window.log 2>&1 &
lab=$!
trap 'kill $lab 2>/dev/null; wait $lab 2>/dev/null' EXIT
# wait_for X Y: until a completed frame's readout shows pixel (X, Y), or "null" for none; 120 s at most.
wait_for() {
  for _ in $(seq 1200); do
    kill -0 $lab 2>/dev/null || { echo "the window exited early:"; tail window.log; return 1; }
    if python3 - "$@" <<'PY'
import json, sys
want = None if sys.argv[1] == "null" else [int(sys.argv[1]), int(sys.argv[2])]
frames = [json.loads(l)["frame"] for l in open("log.jsonl") if '"frame_done":true' in l]
last = frames[-1]["hover"] if frames else "none yet"
sys.exit(0 if last != "none yet" and (last is None if want is None else last and [last["x"], last["y"]] == want) else 1)
PY
    then echo "readout at $*"; return 0; fi
    sleep 0.1
  done
  echo "the readout never showed $*; last frames:"; grep '"frame_done":true' log.jsonl | tail -3 | grep -o '"hover":[^}]*}*'
  return 1
}
touch log.jsonl
wait_for 160 90 || exit 1  # the pointer where Xvfb put it: the screen's centre, the window's
window=$(xdotool search --sync --name raylab | head -1)
for point in "600 300 150 75" "840 300 210 75" "600 650 null"; do
  set -- $point
  xdotool mousemove --sync --window "$window" "$1" "$2"
  shift 2
  wait_for "$@" || exit 1
done
DRIVE
timeout 600 bash "$on_xvfb" 1280x720x24 bash drive.sh "$raylab" || { echo "FAIL: the readout did not follow the pointer"; exit 1; }
if grep -q "validation error" window.log; then echo "FAIL: validation errors"; grep "validation error" window.log | head; exit 1; fi
echo "the heatmap readout follows the pointer"
