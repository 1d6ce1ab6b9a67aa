#!/usr/bin/python3
"""Draws the benchmark charts from a `raylab bench` output folder (results.csv + cells.jsonl).

Times are medians over the sweep's rounds (--rounds); the frame times carry error bars from the fastest to the
slowest round (none with one round, which shows no spread). A cell not measured (an empty CSV cell) is left out.

usage: /usr/bin/python3 app/bench/bench_charts.py BENCH_OUT_DIR [TITLE]
Writes, per (scene, view) case, into BENCH_OUT_DIR:
  stages_<case>.png      stage time breakdown per strategy (stacked bars)
  speed_accuracy_<case>.png  prediction accuracy against trace time and total frame time
  equal_time_<case>.png  relative MSE against cumulative GPU time, one curve per strategy
  coherence_<case>.png   SIMT and virtual warp efficiency per strategy
  tracers_<case>.png     (sweeps with --tracers) frame and trace-after-first time of every cell, compute
                         tracer against the rt tracer and SER; the SER reordering hint in the title
Sweeps over scene size (--scale-tris) or path length (--bounces 2,4,...) make a case per size and bounce
count (<case> = scene-view-b<bounces>), draw only its stage breakdown, and add per view (and tracer):
  crossover_triangles_<view>.png  frame time of every method over the unsorted wavefront's, the frame
                         times themselves and the virtual warp efficiency of bounces >= 1 (device
                         independent), against the triangle count (log), one column per bounce count; a
                         dashed line where the BVH (nodes + triangles) passes the H200's 50 MB L2
  crossover_bounces_<view>.png    the same ratios against the bounce count, one column per scene size
Sweeps over the path count (--sizes, --spps) name each case by its size and spp too
(<case> = scene-view-WxH-sppN) and add
  paths_per_frame.png    the best sorted frame over the best unsorted one, and the megakernel's over the best
                         unsorted one, against paths per frame (width x height x spp, log), one line per case
                         and bounce count; below them the same ratios against the unsorted virtual warp
                         efficiency of bounces >= 1; the named sizes the sweep has (720p, 1080p: the CSV's
                         size_name) are dotted lines on the paths axis
Sweeps along a camera path (--camera-path; <case> = scene-PATH, a file path by its stem) draw the stage
breakdown (times over the path's frames) and, from motion.json (app/bench/bench_path_charts.py):
  motion_frame_ms_<case>.png          work time of each path frame, one line per cell, cuts dotted
  motion_prediction_error_<case>.png  the prediction error of each path frame (the detailed replay)
Uses Debian's python3-matplotlib (run with /usr/bin/python3). Exit status: 0 charts drawn, 1 a chart could
not be written (named), 2 usage, 3 matplotlib is missing.
"""
import csv
import math
import os
import sys
import textwrap

EXIT_NO_MATPLOTLIB = 3  # app/bench/bench_charts_run.cpp knows it: no charts, and no error of the sweep

# `raylab bench` runs this script at the end of a sweep with --quiet-if-unavailable and tells this exit
# status from a chart that failed: a machine without matplotlib keeps its CSV, and the bench says so, once.
QUIET_IF_UNAVAILABLE = "--quiet-if-unavailable" in sys.argv[1:]
if QUIET_IF_UNAVAILABLE:
    sys.argv.remove("--quiet-if-unavailable")
try:
    import matplotlib
except ImportError:
    if not QUIET_IF_UNAVAILABLE:
        print(f"bench_charts.py: matplotlib is missing for {sys.executable} (Debian's python3-matplotlib is for "
              "/usr/bin/python3; RAYLAB_PYTHON picks the interpreter raylab bench uses): no charts drawn",
              file=sys.stderr)
    sys.exit(EXIT_NO_MATPLOTLIB)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

sys.path.insert(1, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))  # app/, for checked_write.py
from checked_write import write_with  # noqa: E402  (app/checked_write.py)
from bench_cells import load_cells  # noqa: E402  (app/bench/bench_cells.py)
from bench_path_charts import path_charts, safe  # noqa: E402  (app/bench/bench_path_charts.py)

