#!/usr/bin/env bash
# The window soak (tests/soak/window_soak.sh) cut to 120 frames: the report is produced and well formed
# (resident memory read after the warm-up and at the end, at the frames asked for, with the device). The
# 10000-frame run that judges growth is a manual tool: it takes longer than a test may.
set -eu
raylab="$1"
repo="$2"
source "$(dirname "$0")/../window_test_setup.sh"  # skips without a window; temporary folder; validation on
timeout 800 bash "$repo/tests/soak/window_soak.sh" "$raylab" 120 "$dir" | tee "$dir/summary.txt"
python3 - "$dir" <<'PY'
import json, sys
r = json.load(open(sys.argv[1] + '/soak.json'))
# Frames rendered when each figure was read: the warm-up's third, then the end (counted as the window counts
# them, so no exact number is asserted beyond their order).
assert 0 < r['warm_frame'] < r['frames'], r
for key in ('warm_rss_kib', 'end_rss_kib', 'peak_rss_kib'):
    assert isinstance(r[key], int) and r[key] > 1000, (key, r)  # a Vulkan process holds megabytes
assert r['growth_kib'] == r['end_rss_kib'] - r['warm_rss_kib'], r
frames = [f for f, _ in r['series']]
assert frames == sorted(frames) and len(frames) >= 3 and frames[0] == r['warm_frame'] and frames[-1] == r['frames'], r
assert r['render'] == '160x90' and r['device'], r
print('ok: soak report well formed')
PY
grep -q "^soak: 120 frames" "$dir/summary.txt"
