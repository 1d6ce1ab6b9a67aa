#!/usr/bin/python3
"""Draws the benchmark charts from a `raylab bench` output folder (results.csv + results.jsonl).

usage: /usr/bin/python3 app/bench_charts.py BENCH_OUT_DIR [TITLE]
Writes, per (scene, view) case, into BENCH_OUT_DIR:
  stages_<case>.png      stage time breakdown per strategy (stacked bars)
  speed_accuracy_<case>.png  prediction accuracy against trace time and total frame time
  equal_time_<case>.png  relative MSE against cumulative GPU time, one curve per strategy
  coherence_<case>.png   SIMT and virtual warp efficiency per strategy
  tracers_<case>.png     (sweeps with --tracers) frame and trace-after-first time of every cell, compute
                         tracer against the rt tracer and SER; the SER reordering hint in the title
Uses Debian's python3-matplotlib (run with /usr/bin/python3).
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STAGES = ["generate", "trace", "learn", "shade", "keys", "oracle-trace", "sort", "reorder",
          "accumulate", "tonemap", "megakernel", "setup", "counters"]


def load(folder):
    with open(os.path.join(folder, "results.csv")) as f:
        rows = list(csv.DictReader(f))
    curves = {}
    with open(os.path.join(folder, "results.jsonl")) as f:
        for line in f:
            j = json.loads(line)
            key = (j["settings"]["scene"], j["view"], j["label"])
            curves[key] = (j["result"]["error_curve_ms"], j["result"]["error_curve_rel_mse"])
    return rows, curves


def case_name(row):
    return f'{os.path.splitext(os.path.basename(row["scene"]))[0]}-{row["view"]}'


def num(row, key):
    try:
        return float(row[key])
    except (KeyError, ValueError):
        return float("nan")


def stacked_stages(rows, title, path):
    fig, ax = plt.subplots(figsize=(max(6, 0.6 * len(rows) + 2), 4.5))
    labels = [r["label"] for r in rows]
    bottom = [0.0] * len(rows)
    for stage in STAGES:
        values = [num(r, stage + "_ms") for r in rows]
        if not any(v > 0 for v in values):
            continue
        ax.bar(labels, values, bottom=bottom, label=stage)
        bottom = [b + v for b, v in zip(bottom, values)]
    ax.set_ylabel("GPU time per frame (ms, median)")
    ax.set_title(f"Stage breakdown — {title}")
    ax.legend(fontsize=7, ncol=2)
    plt.setp(ax.get_xticklabels(), rotation=45, ha="right", fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def speed_accuracy(rows, title, path):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    pts = [r for r in rows if num(r, "prediction_error_mean") >= 0]
    for ax, key, name in ((axes[0], "trace_ms", "trace time (ms)"), (axes[1], "frame_ms_median", "frame time (ms)")):
        for r in pts:
            ax.scatter(num(r, key), num(r, "prediction_error_mean"))
            ax.annotate(r["label"].split(" ")[0], (num(r, key), num(r, "prediction_error_mean")), fontsize=7)
        for r in rows:
            # Baselines as vertical lines; the megakernel has no separate trace stage to place.
            if r["strategy"] == "none" and not (key == "trace_ms" and r["kernel"] == "megakernel"):
                ax.axvline(num(r, key), color="grey", ls="--", lw=0.8)
                ax.text(num(r, key), ax.get_ylim()[1] if pts else 0, r["label"], fontsize=7, rotation=90, va="top")
        ax.set_xlabel(name)
        ax.set_ylabel("prediction error / scene diagonal (mean)")
    fig.suptitle(f"Speed against accuracy — {title}")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def equal_time(rows, curves, title, path):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for r in rows:
        ms, err = curves.get((r["scene"], r["view"], r["label"]), ([], []))
        if ms and min(err) > 0:
            ax.plot(ms, err, marker=".", label=r["label"])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("cumulative GPU time (ms)")
    ax.set_ylabel("relative MSE vs reference")
    ax.set_title(f"Equal-time image error — {title}")
    ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
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
    fig.savefig(path, dpi=110)
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
               label="frame" if i == 0 else None)
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
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    folder = sys.argv[1]
    rows, curves = load(folder)
    cases = {}
    for r in rows:
        cases.setdefault(case_name(r), []).append(r)
    for name, case_rows in cases.items():
        title = f'{name}, {case_rows[0]["width"]}x{case_rows[0]["height"]}, {case_rows[0]["device"]}'
        stacked_stages(case_rows, title, os.path.join(folder, f"stages_{name}.png"))
        speed_accuracy(case_rows, title, os.path.join(folder, f"speed_accuracy_{name}.png"))
        equal_time(case_rows, curves, title, os.path.join(folder, f"equal_time_{name}.png"))
        coherence(case_rows, title, os.path.join(folder, f"coherence_{name}.png"))
        if len({r.get("tracer", "compute") for r in case_rows}) > 1:
            tracers(case_rows, title, os.path.join(folder, f"tracers_{name}.png"))
        print(f"charts for {name} in {folder}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