def stage_columns(header, measured):
    """The stages a CSV header has a NAME_ms column for and some cell timed, in the header's order (that of
    renderer/stages.h, which declares them: this script keeps no list of its own to fall behind; one such list
    left the heatmap out)."""
    return [c[:-len("_ms")] for c in header if c.endswith("_ms") and c[:-len("_ms")] in measured]


def load(folder):
    with open(os.path.join(folder, "results.csv")) as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        header = reader.fieldnames or []
    curves = {}
    measured = set()
    for j in load_cells(folder):  # one record per cell, its rounds made one
        measured.update(j["result"].get("stage_ms", {}).keys())
        st = j["settings"]
        key = (st["scene"], j["view"], j["label"], paths_group_of(st["width"], st["height"], st["spp_per_frame"]))
        curves[key] = (j["result"]["error_curve_ms"], j["result"]["error_curve_rel_mse"])
    return rows, curves, stage_columns(header, measured)


def fit_text(fig):
    """Titles wrapped to the figure's width (long case names were cut off on both sides), and log axes
    labelled with plain numbers (a narrow log range printed minor ticks as 4.4x10^0)."""
    def fill(text, inches, points):  # a character is about 0.55 em wide
        width = max(20, int(inches * 72 / (0.55 * points)))
        return "\n".join(textwrap.fill(line, width) for line in text.split("\n"))
    if fig._suptitle is not None:
        fig._suptitle.set_text(fill(fig._suptitle.get_text(), fig.get_figwidth(), fig._suptitle.get_fontsize()))
    for ax in fig.axes:
        inches = fig.get_figwidth() * ax.get_position().width
        ax.set_title(fill(ax.get_title(), inches, ax.title.get_fontsize()), fontsize=ax.title.get_fontsize())
        for axis, scale in ((ax.xaxis, ax.get_xscale()), (ax.yaxis, ax.get_yscale())):
            if scale == "log":
                plain = matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}")
                axis.set_major_formatter(plain)
                axis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    fig.tight_layout()


def save(fig, path):
    """A chart is all there under its name or not there: a failed write exits non-zero naming it."""
    fit_text(fig)
    write_with(path, lambda f: fig.savefig(f, dpi=110, format="png"))


L2_BYTES = 50e6  # the H200's L2


def scene_name(row):
    """A glTF file's name without folder and extension; a built-in name as it is (temple-detail:1e6)."""
    scene = row["scene"]
    if scene.lower().endswith((".gltf", ".glb")):
        scene = os.path.splitext(os.path.basename(scene))[0]
    return scene.replace(":", "-")


def paths_group_of(width, height, spp):
    """The (width, height, spp) a cell's paths per frame come from: cells of one case differ by it in a
    --sizes/--spps sweep."""
    return (int(width), int(height), int(spp))


def paths_group(row):
    return paths_group_of(row["width"], row["height"], row["spp_per_frame"])


def paths_per_frame(row):
    """width x height x spp: the CSV's column, or made from the size for a CSV from before it."""
    if row.get("paths_per_frame"):
        return int(row["paths_per_frame"])
    w, h, spp = paths_group(row)
    return w * h * spp


def case_name(row, with_bounces=False, with_paths=False):
    w, h, spp = paths_group(row)
    return (f'{scene_name(row)}-{safe(row["view"])}' + (f"-{w}x{h}-spp{spp}" if with_paths else "")
            + (f'-b{row["bounces"]}' if with_bounces else ""))


def num(row, key):
    """A CSV cell as a number; nan where not measured (an empty cell)."""
    try:
        return float(row[key])
    except (KeyError, ValueError, TypeError):
        return float("nan")


