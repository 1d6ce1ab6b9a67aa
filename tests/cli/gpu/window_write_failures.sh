#!/usr/bin/env bash
# The window under Xvfb when its files cannot be written (issue 23): a screenshot into /dev/full (a link to
# it in the screenshot folder) and an imgui.ini under /proc. Each failure is reported naming the file and
# the reason, the window keeps running (the next screenshot is taken), /dev/full stays a device, no sidecar
# is left without its PNG, and the run exits 1 at the end instead of 0.
set -eu
raylab="$1"
repo="$2"
source "$(dirname "$0")/../window_test_setup.sh"  # skips without a window; temporary folder; validation on
mkdir shots
ln -s /dev/full shots/lost.png
printf 'wait 1\nscreenshot lost\nwait 1\nscreenshot kept\nquit\n' >script.txt
set +e
timeout 600 bash "$on_xvfb" 640x480x24 "$raylab" --window-size 160x90 --scale 1 --screenshot-dir shots \
  --ini /proc/raylab-test/imgui.ini --script script.txt >run.log 2>&1
rc=$?
set -e
if grep -q "validation error" run.log; then echo "FAIL: validation errors"; grep "validation error" run.log | head; exit 1; fi
[ $rc -eq 1 ] || { echo "FAIL: the window exited $rc, not 1, after failed writes"; tail -20 run.log; exit 1; }
grep -q "screenshot failed: cannot write shots/lost.png (a link to /dev/full): No space left on device" run.log ||
  { echo "FAIL: the failed screenshot was not reported"; cat run.log; exit 1; }
grep -q "cannot write /proc/raylab-test/imgui.ini: " run.log || { echo "FAIL: the failed imgui.ini was not reported"; cat run.log; exit 1; }
# The ini is saved whenever ImGui asks (a few seconds after a change) and at the end: each attempt fails
# the same way, and is reported once. With the screenshot, two failed writes.
[ "$(grep -c "cannot write /proc/raylab-test/imgui.ini: " run.log)" -eq 1 ] ||
  { echo "FAIL: the failed imgui.ini was reported more than once"; grep "imgui.ini" run.log; exit 1; }
grep -q "raylab: 2 writes failed" run.log || { echo "FAIL: no summary of the two failed writes"; cat run.log; exit 1; }
[ -s shots/kept.png ] && [ -s shots/kept.json ] || { echo "FAIL: the window did not go on to the next screenshot"; ls shots; exit 1; }
[ ! -e shots/lost.json ] || { echo "FAIL: a sidecar without its PNG"; exit 1; }
[ -c /dev/full ] && [ -L shots/lost.png ] || { echo "FAIL: /dev/full or the link to it was replaced"; ls -la shots; exit 1; }
echo "ok: failed screenshot and imgui.ini reported, the window went on, exit 1"
