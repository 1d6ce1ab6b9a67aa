#!/usr/bin/env bash
# A sort-key heatmap of gaussian keys re-renders from its sidecar (issue 38: 1,396 pixels differed, the
# window's length cache having learned over another history). After a camera move the window's cache has
# learned over more frames than the image's: the sidecar says so (learned_state.reproducible false) and
# `render --settings` repeats the note. After restart-learning (the L key) cache and accumulation start
# together, as a re-render's do: the sidecar says reproducible and the re-rendered PNG is byte-identical.
set -eu
raylab="$1"
source "$(dirname "$0")/../window_test_setup.sh"  # skips without a window; temporary folder; validation on
cat >s.txt <<'S'
set strategy gaussian
set bounces 3
set heatmap sort-key
wait 3
camera -110 90 120 0 5 0
wait 3
screenshot moved
restart-learning
wait 3
screenshot learned
quit
S
timeout 600 bash "$on_xvfb" 1280x720x24 "$raylab" --window-size 640x360 --scale 0.25 --screenshot-dir shots \
  --script s.txt >run.log 2>&1 || { echo "FAIL: the window run exited $?"; tail -20 run.log; exit 1; }
reproducible() { python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['learned_state']['reproducible'])" "$1"; }
[ "$(reproducible shots/moved.json)" = False ] || { echo "FAIL: the shot after a camera move claims its cache reproduces"; exit 1; }
[ "$(reproducible shots/learned.json)" = True ] || { echo "FAIL: the shot after restart-learning is not reproducible"; exit 1; }
"$raylab" render --settings shots/moved.json --out moved.png >moved.log 2>&1
grep -q "note from the sidecar: the length cache also learned before" moved.log ||
  { echo "FAIL: render --settings does not repeat the sidecar's note"; cat moved.log; exit 1; }
"$raylab" render --settings shots/learned.json --out learned.png >learned.log 2>&1
cmp -s shots/learned.png learned.png || { echo "FAIL: the re-render of the restart-learning shot differs"; exit 1; }
echo "ok: a moved camera's shot says its cache learned more; after restart-learning the re-render is identical"