def frame_error(rows):
    """matplotlib's yerr/xerr of the rows' median frame times: down to the fastest and up to the slowest round
    (frame_ms_min, frame_ms_max: the spread over the rounds); 0 where one round measured no spread."""
    low, high = [], []
    for r in rows:
        median, lo, hi = num(r, "frame_ms_median"), num(r, "frame_ms_min"), num(r, "frame_ms_max")
        low.append(median - lo if lo == lo else 0.0)
        high.append(hi - median if hi == hi else 0.0)
    return [low, high]


def rounds_note(rows):
    """The title's note of how many rounds the medians and error bars come from."""
    counts = sorted({r.get("rounds") or "1" for r in rows})
    n = "/".join(counts)
    return f"median of {n} round{'s' if counts != ['1'] else ''}" + (", bars: min-max over rounds" if counts != ["1"] else ", no spread")


def stacked_stages(rows, stages, title, path):
    fig, ax = plt.subplots(figsize=(max(6, 0.6 * len(rows) + 2), 4.5))
    labels = [r["label"] for r in rows]
    bottom = [0.0] * len(rows)
    for stage in stages:
        values = [num(r, stage + "_ms") for r in rows]
        if not any(v > 0 for v in values):
            continue
        ax.bar(labels, values, bottom=bottom, label=stage)
        bottom = [b + v for b, v in zip(bottom, values)]
    ax.errorbar(labels, [num(r, "frame_ms_median") for r in rows], yerr=frame_error(rows), fmt="k_", capsize=3,
                label="frame (GPU)")
    ax.set_ylabel("GPU time per frame (ms, median)")
    ax.set_title(f"Stage breakdown — {title}\n{rounds_note(rows)}", fontsize=9)
    ax.legend(fontsize=7, ncol=2)
    plt.setp(ax.get_xticklabels(), rotation=45, ha="right", fontsize=7)
    fig.tight_layout()
    save(fig, path)
    plt.close(fig)


def speed_accuracy(rows, title, path):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    # Every cell with a prediction error: the auto policy's too (its counting frame is one it sorted as planned).
    pts = [r for r in rows if num(r, "prediction_error_mean") >= 0]
    for ax, key, name in ((axes[0], "trace_ms", "trace time (ms)"), (axes[1], "frame_ms_median", "frame time (ms)")):
        for r in pts:
            xerr = frame_error([r]) if key == "frame_ms_median" else None
            ax.errorbar(num(r, key), num(r, "prediction_error_mean"), xerr=xerr, fmt="o", capsize=3)
            policy = r.get("sort_policy", "always")
            ax.annotate(r["label"].split(" ")[0] + ("" if policy == "always" else f" {policy}"),
                        (num(r, key), num(r, "prediction_error_mean")), fontsize=7)
        for r in rows:
            # Baselines as vertical lines; the megakernel has no separate trace stage to place.
            if r["strategy"] == "none" and not (key == "trace_ms" and r["kernel"] == "megakernel"):
                ax.axvline(num(r, key), color="grey", ls="--", lw=0.8)
                ax.text(num(r, key), ax.get_ylim()[1] if pts else 0, r["label"], fontsize=7, rotation=90, va="top")
        ax.set_xlabel(name)
        ax.set_ylabel("prediction error / scene diagonal (mean)")
    fig.suptitle(f"Speed against accuracy — {title} ({rounds_note(rows)})", fontsize=9)
    fig.tight_layout()
    save(fig, path)
    plt.close(fig)


def equal_time(rows, curves, title, path):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for r in rows:
        ms, err = curves.get((r["scene"], r["view"], r["label"], paths_group(r)), ([], []))
        if ms and min(err) > 0:
            ax.plot(ms, err, marker=".", label=r["label"])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("cumulative GPU time (ms)")
    ax.set_ylabel("relative MSE vs reference")
    ax.set_title(f"Equal-time image error — {title}")
    ax.legend(fontsize=6)
    fig.tight_layout()
    save(fig, path)
    plt.close(fig)


