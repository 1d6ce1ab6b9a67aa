#!/usr/bin/python3
"""Where sorting pays on one scene, as one self-contained HTML report (issue 22).

usage: /usr/bin/python3 app/study_report.py [--note TEXT] OUT.html BENCH_DIR [BENCH_DIR...]
Reads the cells of one or more `raylab bench` folders (results.jsonl, sweep.json): a study over image sizes,
samples per frame and bounce counts may be one sweep or several (one per size, or shards), and writes OUT.html
with every chart embedded (PNG as data: URLs), so it opens from disk with no network. It opens with the verdict
in plain words, then:
  - the crossover: the best sorted frame and the megakernel over the best unsorted frame, against paths per
    frame (width x height x samples per frame), one line per bounce count;
  - speed against prediction accuracy per strategy at the largest path count;
  - the per-bounce stage times of the best sorted cell against the best unsorted one at the largest count;
  - coherence: virtual warp efficiency and traversal steps of bounces >= 1, unsorted and sorted;
  - the image check: every sorted cell's relative MSE against its unsorted baseline's (the invariant makes
    them equal), and the error against the reference;
  - the device, driver, revision and the exact commands.
"Sorted" means a wavefront cell with a key strategy that sorted (policy always, or auto where it chose to); "unsorted" the
wavefront without a strategy (split or fused, compacted or not: the best of those measured). Figures are
medians of the timed frames of one run: compare ratios within a report, not across machines.
Needs Debian's python3-matplotlib; exits 2 with a message when the folders hold no usable cells.
"""
import base64
import html
import io
import json
import math
import os
import sys

EXIT_NO_MATPLOTLIB = 3  # app/bench_charts_run.cpp knows it: the study then keeps its results and says so
try:
    import matplotlib
except ImportError:
    print("study_report.py: matplotlib is missing (Debian: apt-get install python3-matplotlib): no report",
          file=sys.stderr)
    sys.exit(EXIT_NO_MATPLOTLIB)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checked_write import write_with  # noqa: E402  (app/checked_write.py, beside this script)


def fail(message):
    print(f"study_report: {message}", file=sys.stderr)
    sys.exit(2)


def load(folders):
    """Every cell of every folder, with its sweep's args and revision."""
    cells, sweeps = [], []
    for folder in folders:
        path = os.path.join(folder, "results.jsonl")
        if not os.path.isfile(path):
            fail(f"{folder} has no results.jsonl (not a raylab bench folder?)")
        sweep_path = os.path.join(folder, "sweep.json")
        sweep = {}
        if os.path.isfile(sweep_path):
            with open(sweep_path) as f:
                sweep = json.load(f)
        sweeps.append({"folder": folder, "args": sweep.get("args", []), "revision": sweep.get("git_revision", "?")})
        with open(path) as f:
            for number, line in enumerate(f, 1):
                if not line.strip():
                    continue
                try:
                    cell = json.loads(line)
                except json.JSONDecodeError as e:
                    fail(f"{path}:{number}: not a JSON line ({e.msg})")
                cells.append(cell)
    if not cells:
        fail("no cells in " + ", ".join(folders))
    return cells, sweeps


def num(value):
    try:
        v = float(value)
    except (TypeError, ValueError):
        return float("nan")
    return v


