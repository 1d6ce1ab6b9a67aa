"""The study report's "Under a moving camera" section (issue 37): one table per camera path the study replayed
(`raylab bench --camera-path`, one folder each), read from the bench's own motion.json (app/bench/
bench_path_summary.h: path totals, mean frame and prediction error, recovery after each cut; nothing is
summed again here), each cell's kind from the folder's cells.jsonl, and links to the path charts
(app/bench/bench_path_charts.py draws them into the folder). The one figure made here is auto's path total
against the better of always and never, never being the best unsorted wavefront (a strategy's "never" sorts
nothing, so its frame is the unsorted one's: the path benches of docs/results/h200-motion compare so too).
"""
import html
import math
import os

from bench_cells import load_cells  # noqa: E402  (app/bench/bench_cells.py; study_report.py puts it on the path)
from bench_path_charts import load_motion, path_charts  # noqa: E402  (app/bench/bench_path_charts.py)

# The target: auto's time over a whole path within 2% of the better of always and never.
AUTO_TOLERANCE = 0.02


def kind_of(described):
    """megakernel, unsorted, or the policy of a configuration with keys (always, auto): study_report's describe
    classifies cells, but calls an auto cell that sorted nothing in its last frame "never", and along a path
    that frame is one of many."""
    return described["kind"] if described["kind"] in ("megakernel", "unsorted") else described["policy"]


def recovery_text(cell):
    """The frames after each cut until the prediction error is back within tolerance of before it (in brackets:
    of the level the segment settles at), as motion.json records them."""
    if cell["recovery"]:
        def frames(value):
            return "never" if value is None else str(value)
        return ", ".join(f"@{r['cut_frame']}: {frames(r['frames'])} ({frames(r.get('frames_to_settle'))})"
                         for r in cell["recovery"])
    if not cell["cuts"]:
        return "no cut in the frames replayed"
    if cell["mean_prediction_error"] is None:
        return "no prediction"
    return "not measured"


def number(value, digits):
    return "n/a" if value is None or (isinstance(value, float) and math.isnan(value)) else f"{value:.{digits}f}"


def auto_against(auto, always, never):
    """(ratio, which): auto's path total over the better of always and never, and which that was."""
    options = [(c["total_ms"], name) for c, name in ((always, "always"), (never, "never")) if c]
    if not auto or not options:
        return None, None
    better, which = min(options)
    return auto["total_ms"] / better, which


def path_table(motion, kinds, table):
    """One path's rows (baselines, then each strategy's always and auto) and the per-strategy auto verdicts."""
    cells = motion["cells"]
    unsorted = [c for c in cells if kinds.get(c["cell"]) == "unsorted"]
    never = min(unsorted, key=lambda c: c["total_ms"]) if unsorted else None
    rows, verdicts = [], []
    for c in cells:
        if kinds.get(c["cell"]) in ("unsorted", "megakernel"):
            rows.append((c["label"], kinds[c["cell"]] + (" (never)" if c is never else ""), number(c["total_ms"], 1),
                         number(c["mean_frame_ms"], 3), "no prediction", "", recovery_text(c)))
    strategies = []
    for c in cells:
        if kinds.get(c["cell"]) not in ("unsorted", "megakernel") and c["strategy"] not in strategies:
            strategies.append(c["strategy"])
    for strategy in strategies:
        own = {kinds.get(c["cell"]): c for c in cells if c["strategy"] == strategy}
        ratio, which = auto_against(own.get("auto"), own.get("always"), never)
        if ratio is not None:
            verdicts.append((strategy, ratio, which))
        for policy in ("always", "auto"):
            c = own.get(policy)
            if not c:
                continue
            against = ""
            if policy == "auto" and ratio is not None:
                against = f"{(ratio - 1) * 100:+.1f}% against {which}" + (
                    " (faster)" if ratio < 1 else " (within 2%)" if ratio <= 1 + AUTO_TOLERANCE else " (not within 2%)")
            error = c["mean_prediction_error"]
            rows.append((c["label"], policy, number(c["total_ms"], 1), number(c["mean_frame_ms"], 3),
                         "no prediction" if error is None else number(error, 4), against, recovery_text(c)))
    return table(["cell", "policy", "path total ms", "mean frame ms", "mean prediction error",
                  "auto / better of always and never", "frames to recover after each cut (to the settled level)"],
                 rows), verdicts


def verdict_text(verdicts):
    if not verdicts:
        return "no strategy was measured under both always and auto beside the unsorted wavefront"
    within = [v for v in verdicts if v[1] <= 1 + AUTO_TOLERANCE]
    worst = max(verdicts, key=lambda v: v[1])
    return (f"auto keeps within {AUTO_TOLERANCE * 100:.0f}% of the better of always and never over the path for "
            f"{len(within)} of {len(verdicts)} strateg{'y' if len(verdicts) == 1 else 'ies'} (worst: {worst[0]}, "
            f"{(worst[1] - 1) * 100:+.1f}% against {worst[2]})")


def motion_section(plt, folders, note, report_dir, describe, table):
    """The section's HTML parts: `folders` the motion sweeps' bench folders, `note` why there are none,
    `describe` study_report's cell description, `table` its HTML table."""
    parts = ["<h2>Under a moving camera</h2>"]
    if not folders:
        parts.append(f"<p>No camera path was replayed: {html.escape(note or 'none was asked for')}.</p>")
        return parts
    parts.append("<p>Each path replayed by <code>raylab bench --camera-path</code>: every path frame a fresh frame, the "
                 "learned lengths and auto's measured costs carried along from the path's first frame, cuts included. "
                 "Times are GPU work ms over the path's frames (medians over the rounds); the prediction error is the "
                 "mean over bounces &ge; 1 of the detailed replay; never is the best unsorted wavefront.</p>")
    for folder in folders:
        motion = load_motion(folder)
        if not motion or not motion.get("cells"):
            parts.append(f"<p>{html.escape(folder)}: no motion.json (no path frame was measured).</p>")
            continue
        described = {c["cell"]: describe(c) for c in load_cells(folder)}
        kinds = {cell: kind_of(d) for cell, d in described.items()}
        charts = path_charts(plt, folder)
        first = motion["cells"][0]
        about = next(iter(described.values()), {})
        tolerance = motion.get("recovery_tolerance", 0.1) * 100
        parts.append(f"<h3>{html.escape(first['scene'])} along {html.escape(first['camera_path'])} "
                     f"({first['frames']} frames, {html.escape(about.get('size', '?'))}, "
                     f"{about.get('bounces', '?')} bounces, {first['rounds']} round(s))</h3>")
        rows, verdicts = path_table(motion, kinds, table)
        parts.append(f"<p>{html.escape(verdict_text(verdicts))}. Recovery: frames after a cut until the prediction "
                     f"error is within {tolerance:.0f}% of its value before the cut (in brackets: of the level it "
                     "settles at), \"never\" when not before the next cut.</p>")
        parts.append(rows)
        links = [f'<a href="{html.escape(os.path.relpath(chart, report_dir))}">{html.escape(os.path.basename(chart))}</a>'
                 for group in charts.values() for chart in group]
        parts.append("<p>Charts against the path frame: " + (", ".join(links) or "none drawn") + ".</p>")
    return parts