def coherence(rows, title, path):
    fig, ax = plt.subplots(figsize=(max(6, 0.6 * len(rows) + 2), 4.5))
    labels = [r["label"] for r in rows]
    x = range(len(rows))
    ax.bar([i - 0.2 for i in x], [num(r, "simt_efficiency") for r in rows], width=0.4, label="SIMT (device subgroups)")
    ax.bar([i + 0.2 for i in x], [num(r, "virtual_warp_efficiency_after_first") for r in rows], width=0.4,
           label="virtual warp, W=32, bounces >= 1")
    ax.set_xticks(list(x))
    ax.set_xticklabels(labels, rotation=45, ha="right", fontsize=7)
    ax.set_ylim(0, 1)
    ax.set_ylabel("efficiency")
    ax.set_title(f"Traversal coherence — {title}")
    ax.legend(fontsize=7)
    fig.tight_layout()
    save(fig, path)
    plt.close(fig)


def tracers(rows, title, path):
    """Frame time and trace time of bounces >= 1 per cell, coloured by tracer (hatched: SER)."""
    fig, ax = plt.subplots(figsize=(max(7, 0.55 * len(rows) + 2), 4.8))
    labels = [r["label"] for r in rows]
    x = range(len(rows))
    colours = ["tab:blue" if r.get("tracer", "compute") == "compute" else "tab:orange" for r in rows]
    hatches = ["//" if r.get("ser", "off") != "off" else "" for r in rows]
    for i, r in enumerate(rows):
        ax.bar(i - 0.2, num(r, "frame_ms_median"), width=0.4, color=colours[i], hatch=hatches[i],
               yerr=frame_error([r]), capsize=2, label="frame" if i == 0 else None)
        ax.bar(i + 0.2, num(r, "trace_after_first_ms"), width=0.4, color=colours[i], alpha=0.45,
               label="trace, bounces >= 1" if i == 0 else None)
    ax.set_xticks(list(x))
    ax.set_xticklabels(labels, rotation=45, ha="right", fontsize=7)
    ax.set_ylabel("GPU time per frame (ms, median)")
    hint = sorted({r.get("ser_reordering_hint", "") for r in rows} - {""})
    ax.set_title(f"Compute (blue) vs rt tracer (orange, hatched: SER) — {title}"
                 + (f"\nSER reordering hint: {', '.join(hint)}" if hint else ""), fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    save(fig, path)
    plt.close(fig)


def is_baseline(row):
    # The bench's own unsorted cell ("none", "rt none"), with the run's compaction; the unsorted wavefront with
    # another compaction (--compactions) is a method of its own ("none compaction=...").
    return row["kernel"] == "wavefront" and row["strategy"] == "none" and row["label"] in ("none", "rt none")


def frame_ratios(rows):
    """{(view, tracer): {label: [(triangles, bounces, ratio to the unsorted wavefront, frame ms)]}}."""
    unsorted = {(r["view"], r["tracer"], r["scene"], r["bounces"]): num(r, "frame_ms_median")
                for r in rows if is_baseline(r)}
    series = {}
    for r in rows:
        base = unsorted.get((r["view"], r["tracer"], r["scene"], r["bounces"]))
        if is_baseline(r) or not base or base <= 0:
            continue
        ms = num(r, "frame_ms_median")
        series.setdefault((r["view"], r["tracer"]), {}).setdefault(r["label"], []).append(
            (num(r, "triangles"), int(r["bounces"]), ms / base, ms))
    return series


def coherence_of(rows, label, bounces):
    """[(triangles, virtual warp efficiency of bounces >= 1)] of one method, where measured."""
    pts = [(num(r, "triangles"), num(r, "virtual_warp_efficiency_after_first")) for r in rows
           if r["label"] == label and int(r["bounces"]) == bounces]
    return sorted(p for p in pts if p[1] >= 0)


def l2_crossing(rows):
    """Triangle count at which the BVH passes L2_BYTES, interpolated in log space; None outside the data."""
    points = sorted({(num(r, "triangles"), num(r, "bvh_bytes")) for r in rows})
    for (t0, b0), (t1, b1) in zip(points, points[1:]):
        if b0 < L2_BYTES <= b1 and t0 > 0 and b0 > 0:
            f = (math.log(L2_BYTES) - math.log(b0)) / (math.log(b1) - math.log(b0))
            return math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0)))
    return None