def describe(cell):
    """The facts of a cell the report groups and compares by."""
    s, r, csv = cell["settings"], cell["result"], cell.get("csv", {})
    paths = int(s["width"]) * int(s["height"]) * int(s.get("spp_per_frame", s.get("spp", 1)))
    kernel = s.get("kernel", "wavefront")
    strategy = s.get("strategy", "none")
    policy = s.get("sort_policy", "always")
    if kernel == "megakernel":
        kind = "megakernel"
    elif strategy == "none" or s.get("sort", "radix") == "none":
        kind = "unsorted"
    elif policy == "never" or (policy == "auto" and not any(r.get("sorted_after", []))):
        # A sorted configuration that sorted nothing (never, or auto deciding against): neither a baseline nor
        # a sorted frame; its frame time is the unsorted one's plus noise.
        kind = "never"
    else:
        kind = "sorted"
    bounces_detail = (r.get("detailed_frame") or {}).get("bounces") or []
    after_first = [b for b in bounces_detail if b.get("bounce", 0) >= 1]

    def mean_of(key):
        values = [num(b.get(key)) for b in after_first if b.get(key) is not None]
        values = [v for v in values if not math.isnan(v)]
        return sum(values) / len(values) if values else float("nan")

    return {
        "case": f"{cell.get('scene', {}).get('name', '') or s.get('scene', '?')}",
        "scene": os.path.basename(str(s.get("scene", "?"))),
        "view": cell.get("view", s.get("view", "")),
        "paths": paths,
        "size": f"{s['width']}x{s['height']}",
        "spp": int(s.get("spp_per_frame", 1)),
        "bounces": int(s["bounces"]),
        "kind": kind,
        "strategy": strategy,
        "policy": policy,
        "label": cell.get("label", ""),
        "frame_ms": num(r["frame_ms"]["median"]),
        "stage_ms": r.get("stage_ms", {}),
        "stage_bounce_ms": r.get("stage_bounce_ms", {}),
        "rel_mse": num(r.get("final_rel_mse")),
        "prediction_error": num(csv.get("prediction_error_mean")),
        "vwe": mean_of("virtual_warp_efficiency"),
        "steps": mean_of("mean_traversal_steps"),
        "device": cell.get("device", {}),
        "revision": cell.get("git_revision", "?"),
        "triangles": cell.get("scene", {}).get("triangles"),
        # Bounces the policy sorted after in the last timed frame, of those it could (all but the last).
        "sorted_after": sum(1 for x in r.get("sorted_after", []) if x),
        "sortable": max(0, len(r.get("sorted_after", [])) - 1),
    }


def median_of(stage):
    return num(stage["median"]) if isinstance(stage, dict) else num(stage)


def best(rows):
    rows = [r for r in rows if not math.isnan(r["frame_ms"])]
    return min(rows, key=lambda r: r["frame_ms"]) if rows else None


def groups(rows):
    """(scene, view, bounces) -> paths -> kind -> rows."""
    out = {}
    for r in rows:
        out.setdefault((r["scene"], r["view"], r["bounces"]), {}).setdefault(r["paths"], {}).setdefault(r["kind"], []).append(r)
    return out


def crossover(by_group):
    """Per group: [(paths, best sorted row, best unsorted row, megakernel row)], by paths."""
    out = {}
    for key, by_paths in by_group.items():
        out[key] = [(p, best(k.get("sorted", [])), best(k.get("unsorted", [])), best(k.get("megakernel", [])))
                    for p, k in sorted(by_paths.items())]
    return out


def paths_text(p):
    if p >= 1e6:
        return f"{p / 1e6:.2f}M"
    return f"{p / 1e3:.0f}k" if p >= 1e4 else (f"{p / 1e3:.1f}k".replace(".0k", "k") if p >= 1e3 else str(p))


