#!/usr/bin/python3
"""Where sorting pays on one scene, as one self-contained HTML report (issue 22).

usage: /usr/bin/python3 app/study/study_report.py [--note TEXT] [--motion DIR]... [--motion-note TEXT]
                                                  OUT.html BENCH_DIR [BENCH_DIR...]
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
  - under a moving camera: one table per `raylab bench --camera-path` folder given with --motion
    (app/study/study_motion.py), or --motion-note's reason for none;
  - the device, driver, revision and the exact commands.
"Sorted" means a wavefront cell with a key strategy that sorted (policy always, or auto where it chose to); "unsorted" the
wavefront without a strategy (split or fused, compacted or not: the best of those measured). Figures are
medians over the sweep's rounds (each round's own median of its timed frames; raylab bench --rounds), shown with
their spread over the rounds [min-max]; where two spreads overlap the report calls the difference "not
distinguishable here" instead of naming a winner (app/bench/bench_cells.py's rule, the bench's own). Compare ratios
within a report, not across machines. Not measured is "n/a".
Needs Debian's python3-matplotlib; exits 2 with a message when the folders hold no usable cells.
"""
import base64
import html
import io
import json
import math
import os
import sys

EXIT_NO_MATPLOTLIB = 3  # app/bench/bench_charts_run.cpp knows it: the study then keeps its results and says so
try:
    import matplotlib
except ImportError:
    print(f"study_report.py: matplotlib is missing for {sys.executable} (Debian's python3-matplotlib is for "
          "/usr/bin/python3: run the report with it, or set RAYLAB_PYTHON for raylab study): no report",
          file=sys.stderr)
    sys.exit(EXIT_NO_MATPLOTLIB)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

_app = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path[0:0] = [_app, os.path.join(_app, "bench")]  # app/checked_write.py, app/bench/bench_cells.py
from checked_write import write_with  # noqa: E402  (app/checked_write.py)
from bench_cells import NotABenchFolder, distinguishable, load_cells, rounds_of, spread  # noqa: E402
from study_motion import motion_section  # noqa: E402  (app/study/study_motion.py)


def fail(message):
    print(f"study_report: {message}", file=sys.stderr)
    sys.exit(2)


def sweep_of(folder):
    """A bench folder's args and revision, from its sweep.json."""
    sweep_path = os.path.join(folder, "sweep.json")
    sweep = {}
    if os.path.isfile(sweep_path):
        with open(sweep_path) as f:
            sweep = json.load(f)
    return {"folder": folder, "args": sweep.get("args", []), "revision": sweep.get("git_revision", "?")}


def load(folders):
    """Every cell of every folder, with its sweep's args and revision."""
    cells, sweeps = [], []
    for folder in folders:
        sweeps.append(sweep_of(folder))
        try:
            cells.extend(load_cells(folder))  # one record per cell, its rounds made one
        except (NotABenchFolder, ValueError) as e:
            fail(str(e))
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
        "frame": spread(r["frame_ms"]),  # (median, min, max) over the rounds
        "trace": spread((r.get("stage_ms") or {}).get("trace")),
        "rounds": rounds_of(cell),
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
    # Counts where the best sorted and unsorted frames are within each other's spread: no winner there.
    unresolved = [q for q, s_, u_, _ in usable if not distinguishable(s_["frame"], u_["frame"])]
    if pays_from is None:
        text.append(f"sorting does not pay at any measured path count (up to {paths_text(ratios[-1][0])} paths per frame)")
    elif pays_from == ratios[0][0]:
        text.append(f"sorting pays at every measured path count, from {paths_text(pays_from)} paths per frame")
    else:
        text.append(f"sorting pays from about {paths_text(pays_from)} paths per frame")
    if unresolved:
        text.append("the best sorted and unsorted frames are not distinguishable here (their spreads over the rounds "
                    "overlap) at " + ", ".join(paths_text(q) for q in unresolved) + " paths")
    mega = ""
    if m:
        mega = (f" and {m['frame_ms'] / s['frame_ms']:.2f}x that of the megakernel ({spread_text(m['frame'])} ms"
                + ("" if distinguishable(m["frame"], s["frame"]) else ", not distinguishable from it here") + ")")
    sorted_text = f", sorting after {s['sorted_after']} of {s['sortable']} bounces" if s["policy"] == "auto" else ""
    text.append(f"at {paths_text(p)} paths the best sorted frame ({s['strategy']} keys, policy {s['policy']}"
                f"{sorted_text}, {spread_text(s['frame'])} ms) runs at {speedup:.2f}x the speed of the best unsorted "
                f"frame ({spread_text(u['frame'])} ms"
                + ("" if distinguishable(s["frame"], u["frame"]) else ", not distinguishable here") + f"){mega}")
    text.append(limit(s, u))
    return "; ".join(text)