def crossover_triangles(rows, methods, title, path):
    counts = sorted({b for pts in methods.values() for _, b, _, _ in pts})
    fig, axes = plt.subplots(3, len(counts), figsize=(4.2 * len(counts) + 1, 10.5), squeeze=False, sharex=True)
    crossing = l2_crossing(rows)
    unsorted_label = next(r["label"] for r in rows if is_baseline(r))
    for col, bounces in enumerate(counts):
        ratio_ax, ms_ax, vwe_ax = axes[0][col], axes[1][col], axes[2][col]
        for i, (label, pts) in enumerate(sorted(methods.items())):
            colour = f"C{i}"
            pts = sorted(p for p in pts if p[1] == bounces)
            ratio_ax.plot([p[0] for p in pts], [p[2] for p in pts], marker="o", color=colour, label=label)
            ms_ax.plot([p[0] for p in pts], [p[3] for p in pts], marker="o", color=colour, label=label)
            vwe = coherence_of(rows, label, bounces)
            vwe_ax.plot([p[0] for p in vwe], [p[1] for p in vwe], marker="o", color=colour, label=label)
        base = sorted((num(r, "triangles"), num(r, "frame_ms_median")) for r in rows
                      if is_baseline(r) and int(r["bounces"]) == bounces)
        ms_ax.plot([b[0] for b in base], [b[1] for b in base], marker="s", color="black", label="unsorted")
        vwe = coherence_of(rows, unsorted_label, bounces)
        vwe_ax.plot([p[0] for p in vwe], [p[1] for p in vwe], marker="s", color="black", label="unsorted")
        vwe_ax.set_ylim(0, 1)
        vwe_ax.set_xlabel("triangles")
        ratio_ax.axhline(1.0, color="black", lw=0.8)
        for ax in (ratio_ax, ms_ax, vwe_ax):
            ax.set_xscale("log")
            if crossing:
                ax.axvline(crossing, color="grey", ls="--", lw=0.8)
        if crossing:
            ratio_ax.text(crossing, ratio_ax.get_ylim()[1], " BVH > 50 MB", fontsize=7, va="top", color="grey")
        ratio_ax.set_title(f"{bounces} bounce{'s' if bounces != 1 else ''}", fontsize=9)
        ms_ax.set_yscale("log")
    axes[0][0].set_ylabel("frame time / unsorted wavefront")
    axes[1][0].set_ylabel("frame time (ms, median)")
    axes[2][0].set_ylabel("virtual warp efficiency, bounces >= 1")
    axes[0][-1].legend(fontsize=7)
    fig.suptitle(f"Where does sorting pay? {title}", fontsize=10)
    fig.tight_layout()
    save(fig, path)
    plt.close(fig)


def crossover_bounces(rows, methods, title, path):
    sizes = sorted({t for pts in methods.values() for t, _, _, _ in pts})
    fig, axes = plt.subplots(1, len(sizes), figsize=(4.2 * len(sizes) + 1, 4.2), squeeze=False, sharey=True)
    bvh = {num(r, "triangles"): num(r, "bvh_bytes") for r in rows}
    for col, tris in enumerate(sizes):
        ax = axes[0][col]
        for label, pts in sorted(methods.items()):
            pts = sorted((p[1], p[2]) for p in pts if p[0] == tris)
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", label=label)
        ax.axhline(1.0, color="black", lw=0.8)
        ax.set_xscale("log", base=2)
        ax.set_xticks(sorted({p[1] for pts in methods.values() for p in pts}))
        ax.get_xaxis().set_major_formatter(matplotlib.ticker.ScalarFormatter())
        ax.set_xlabel("bounces")
        ax.set_title(f"{tris:.3g} triangles, BVH {bvh.get(tris, float('nan')) / 1e6:.3g} MB", fontsize=9)
    axes[0][0].set_ylabel("frame time / unsorted wavefront")
    axes[0][-1].legend(fontsize=7)
    fig.suptitle(f"Sorting and the megakernel against path length — {title}", fontsize=10)
    fig.tight_layout()
    save(fig, path)
    plt.close(fig)