def verdict(points):
    """Plain-words verdict of one (scene, view, bounces) group."""
    usable = [(p, s, u, m) for p, s, u, m in points if s and u]
    if not usable:
        return "no sorted and unsorted cells of the same size to compare"
    ratios = [(p, s["frame_ms"] / u["frame_ms"]) for p, s, u, _ in usable]
    pays_from = None
    for i, (p, ratio) in enumerate(ratios):  # the smallest count from which sorting pays at every larger one
        if all(r < 1.0 for _, r in ratios[i:]):
            pays_from = p
            break
    p, s, u, m = usable[-1]
    speedup = u["frame_ms"] / s["frame_ms"]
    text = []
    if pays_from is None:
        text.append(f"sorting does not pay at any measured path count (up to {paths_text(ratios[-1][0])} paths per frame)")
    elif pays_from == ratios[0][0]:
        text.append(f"sorting pays at every measured path count, from {paths_text(pays_from)} paths per frame")
    else:
        text.append(f"sorting pays from about {paths_text(pays_from)} paths per frame")
    mega = f" and {m['frame_ms'] / s['frame_ms']:.2f}x that of the megakernel ({m['frame_ms']:.2f} ms)" if m else ""
    sorted_text = f", sorting after {s['sorted_after']} of {s['sortable']} bounces" if s["policy"] == "auto" else ""
    text.append(f"at {paths_text(p)} paths the best sorted frame ({s['strategy']} keys, policy {s['policy']}"
                f"{sorted_text}, {s['frame_ms']:.2f} ms) runs at {speedup:.2f}x the speed of the best unsorted frame "
                f"({u['frame_ms']:.2f} ms){mega}")
    text.append(limit(s, u))
    return "; ".join(text)


def sorting_cost(stage_ms):
    return sum(median_of(stage_ms.get(n, 0)) for n in ("keys", "oracle-trace", "sort", "reorder", "learn"))


def path_work(stage_ms):
    return sum(median_of(stage_ms.get(n, 0)) for n in ("trace", "shade", "trace+shade"))


def limit(s, u):
    """What limits the gain, from the stage times of the best sorted and unsorted cells."""
    cost = sorting_cost(s["stage_ms"])
    saved = path_work(u["stage_ms"]) - path_work(s["stage_ms"])
    if saved <= 0:
        return f"sorting saves no trace or shade time here and costs {cost:.2f} ms a frame"
    share = cost / saved
    return (f"sorting costs {cost:.2f} ms a frame (keys, sort, reorder, learning) against {saved:.2f} ms it saves in "
            f"trace and shade: its cost takes {share * 100:.0f}% of the saving")


def png(fig):
    data = io.BytesIO()
    fig.savefig(data, format="png", dpi=110)
    plt.close(fig)
    return "data:image/png;base64," + base64.b64encode(data.getvalue()).decode()


def crossover_chart(cross):
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for (scene, view, bounces), points in sorted(cross.items()):
        xs = [p for p, s, u, _ in points if s and u]
        ax.plot(xs, [s["frame_ms"] / u["frame_ms"] for p, s, u, _ in points if s and u], "o-",
                label=f"sorted, {bounces} bounces")
        xm = [p for p, _, u, m in points if m and u]
        if xm:
            ax.plot(xm, [m["frame_ms"] / u["frame_ms"] for p, _, u, m in points if m and u], "s--",
                    label=f"megakernel, {bounces} bounces")
    ax.axhline(1.0, color="gray", lw=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("paths per frame")
    ax.set_ylabel("frame time / best unsorted frame")
    ax.set_title("Below 1: faster than the best unsorted wavefront")
    ax.legend(fontsize=8)
    fig.tight_layout()
    return png(fig)


def accuracy_chart(rows):
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for r in rows:
        if math.isnan(r["prediction_error"]) or r["prediction_error"] < 0:
            continue
        ax.scatter(r["frame_ms"], r["prediction_error"], s=25)
        ax.annotate(f"{r['strategy']} {r['policy']} b{r['bounces']}", (r["frame_ms"], r["prediction_error"]), fontsize=7)
    ax.set_xlabel("frame ms (median)")
    ax.set_ylabel("mean prediction error of the end point")
    ax.set_title("Speed against prediction accuracy (largest path count)")
    fig.tight_layout()
    return png(fig)


def per_bounce(stage_bounce_ms):
    """{"trace@1": ms, ...} (the JSONL's medians per stage and bounce) -> {bounce: {stage: ms}}."""
    out = {}
    for key, ms in stage_bounce_ms.items():
        name, _, bounce = key.rpartition("@")
        if name and bounce.lstrip("-").isdigit():
            out.setdefault(int(bounce), {})[name] = num(ms)
    return out


def stage_chart(s, u):
    """Per-bounce stacked stage times of two cells side by side."""
    fig, ax = plt.subplots(figsize=(7, 4.2))
    width = 0.38
    cells = {id(u): per_bounce(u["stage_bounce_ms"]), id(s): per_bounce(s["stage_bounce_ms"])}
    stages = sorted({name for c in cells.values() for b in c.values() for name in b})
    bounces = sorted({b for c in cells.values() for b in c if b >= 0})
    for offset, cell, hatch in ((-width / 2, u, ""), (width / 2, s, "//")):
        bottom = [0.0] * len(bounces)
        for i, name in enumerate(stages):
            values = [cells[id(cell)].get(b, {}).get(name, 0.0) for b in bounces]
            ax.bar([b + offset for b in bounces], values, width, bottom=bottom, color=f"C{i % 10}", hatch=hatch,
                   label=name if cell is u else None, edgecolor="white")
            bottom = [x + v for x, v in zip(bottom, values)]
    ax.set_xticks(bounces)
    ax.set_xlabel("bounce (left: best unsorted, right, hatched: best sorted)")
    ax.set_ylabel("GPU ms (median)")
    ax.legend(fontsize=7, ncol=3)
    fig.tight_layout()
    return png(fig)


def table(headers, rows):
    head = "".join(f"<th>{html.escape(h)}</th>" for h in headers)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in row) + "</tr>" for row in rows)
    return f"<table><tr>{head}</tr>{body}</table>"


