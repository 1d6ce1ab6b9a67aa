#!/usr/bin/env bash
# The window's --frame-log under Xvfb (validation on): a render budget far below a frame's cost makes the
# window render in slices and preview after each camera change. Every line is a JSON object with the
# documented fields and types; the slices between two completed frames add up to exactly one frame's paths;
# each restart is followed by a preview; app/frame_log_report.py reads the log. No timing is asserted (the
# figures are the benchmark's: docs/lab-window.md).
set -eu
raylab="$1"
repo="$2"
source "$(dirname "$0")/../window_test_setup.sh"  # skips without a window; temporary folder; validation on
cat >script.txt <<'SCRIPT'
set bounces 3
wait 2
view alley
wait 2
camera 0.3 1.6 9 0 1.2 0
wait 1
set strategy two-point
wait 2
screenshot-window sliced
quit
SCRIPT
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" "$raylab" --size 160x90 --scale 1 --render-budget-ms 3 \
  --frame-log log.jsonl --screenshot-dir shots --script script.txt >run.log 2>&1 ||
  { echo "FAIL: the window exited $?"; tail -20 run.log; exit 1; }
if grep -q "validation error" run.log; then echo "FAIL: validation errors"; grep "validation error" run.log | head; exit 1; fi
[ -s shots/sliced.png ] || { echo "FAIL: no window screenshot of a sliced frame"; exit 1; }

python3 - log.jsonl <<'PY'
import json, sys
types = {"ui_frame": int, "ui_ms": (int, float), "render_ms": (int, float), "frame_done": bool, "preview": bool,
         "restarted": bool, "panels": bool, "presented": bool, "slice_paths": int, "frame_paths": int,
         "preview_width": int, "preview_height": int}
rows = []
for n, line in enumerate(open(sys.argv[1]), 1):
    row = json.loads(line)  # raises on a line that is not JSON
    assert isinstance(row, dict), f"line {n}: not an object"
    for key, kind in types.items():
        assert key in row, f"line {n}: no {key}"
        assert isinstance(row[key], kind) and (kind is bool or not isinstance(row[key], bool)), f"line {n}: {key}"
    assert row["ui_frame"] == n - 1, f"line {n}: ui_frame {row['ui_frame']}"
    assert row["ui_ms"] >= row["render_ms"] >= 0, f"line {n}: render work outside its UI frame"
    assert 0 <= row["slice_paths"] <= row["frame_paths"], f"line {n}: slice larger than the frame"
    rows.append(row)
done = [r for r in rows if r["frame_done"]]
assert len(done) >= 2 + 2 + 1 + 2, f"only {len(done)} whole frames for the script's 7 waits"
# A budget of 3 ms cannot hold a frame: frames are sliced, and the slices of one frame (since the last
# completed frame or restart) sum to exactly the frame's paths.
assert any(r["slice_paths"] < r["frame_paths"] for r in rows), "no frame was sliced"
paths = 0
for r in rows:
    if r["restarted"]:
        paths = 0
    paths += r["slice_paths"]
    if r["frame_done"]:
        assert paths == r["frame_paths"], f"ui frame {r['ui_frame']}: slices sum to {paths}, frame {r['frame_paths']}"
        paths = 0
# Each change that restarted the render shows a preview in that UI frame, smaller than the render.
restarts = [r for r in rows if r["restarted"]]
assert len(restarts) >= 2, "the view and camera changes did not restart the render"
for r in restarts[1:]:  # (the first frame of the window may restart before anything was measured)
    assert r["preview"] and 0 < r["preview_width"] < 160, f"ui frame {r['ui_frame']}: no preview after a restart"
print(f"{len(rows)} UI frames, {len(done)} whole frames, {len(restarts)} restarts: log ok")
PY

python3 "$repo/app/frame_log_report.py" log.jsonl >report.txt || { echo "FAIL: the report"; cat report.txt; exit 1; }
grep -q "^ui_ms_p95 " report.txt && grep -q "^time_to_preview_ms_p50 " report.txt ||
  { echo "FAIL: the report lacks its figures"; cat report.txt; exit 1; }
echo '{"ui_ms": "slow"}' >bad.jsonl
if python3 "$repo/app/frame_log_report.py" bad.jsonl 2>bad.txt; then echo "FAIL: a bad log was reported"; exit 1; fi
grep -q "bad.jsonl:1" bad.txt || { echo "FAIL: the bad line is not named"; cat bad.txt; exit 1; }
echo "frame log and report ok"
