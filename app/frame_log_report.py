#!/usr/bin/python3
"""Reports how live the lab window stayed, from its `--frame-log FILE` (one JSON object per UI frame).

usage: python3 app/frame_log_report.py FRAME_LOG [--skip N] [--json]
  --skip N   leave out the first N UI frames (start-up: pipelines, first allocation)
  --json     one JSON object instead of the text table
Reports, over the UI frames: p50/p95/max of ui_ms (and the UI rate they mean), the render work per UI
frame, whole render frames completed, the window's own cost (ui_ms - render_ms) in the UI frames that
rebuilt the panels and presented, and after each change of settings or camera ("changed", whether or not it
restarted the accumulation: a strategy, grid, clamp or policy change keeps the image; older logs have only
"restarted"): time to preview (the UI frames from the change up to and including the first one that showed
a preview or a completed frame, which after a change is one rendered with the new settings) and time to the
first whole frame (up to the first frame_done). A line that is not a
JSON object with the required fields stops the report with a message naming the line (exit 1).
"""
import json
import sys

REQUIRED = {"ui_ms": (int, float), "render_ms": (int, float), "frame_done": bool}


def percentile(values, p):
    """Nearest-rank percentile (p in 0..100) of a non-empty list."""
    s = sorted(values)
    rank = max(1, -(-len(s) * p // 100))  # ceil(n * p / 100), at least 1
    return s[min(len(s), int(rank)) - 1]


def load(path):
    frames = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            try:
                row = json.loads(line)
            except json.JSONDecodeError as e:
                raise ValueError(f"{path}:{number}: not JSON ({e})")
            if not isinstance(row, dict):
                raise ValueError(f"{path}:{number}: not a JSON object")
            for key, kind in REQUIRED.items():
                if not isinstance(row.get(key), kind) or (kind != bool and isinstance(row.get(key), bool)):
                    raise ValueError(f"{path}:{number}: field {key} missing or of the wrong type")
            frames.append(row)
    return frames


def changed(row):
    """The UI frame changed the settings or the camera (a restart is a change too)."""
    return bool(row.get("changed") or row.get("restarted"))


def latencies(frames):
    """(time to preview, time to whole frame) in ms for each change of settings or camera."""
    previews, wholes = [], []
    for i, row in enumerate(frames):
        if not changed(row):
            continue
        elapsed, preview = 0.0, None
        for later in frames[i:]:
            if later is not row and changed(later):
                break  # changed again before it finished: counts neither
            elapsed += later["ui_ms"]
            if preview is None and (later.get("preview") or later["frame_done"]):
                preview = elapsed
            if later["frame_done"]:
                previews.append(preview)
                wholes.append(elapsed)
                break
    return previews, wholes


def report(frames):
    ui = [r["ui_ms"] for r in frames]
    render = [r["render_ms"] for r in frames]
    previews, wholes = latencies(frames)
    out = {
        "ui_frames": len(frames),
        "ui_ms_p50": percentile(ui, 50),
        "ui_ms_p95": percentile(ui, 95),
        "ui_ms_max": max(ui),
        "ui_hz_at_p50": 1000.0 / percentile(ui, 50) if percentile(ui, 50) > 0 else None,
        "render_ms_p50": percentile(render, 50),
        "render_ms_p95": percentile(render, 95),
        "whole_frames": sum(1 for r in frames if r["frame_done"]),
        "preview_frames": sum(1 for r in frames if r.get("preview")),
        "changes": len(previews),
    }
    # UI frames that rebuilt the panels and presented (the window's own cost shows in these; the others
    # only rendered their steps). Logs of windows that present every frame have no "panels" field.
    drawn = [r["ui_ms"] - r["render_ms"] for r in frames if r.get("panels", True) and r.get("presented", True)]
    if drawn:
        out.update({"panel_frames": len(drawn), "panel_ms_p50": percentile(drawn, 50),
                    "panel_ms_p95": percentile(drawn, 95)})
    if previews:
        out.update({"time_to_preview_ms_p50": percentile(previews, 50), "time_to_preview_ms_max": max(previews),
                    "time_to_whole_frame_ms_p50": percentile(wholes, 50),
                    "time_to_whole_frame_ms_max": max(wholes)})
    return out


def main(argv):
    args = argv[1:]
    as_json = "--json" in args
    args = [a for a in args if a != "--json"]
    skip = 0
    if "--skip" in args:
        i = args.index("--skip")
        if i + 1 >= len(args) or not args[i + 1].isdigit():
            print("frame_log_report: --skip needs a whole number", file=sys.stderr)
            return 2
        skip = int(args[i + 1])
        del args[i:i + 2]
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        frames = load(args[0])[skip:]
    except (OSError, ValueError) as e:
        print(f"frame_log_report: {e}", file=sys.stderr)
        return 1
    if not frames:
        print("frame_log_report: no UI frames in the log", file=sys.stderr)
        return 1
    r = report(frames)
    if as_json:
        print(json.dumps(r))
        return 0
    for key, value in r.items():
        print(f"{key:28s} {value:.1f}" if isinstance(value, float) else f"{key:28s} {value}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
