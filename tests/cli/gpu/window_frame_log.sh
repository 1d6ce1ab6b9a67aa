#!/usr/bin/env bash
# The window's --frame-log under Xvfb (validation on): a render budget far below a frame's cost makes the
# window render each frame's steps over several UI frames and preview after each camera change. Every line
# is a JSON object with the documented fields and types; the steps between two completed frames add up to
# exactly one frame's steps; each restart is followed by a preview; every completed frame carries its
# statistics; app/frame_log_report.py reads the log and counts a change that kept the accumulation (the
# strategy) as a change. No timing is asserted (the figures are the benchmark's: docs/lab-window.md).
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
screenshot-window stepped
quit
SCRIPT
timeout 600 bash "$on_xvfb" 1280x720x24 "$raylab" --window-size 160x90 --scale 1 --render-budget-ms 3 \
  --frame-log log.jsonl --screenshot-dir shots --script script.txt >run.log 2>&1 ||
  { echo "FAIL: the window exited $?"; tail -20 run.log; exit 1; }
if grep -q "validation error" run.log; then echo "FAIL: validation errors"; grep "validation error" run.log | head; exit 1; fi
[ -s shots/stepped.png ] || { echo "FAIL: no window screenshot of a frame in steps"; exit 1; }

python3 - log.jsonl <<'PY'
import json, sys
types = {"ui_frame": int, "ui_ms": (int, float), "render_ms": (int, float), "frame_done": bool, "preview": bool,
         "changed": bool, "restarted": bool, "panels": bool, "presented": bool, "steps": int, "frame_steps": int,
         "frame_paths": int,
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
    assert 0 <= row["steps"] <= row["frame_steps"], f"line {n}: more steps than the frame has"
    assert row["changed"] or not row["restarted"], f"line {n}: a restart that is no change"
    if row["frame_done"]:
        frame = row["frame"]
        assert frame["gpu_frame_ms"] > 0 and frame["strategy"] and isinstance(frame["stages"], dict), f"line {n}"
        assert frame["stages"].get("trace", 0) + frame["stages"].get("trace+shade", 0) > 0, f"line {n}: no trace"
        assert len(frame["sorted_after"]) == 3, f"line {n}: sorted_after per bounce"
    else:
        assert "frame" not in row, f"line {n}: frame statistics without a completed frame"
    rows.append(row)
done = [r for r in rows if r["frame_done"]]
assert len(done) >= 2 + 2 + 1 + 2, f"only {len(done)} whole frames for the script's 7 waits"
# A budget of 3 ms cannot hold a frame: frames take several UI frames, and the steps of one frame (since
# the last completed frame or change, which abandons a partial frame) sum to exactly the frame's steps.
assert any(0 < r["steps"] < r["frame_steps"] for r in rows), "no frame was rendered over several UI frames"
steps = 0
for r in rows:
    if r["changed"]:
        steps = 0
    steps += r["steps"]
    if r["frame_done"]:
        assert steps == r["frame_steps"], f"ui frame {r['ui_frame']}: steps sum to {steps}, frame {r['frame_steps']}"
        steps = 0
# The strategy change keeps the accumulation (same image) and is still logged as a change.
assert any(r["changed"] and not r["restarted"] for r in rows), "the strategy change was not logged as a change"
two_point = [r for r in done if r["frame"]["strategy"] == "two-point"]
assert two_point and all(any(r["frame"]["sorted_after"]) for r in two_point), "two-point frames sorted nothing"
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
# Every change that completed a frame before the next is counted, the strategy change among them.
python3 - log.jsonl <<PY
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
want, kept = 0, 0
for i, r in enumerate(rows):
    if r["changed"]:
        for later in rows[i:]:
            if later is not r and later["changed"]:
                break
            if later["frame_done"]:
                want += 1
                kept += 0 if r["restarted"] else 1
                break
got = json.loads("""$(python3 "$repo/app/frame_log_report.py" log.jsonl --json)""")["changes"]
assert got == want and kept > 0, f"the report counts {got} changes, the log has {want} ({kept} without a restart)"
PY
echo '{"ui_ms": "slow"}' >bad.jsonl
if python3 "$repo/app/frame_log_report.py" bad.jsonl 2>bad.txt; then echo "FAIL: a bad log was reported"; exit 1; fi
grep -q "bad.jsonl:1" bad.txt || { echo "FAIL: the bad line is not named"; cat bad.txt; exit 1; }
echo "frame log and report ok"