def crossover_charts(folder, all_rows):
    # The ratios compare cells of one image size and spp: a --sizes/--spps sweep gets a set per size and spp.
    groups = sorted({paths_group(r) for r in all_rows})
    for group in groups:
        rows = [r for r in all_rows if paths_group(r) == group]
        suffix = f"-{group[0]}x{group[1]}-spp{group[2]}" if len(groups) > 1 else ""
        crossover_charts_of(folder, rows, suffix)


def crossover_charts_of(folder, rows, suffix):
    for (view, tracer), methods in frame_ratios(rows).items():
        view_rows = [r for r in rows if r["view"] == view and r["tracer"] == tracer]
        name = view + ("" if tracer == "compute" else f"-{tracer}") + suffix
        title = (f'{view}, {tracer} tracer, {rows[0]["width"]}x{rows[0]["height"]} at {rows[0]["spp_per_frame"]} spp, '
                 f'{rows[0]["device"]}')
        if len({r["triangles"] for r in view_rows}) > 1:
            crossover_triangles(view_rows, methods, title, os.path.join(folder, f"crossover_triangles_{name}.png"))
        if len({r["bounces"] for r in view_rows}) > 1:
            crossover_bounces(view_rows, methods, title, os.path.join(folder, f"crossover_bounces_{name}.png"))
        print(f"crossover charts for {name} in {folder}")


def is_unsorted(row):
    """Any unsorted wavefront cell: the bench's own and its variants (compaction, trace and shade fused)."""
    return row["kernel"] == "wavefront" and row["strategy"] == "none"


def is_megakernel(row):
    return row["kernel"] == "megakernel" and row["strategy"] == "none" and row.get("ser", "off") == "off"


def path_count_ratios(rows):
    """{(case, bounces, tracer): [(paths per frame, best sorted / best unsorted, megakernel / best unsorted,
    unsorted virtual warp efficiency of bounces >= 1 or nan)]}, sorted by paths; a point only where the
    group has an unsorted frame. Best: the fastest median frame of the kind in that group."""
    groups = {}
    for r in rows:
        key = (f'{scene_name(r)}@{r["view"]}', int(r["bounces"]), r.get("tracer", "compute"), paths_group(r))
        groups.setdefault(key, []).append(r)
    lines = {}
    for (case, bounces, tracer, _), group in groups.items():
        def best(pick):
            times = [num(r, "frame_ms_median") for r in group if pick(r)]
            times = [t for t in times if t > 0]
            return min(times) if times else float("nan")
        unsorted = best(is_unsorted)
        if not unsorted > 0:
            continue
        sorted_best = best(lambda r: r["kernel"] == "wavefront" and r["strategy"] != "none")
        mega = best(is_megakernel)
        vwe = [num(r, "virtual_warp_efficiency_after_first") for r in group if is_baseline(r)]
        vwe = vwe[0] if vwe and vwe[0] >= 0 else float("nan")
        lines.setdefault((case, bounces, tracer), []).append(
            (paths_per_frame(group[0]), sorted_best / unsorted, mega / unsorted, vwe))
    return {k: sorted(v) for k, v in lines.items()}


def named_sizes(rows):
    """[(paths per frame, "720p (1280x720)")] for the named sizes the sweep has (its CSV's size_name column,
    filled by raylab from renderer/named_sizes.h: this script keeps no list of sizes of its own), by paths."""
    marks = {}
    for r in rows:
        if r.get("size_name"):
            marks[paths_per_frame(r)] = f'{r["size_name"]} ({r["width"]}x{r["height"]}' + (
                f', {r["spp_per_frame"]} spp)' if str(r.get("spp_per_frame", "1")) != "1" else ")")
    return sorted(marks.items())


