#!/usr/bin/env bash
# A recorded camera path that cannot be saved (its folder is a file here): the window says so, naming the
# folder and the reason, keeps running, and exits 1 at the end instead of 0; nothing is written.
set -eu
raylab="$1"
source "$(dirname "$0")/../window_test_setup.sh"  # skips without a window; temporary folder; validation on
echo "not a folder" >shots
printf 'press K\nwait 1\ncamera 0 4 -31 0 6 -66\nwait 1\npress K\nwait 1\nquit\n' >script.txt
set +e
timeout 600 bash "$on_xvfb" 640x480x24 "$raylab" --window-size 160x90 --scale 0.5 --screenshot-dir shots \
  --script script.txt >run.log 2>&1
rc=$?
set -e
[ $rc -eq 1 ] || { echo "FAIL: the window exited $rc, not 1, after the path was not saved"; tail -20 run.log; exit 1; }
grep -q "camera path not saved: cannot create the folder 'shots' for the camera path" run.log ||
  { echo "FAIL: the failed save was not reported"; cat run.log; exit 1; }
grep -q "raylab: 1 writes failed" run.log || { echo "FAIL: no summary of the failed write"; cat run.log; exit 1; }
[ "$(cat shots)" = "not a folder" ] || { echo "FAIL: the file in the folder's place was changed"; exit 1; }
echo "ok: a camera path that cannot be saved is reported, exit 1"