def spread_text(sp):
    """'12.3 [11.0-13.5]': a median with its spread over the rounds; the median alone with one round."""
    median, lo, hi = sp
    if median is None:
        return "n/a"
    return f"{median:.2f}" + (f" [{lo:.2f}-{hi:.2f}]" if lo is not None and hi is not None else "")


def policies(by_group):
    """Per group at its largest path count: (best always row, best auto row) among the sorted configurations."""
    out = {}
    for key, by_paths in by_group.items():
        p = max(by_paths)
        rows = [r for kind in ("sorted", "never") for r in by_paths[p].get(kind, [])]
        out[key] = (p, best([r for r in rows if r["policy"] == "always"]), best([r for r in rows if r["policy"] == "auto"]))
    return out


def policy_text(p, always, auto):
    if not always or not auto:
        return "no always and auto cells to compare"
    if not distinguishable(always["frame"], auto["frame"]):
        verdict = "not distinguishable here (the spreads over the rounds overlap)"
    else:
        verdict = ("auto is faster" if auto["frame_ms"] < always["frame_ms"] else "always is faster")
    return (f"at {paths_text(p)} paths, always ({always['strategy']}) {spread_text(always['frame'])} ms against auto "
            f"({auto['strategy']}, sorting after {auto['sorted_after']} of {auto['sortable']} bounces) "
            f"{spread_text(auto['frame'])} ms: {verdict}")


def sorting_cost(stage_ms):
    return sum(median_of(stage_ms.get(n, 0)) for n in ("keys", "oracle-trace", "sort", "reorder", "learn"))


def path_work(stage_ms):
    return sum(median_of(stage_ms.get(n, 0)) for n in ("trace", "shade", "trace+shade"))


def limit(s, u):
    """What limits the gain, from the stage times of the best sorted and unsorted cells."""
    cost = sorting_cost(s["stage_ms"])
    saved = path_work(u["stage_ms"]) - path_work(s["stage_ms"])
    trace_note = ""
    if s["trace"][0] is not None and u["trace"][0] is not None and not distinguishable(s["trace"], u["trace"]):
        trace_note = (f" (their trace times, sorted {spread_text(s['trace'])} and unsorted {spread_text(u['trace'])} ms, "
                      "are not distinguishable here)")
    if saved <= 0:
        return f"sorting saves no trace or shade time here and costs {cost:.2f} ms a frame{trace_note}"
    share = cost / saved
    return (f"sorting costs {cost:.2f} ms a frame (keys, sort, reorder, learning) against {saved:.2f} ms it saves in "
            f"trace and shade: its cost takes {share * 100:.0f}% of the saving{trace_note}")


def png(fig):
    data = io.BytesIO()
    fig.savefig(data, format="png", dpi=110)
    plt.close(fig)
    return "data:image/png;base64," + base64.b64encode(data.getvalue()).decode()


def ratio_error(a, b):
    """The error bar of a / b: from the fastest a over the slowest b to the slowest a over the fastest b (the
    spreads over the rounds); none where a spread was not measured (one round)."""
    ratio = a["frame_ms"] / b["frame_ms"]
    (_, alo, ahi), (_, blo, bhi) = a["frame"], b["frame"]
    if None in (alo, ahi, blo, bhi) or blo <= 0 or bhi <= 0:
        return 0.0, 0.0
    return max(0.0, ratio - alo / bhi), max(0.0, ahi / blo - ratio)


