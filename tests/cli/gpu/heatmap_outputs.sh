#!/usr/bin/env bash
# What `raylab render --heatmap` writes and says: the PNG carries its legend strip, --stats carries the
# legend's range, unit and scale (and the settings to re-render the same PNG), a view with nothing to show
# is refused with the reason, and the cache views count "no cache entry" apart from "no path".
set -u
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
export RAYLAB_VALIDATE=1
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; fi; }
height() { od -An -tu1 -j20 -N4 "$1" | awk '{print $1*16777216+$2*65536+$3*256+$4}'; }
common=(--scene temple --view alley --size 64x32 --bounces 3 --frames 1)

out=$("$raylab" render "${common[@]}" --strategy fixed --heatmap traversal-steps --heatmap-scale log \
      --heatmap-range 5:100 --out steps.png --stats steps.json 2>&1) || { echo "FAIL: steps render"; echo "$out"; exit 1; }
check "headless legend line" 'grep -q "heatmap traversal-steps bounce 1: 5 .. 100 traversal steps (log, fixed range)" <<<"$out"'
check "legend strip below the 32 rows" '[ "$(height steps.png)" -gt 32 ]'
check "--stats heatmap range, unit, scale" 'python3 -c "
import json; h = json.load(open(\"steps.json\"))[\"heatmap\"]
assert h[\"range\"] == [5, 100] and h[\"unit\"] == \"traversal steps\" and h[\"scale\"] == \"log\" and h[\"range_locked\"], h"'
# The stats file's settings re-render the same PNG, heatmap options and all.
"$raylab" render --settings steps.json --out again.png >/dev/null 2>&1
check "re-render from --stats settings" 'cmp -s steps.png again.png'
# A window sidecar's camera can have no name (the camera moved, or the default view): the description names
# where it stands, not "temple/" and "1 spp, , wavefront".
python3 -c "
import json; s = json.load(open('steps.json'))['settings']
cam = {'name': '', 'position': [0.3, 1.6, 9], 'target': [0, 1.2, 0], 'up': [0, 1, 0], 'yfov_degrees': 50}
json.dump({'settings': s, 'camera': cam}, open('unnamed.json', 'w'))"
out=$("$raylab" render --settings unnamed.json --out unnamed.png 2>&1)
check "unnamed camera described: $out" 'grep -q "^raylab: temple, camera at (0.3, 1.6, 9), " <<<"$out" &&
  grep -q " spp, camera at (0.3, 1.6, 9), wavefront, " <<<"$out" && ! grep -q "/,\|, ," <<<"$out"'

out=$("$raylab" render "${common[@]}" --strategy gaussian --heatmap cache-mean --out cache.png --stats cache.json 2>&1)
check "cache view renders" '[ -s cache.png ]'
check "no cache entry told apart from no path" 'python3 -c "
import json; h = json.load(open(\"cache.json\"))[\"heatmap\"]
assert \"no cache entry\" in h[\"no_value_means\"], h
assert h[\"pixels_with_value\"] + h[\"pixels_without_value\"] + h[\"pixels_without_path\"] == h[\"pixels\"] == 64 * 32, h
assert h[\"pixels_without_value\"] > 0 and h[\"pixels_without_path\"] < h[\"pixels\"] // 4, h"'
check "the headless line names both" 'grep -q "no path, .*no cache entry" <<<"$out"'

out=$("$raylab" render "${common[@]}" --strategy two-point --heatmap sort-key --heatmap-key-colour rank --out rank.png --stats rank.json 2>&1)
check "rank view" 'python3 -c "
import json; h = json.load(open(\"rank.json\"))[\"heatmap\"]
assert h[\"key_colour\"] == \"rank\" and h[\"unit\"] == \"rank among the sorted keys\" and h[\"range\"][0] == 0, h"'

# Views with nothing to show are refused headless with the reason (the window greys them out with it).
refused() {  # expected-words flags...
  local words="$1"; shift
  local o rc
  o=$("$raylab" render "${common[@]}" "$@" --out x.png 2>&1); rc=$?
  [ $rc -eq 2 ] && grep -q "$words" <<<"$o" || { echo "FAIL: $* exit $rc: $o"; fail=1; }
}
refused "camera rays (bounce 0) get no keys" --strategy fixed --heatmap sort-key --heatmap-bounce 0
refused "needs a key strategy" --strategy none --heatmap sort-key
refused "needs the wavefront kernel" --kernel megakernel --strategy fixed --heatmap sort-key
refused "keeps no length cache" --strategy fixed --heatmap cache-variance
refused "must be below max" --heatmap traversal-steps --heatmap-range 9:3
[ $fail -eq 0 ] && echo "ok: legend strip, --stats legend, re-render, cache counts, ranks, refusals"
exit $fail