def fmt(v, digits=3):
    return "n/a" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{v:.{digits}g}"


def image_check(by_group):
    """Sorted cells whose relative MSE differs from their unsorted baseline's (the invariant says none)."""
    checked, differ = 0, []
    for key, by_paths in by_group.items():
        for p, kinds in by_paths.items():
            base = [u["rel_mse"] for u in kinds.get("unsorted", []) if not math.isnan(u["rel_mse"])]
            for s in kinds.get("sorted", []) + kinds.get("never", []):
                if not base or math.isnan(s["rel_mse"]):
                    continue
                checked += 1
                if s["rel_mse"] != base[0]:
                    differ.append((s["label"], p, s["rel_mse"], base[0]))
    return checked, differ


def report(out_path, folders, note=""):
    cells, sweeps = load(folders)
    rows = [describe(c) for c in cells]
    by_group = groups(rows)
    cross = crossover(by_group)
    scenes = sorted({(r["scene"], r["view"]) for r in rows})
    largest = max(r["paths"] for r in rows)
    at_largest = [r for r in rows if r["paths"] == largest]

    parts = [f"<h1>Where sorting pays: {html.escape(', '.join(f'{s}@{v}' for s, v in scenes))}</h1>"]
    if note:
        parts.append(f"<p><b>{html.escape(note)}</b></p>")
    parts.append("<h2>Verdict</h2><ul>")
    for key in sorted(cross):
        parts.append(f"<li><b>{html.escape(key[0])}@{html.escape(key[1])}, {key[2]} bounces</b>: "
                     f"{html.escape(verdict(cross[key]))}.</li>")
    parts.append("</ul>")

    parts.append("<h2>Crossover</h2>")
    parts.append(f'<img alt="crossover" src="{crossover_chart(cross)}">')
    parts.append(table(["scene", "bounces", "paths", "best sorted ms", "best unsorted ms", "megakernel ms",
                        "sorted / unsorted", "best sorted cell"],
                       [(f"{k[0]}@{k[1]}", k[2], paths_text(p), fmt(s and s["frame_ms"], 4),
                         fmt(u and u["frame_ms"], 4), fmt(m and m["frame_ms"], 4),
                         fmt(s["frame_ms"] / u["frame_ms"]) if s and u else "n/a", s["label"] if s else "")
                        for k, points in sorted(cross.items()) for p, s, u, m in points]))

    parts.append(f"<h2>Speed against accuracy ({paths_text(largest)} paths)</h2>")
    if any(not math.isnan(r["prediction_error"]) and r["prediction_error"] >= 0 for r in at_largest):
        parts.append(f'<img alt="speed against accuracy" src="{accuracy_chart(at_largest)}">')
    else:
        parts.append("<p>No prediction errors measured (a sweep with --no-detail, or strategies that predict no end point).</p>")

    parts.append(f"<h2>Stages per bounce ({paths_text(largest)} paths)</h2>")
    for key in sorted(cross):
        p, s, u, _ = cross[key][-1]
        if s and u and s["stage_bounce_ms"] and u["stage_bounce_ms"]:
            parts.append(f"<h3>{html.escape(key[0])}@{html.escape(key[1])}, {key[2]} bounces</h3>")
            parts.append(f'<img alt="stages" src="{stage_chart(s, u)}">')

    parts.append("<h2>Coherence (bounces &ge; 1)</h2>")
    coherent = [r for r in at_largest if not math.isnan(r["vwe"])]
    if coherent:
        parts.append(table(["scene", "bounces", "cell", "virtual warp efficiency", "traversal steps"],
                           [(f"{r['scene']}@{r['view']}", r["bounces"], r["label"], fmt(r["vwe"]), fmt(r["steps"]))
                            for r in sorted(coherent, key=lambda r: (r["scene"], r["bounces"], r["label"]))]))
    else:
        parts.append("<p>No coherence figures: the sweep skipped the counting frame (--no-detail).</p>")

    checked, differ = image_check(by_group)
    parts.append("<h2>Image check</h2>")
    if checked == 0:
        parts.append("<p>No sorted cell had an unsorted baseline of the same size to compare with.</p>")
    elif not differ:
        parts.append(f"<p>All {checked} sorted cells have their unsorted baseline's relative MSE against the reference, "
                     "as the invariant requires (the tests check the images bit for bit).</p>")
    else:
        parts.append(f"<p><b>{len(differ)} of {checked} sorted cells differ from their unsorted baseline</b>: the "
                     "invariant is broken.</p>")
        parts.append(table(["cell", "paths", "rel MSE", "unsorted rel MSE"], differ))
    parts.append(table(["cell", "scene", "bounces", "paths", "rel MSE against the reference"],
                       [(r["label"], f"{r['scene']}@{r['view']}", r["bounces"], paths_text(r["paths"]), fmt(r["rel_mse"]))
                        for r in at_largest]))

    devices = sorted({(r["device"].get("name", "?"), r["device"].get("driver", "?")) for r in rows})
    parts.append("<h2>Device, revision and commands</h2>")
    parts.append(table(["device", "driver"], devices))
    parts.append(table(["folder", "revision", "command"],
                       [(sw["folder"], sw["revision"], "raylab bench " + " ".join(sw["args"])) for sw in sweeps]))

    page = ("<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>raylab study</title><style>"
            "body{font-family:sans-serif;max-width:60em;margin:2em auto;color:#222}"
            "table{border-collapse:collapse;margin:1em 0;font-size:0.85em}"
            "td,th{border:1px solid #bbb;padding:2px 6px;text-align:left}img{max-width:100%}"
            "</style></head><body>" + "\n".join(parts) + "</body></html>\n")
    write_with(out_path, lambda f: f.write(page), mode="w")
    print(f"study_report: {out_path} ({len(rows)} cells, {len(scenes)} case(s))")


def main():
    args = sys.argv[1:]
    note = ""
    if len(args) >= 2 and args[0] == "--note":
        note, args = args[1], args[2:]
    if len(args) < 2:
        fail("usage: study_report.py [--note TEXT] OUT.html BENCH_DIR [BENCH_DIR...]")
    report(args[0], args[1:], note)


if __name__ == "__main__":
    main()