def paths_chart(rows, path):
    lines = path_count_ratios(rows)
    several_tracers = len({k[2] for k in lines}) > 1
    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    for i, ((case, bounces, tracer), pts) in enumerate(sorted(lines.items())):
        label = f"{case}, {bounces} bounce{'s' if bounces != 1 else ''}" + (f", {tracer}" if several_tracers else "")
        colour = f"C{i % 10}"
        for col, index in ((0, 1), (1, 2)):
            axes[0][col].plot([p[0] for p in pts], [p[index] for p in pts], marker="o", color=colour, label=label)
            coherent = [p for p in pts if p[3] == p[3]]  # nan: not measured (--no-detail, the rt tracer)
            axes[1][col].scatter([p[3] for p in coherent], [p[index] for p in coherent], color=colour, label=label)
    named = named_sizes(rows)
    for col, what in ((0, "best sorted frame"), (1, "megakernel frame")):
        top, bottom = axes[0][col], axes[1][col]
        top.set_xscale("log")
        for paths, name in named:
            top.axvline(paths, color="grey", ls=":", lw=0.8)
            top.text(paths, 1.0, f" {name}", transform=top.get_xaxis_transform(), fontsize=7, va="top", color="grey")
        top.set_xlabel("paths per frame (width x height x spp)")
        bottom.set_xlabel("unsorted virtual warp efficiency, bounces >= 1")
        bottom.set_xlim(0, 1)
        for ax in (top, bottom):
            ax.axhline(1.0, color="black", lw=0.8)
            ax.set_ylabel(f"{what} / best unsorted frame")
    axes[0][0].set_title("Sorting: below 1 it pays", fontsize=9)
    axes[0][1].set_title("The megakernel: below 1 it beats the unsorted wavefront", fontsize=9)
    axes[0][1].legend(fontsize=7)
    fig.suptitle(f'Frame ratios against the path count — {rows[0]["device"]}', fontsize=10)
    fig.tight_layout()
    save(fig, path)
    plt.close(fig)
    print(f"paths chart in {path}")


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    folder = sys.argv[1]
    rows, curves, stages = load(folder)
    if not rows:
        print(f"bench_charts.py: {folder}/results.csv has no cells: no charts", file=sys.stderr)
        return 0
    several_bounces = len({r["bounces"] for r in rows}) > 1
    several_paths = len({paths_group(r) for r in rows}) > 1
    scale_sweep = several_bounces or len({r["scene"] for r in rows if r["scene"].startswith("temple-detail")}) > 1
    cases = {}
    for r in rows:
        cases.setdefault(case_name(r, several_bounces, several_paths), []).append(r)
    for name, case_rows in cases.items():
        title = (f'{name}, {case_rows[0]["width"]}x{case_rows[0]["height"]} at {case_rows[0]["spp_per_frame"]} spp, '
                 f'{case_rows[0]["device"]}')
        stacked_stages(case_rows, stages, title, os.path.join(folder, f"stages_{name}.png"))
        if scale_sweep:
            continue
        if case_rows[0].get("camera_path"):  # along a path: no reference image (equal time), times over the path
            continue
        speed_accuracy(case_rows, title, os.path.join(folder, f"speed_accuracy_{name}.png"))
        equal_time(case_rows, curves, title, os.path.join(folder, f"equal_time_{name}.png"))
        coherence(case_rows, title, os.path.join(folder, f"coherence_{name}.png"))
        if len({r.get("tracer", "compute") for r in case_rows}) > 1:
            tracers(case_rows, title, os.path.join(folder, f"tracers_{name}.png"))
        print(f"charts for {name} in {folder}")
    if any(r.get("camera_path") for r in rows):
        path_charts(plt, folder, rows[0]["device"])
    if scale_sweep:
        crossover_charts(folder, rows)
    if len({paths_per_frame(r) for r in rows}) > 1:
        paths_chart(rows, os.path.join(folder, "paths_per_frame.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
