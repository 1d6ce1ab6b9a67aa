#!/usr/bin/env python3
"""The tables of README.md from this folder's bench results (rt-vs-compute.jsonl, detail10m.jsonl)."""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
# The issue's own table (revision f130477, the hand-written binary builder), 2048x1024, 4 bounces.
BEFORE = {"temple": (76, 4.9, 1.88e9, 1.75e9), "Sponza": (80, 236, 0.78e9, 0.81e9),
          "temple-detail:1000000": (80, 1170, 0.98e9, 0.95e9), "temple-detail:10000000": (80, 12800, 0.82e9, 0.82e9)}


def cells():
    for name in ("rt-vs-compute.jsonl", "detail10m.jsonl"):
        with open(os.path.join(HERE, name)) as f:
            for line in f:
                yield json.loads(line)


def short(scene):
    return "Sponza" if "Sponza" in scene else scene


def key(cell):
    c = cell["csv"]
    layout = "rt" if c["tracer"] == "rt" else c["bvh"]
    kind = "mega" if c["kernel"] == "megakernel" else ("sorted" if c["strategy"] != "none" else "unsorted")
    return short(c["scene"].strip('"')), int(c["width"]), layout, kind


def per_bounce(cell, stage="trace"):
    bounces = cell["result"]["stage_bounce_ms"]
    return [bounces[f"{stage}@{b}"] for b in range(int(cell["csv"]["bounces"])) if f"{stage}@{b}" in bounces]


def main():
    table = {key(c): c for c in cells()}
    scenes = ["temple", "Sponza", "temple-detail:1000000", "temple-detail:10000000"]
    print("| scene | bytes/tri before -> binary, wide | megakernel rays/s before -> binary, wide | unsorted rays/s "
          "before -> binary, wide | trace ms per bounce, binary | trace ms per bounce, wide | trace wide/binary |")
    print("|---|---|---|---|---|---|---|")
    for s in scenes:
        b, w = table[(s, 2048, "binary", "unsorted")], table[(s, 2048, "wide", "unsorted")]
        bm, wm = table[(s, 2048, "binary", "mega")], table[(s, 2048, "wide", "mega")]
        tris = int(b["csv"]["triangles"])
        before = BEFORE[s]
        tb, tw = per_bounce(b), per_bounce(w)
        print(f"| {s} | {before[0]} -> {int(b['csv']['bvh_bytes']) / tris:.1f}, {int(w['csv']['wide_bvh_bytes']) / tris:.1f}"
              f" | {before[2]:.2e} -> {float(bm['csv']['rays_per_second']):.2e}, {float(wm['csv']['rays_per_second']):.2e}"
              f" | {before[3]:.2e} -> {float(b['csv']['rays_per_second']):.2e}, {float(w['csv']['rays_per_second']):.2e}"
              f" | {' / '.join(f'{t:.2f}' for t in tb)} | {' / '.join(f'{t:.2f}' for t in tw)}"
              f" | {sum(tw) / sum(tb):.2f} |")
    print()
    print("| case | paths | trace | megakernel | unsorted frame | sorted frame | sorting's gain | unsorted trace |"
          " sorted trace | trace per bounce, unsorted |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for s in scenes:
        for width in (2048, 4096):
            if (s, width, "binary", "unsorted") not in table:
                continue
            for layout in ("binary", "wide", "rt"):
                m, u, o = (table[(s, width, layout, k)] for k in ("mega", "unsorted", "sorted"))
                fu, fo = float(u["csv"]["frame_ms_median"]), float(o["csv"]["frame_ms_median"])
                paths = int(u["csv"]["paths_per_frame"]) / 1e6
                print(f"| {s} | {paths:.1f}M | {layout} | {float(m['csv']['frame_ms_median']):.2f} | {fu:.2f} | {fo:.2f}"
                      f" | {fu / fo:.2f}x | {float(u['csv']['trace_ms']):.2f} | {float(o['csv']['trace_ms']):.2f}"
                      f" | {' / '.join(f'{t:.2f}' for t in per_bounce(u))} |")


if __name__ == "__main__":
    main()