def crossover_chart(cross):
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for (scene, view, bounces), points in sorted(cross.items()):
        for pick, style, name in ((lambda s, m: s, "o-", "sorted"), (lambda s, m: m, "s--", "megakernel")):
            pts = [(p, pick(s, m), u) for p, s, u, m in points if pick(s, m) and u]
            if not pts:
                continue
            errors = [ratio_error(a, u) for _, a, u in pts]
            ax.errorbar([p for p, _, _ in pts], [a["frame_ms"] / u["frame_ms"] for _, a, u in pts],
                        yerr=[[e[0] for e in errors], [e[1] for e in errors]], fmt=style, capsize=3,
                        label=f"{name}, {bounces} bounces")
    ax.axhline(1.0, color="gray", lw=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("paths per frame")
    ax.set_ylabel("frame time / best unsorted frame")
    ax.set_title("Below 1: faster than the best unsorted wavefront (bars: spread over the rounds)", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return png(fig)


def accuracy_chart(rows):
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for r in rows:
        if math.isnan(r["prediction_error"]) or r["prediction_error"] < 0:
            continue
        lo, hi = r["frame"][1], r["frame"][2]
        xerr = [[r["frame_ms"] - lo], [hi - r["frame_ms"]]] if lo is not None and hi is not None else None
        ax.errorbar(r["frame_ms"], r["prediction_error"], xerr=xerr, fmt="o", capsize=3)
        ax.annotate(f"{r['strategy']} {r['policy']} b{r['bounces']}", (r["frame_ms"], r["prediction_error"]), fontsize=7)
    ax.set_xlabel("frame ms (median over the rounds, bars: min-max)")
    ax.set_ylabel("mean prediction error\n(fraction of the scene diagonal)")
    ax.margins(0.15)  # no point half-clipped on the frame
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


def report(out_path, folders, note="", motion=(), motion_note=""):
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
    by_policy = policies(by_group)
    for key in sorted(cross):
        parts.append(f"<li><b>{html.escape(key[0])}@{html.escape(key[1])}, {key[2]} bounces</b>: "
                     f"{html.escape(verdict(cross[key]))}. Policy: {html.escape(policy_text(*by_policy[key]))}.</li>")
    parts.append("</ul>")
    rounds = sorted({r["rounds"] for r in rows})
    parts.append("<p>" + html.escape(
        f"Each cell was measured in {'/'.join(map(str, rounds))} interleaved round(s); times are medians over the "
        "rounds with their spread [min-max]" + ("" if rounds != [1] else
                                                 ": one round shows no spread, so no difference is resolved")) + ".</p>")

    parts.append("<h2>Crossover</h2>")
    parts.append(f'<img alt="crossover" src="{crossover_chart(cross)}">')
    parts.append(table(["scene", "bounces", "paths", "best sorted ms", "best unsorted ms", "megakernel ms",
                        "speed-up (unsorted / sorted)", "best sorted cell"],
                       [(f"{k[0]}@{k[1]}", k[2], paths_text(p), spread_text(s["frame"]) if s else "n/a",
                         spread_text(u["frame"]) if u else "n/a", spread_text(m["frame"]) if m else "n/a",
                         # Speed ratios, as the verdict gives them (issue 38: one convention): > 1 where sorting pays.
                         fmt(u["frame_ms"] / s["frame_ms"]) + "x" if s and u else "n/a", s["label"] if s else "")
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
    parts.append("<p>The relative MSE of a cell's last frame (one sample a pixel per frame) against the study's "
                 "reference reads about 1 for every cell by construction: it measures the noise of a few samples, "
                 "the same for every cell; sorting's effect on the image is the comparison above, which must find "
                 "none.</p>")

    try:
        parts.extend(motion_section(plt, list(motion), motion_note, os.path.dirname(os.path.abspath(out_path)), describe,
                                    table))
    except (NotABenchFolder, ValueError, KeyError) as e:
        fail(f"a motion folder is not usable: {e}")

    devices = sorted({(r["device"].get("name", "?"), r["device"].get("driver", "?")) for r in rows})
    parts.append("<h2>Device, revision and commands</h2>")
    parts.append(table(["device", "driver"], devices))
    parts.append(table(["folder", "revision", "command"],
                       [(sw["folder"], sw["revision"], "raylab bench " + " ".join(sw["args"]))
                        for sw in sweeps + [sweep_of(m) for m in motion]]))

    page = ("<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>raylab study</title><style>"
            "body{font-family:sans-serif;max-width:60em;margin:2em auto;color:#222}"
            "table{border-collapse:collapse;margin:1em 0;font-size:0.85em}"
            "td,th{border:1px solid #bbb;padding:2px 6px;text-align:left}img{max-width:100%}"
            "</style></head><body>" + "\n".join(parts) + "</body></html>\n")
    write_with(out_path, lambda f: f.write(page), mode="w")
    print(f"study_report: {out_path} ({len(rows)} cells, {len(scenes)} case(s))")


def main():
    args = sys.argv[1:]
    options = {"--note": "", "--motion": [], "--motion-note": ""}
    while len(args) >= 2 and args[0] in options:
        if isinstance(options[args[0]], list):
            options[args[0]].append(args[1])
        else:
            options[args[0]] = args[1]
        args = args[2:]
    if len(args) < 2:
        fail("usage: study_report.py [--note TEXT] [--motion DIR]... [--motion-note TEXT] OUT.html BENCH_DIR [BENCH_DIR...]")
    report(args[0], args[1:], options["--note"], options["--motion"], options["--motion-note"])


if __name__ == "__main__":
    main()
