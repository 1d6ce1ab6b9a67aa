#!/usr/bin/env python3
"""The sorting study at the final revision (study-4.jsonl, study-8.jsonl): per case, size and bounce count, each
BVH's megakernel, best unsorted (split or fused) and best sorted frame; the best sorted frame of either BVH
against the strongest unsorted one and the fastest megakernel; then, for 8.4M paths, the stages per bounce of
the best unsorted and best sorted cells. Usage: python3 table.py [DIR]"""
import json
import os
import sys

HERE = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))


def load():
    cells = []
    for name in ("study-4.jsonl", "study-8.jsonl"):
        with open(os.path.join(HERE, name)) as f:
            cells += [json.loads(line) for line in f]
    return cells


def case_of(cell):
    c = cell["csv"]
    scene = c["scene"].strip('"').split("/")[-1].replace(".gltf", "")
    return f"{scene}@{c['view']}", f"{c['width']}x{c['height']}", int(c["bounces"])


def kind_of(cell):
    c = cell["csv"]
    return "mega" if c["kernel"] == "megakernel" else ("unsorted" if c["strategy"] == "none" else "sorted")


def best(cells, **match):
    chosen = [c for c in cells if all(c[k] == v for k, v in match.items())]
    return min(chosen, key=lambda c: c["ms"]) if chosen else None


def label(cell):
    return f"{cell['bvh']} {cell['csv']['trace_shade']}"


def stages(cell):
    per = cell["result"]["stage_bounce_ms"]
    names = ["trace", "trace+shade", "shade", "keys", "sort"]
    bounces = int(cell["csv"]["bounces"])
    rows = []
    for b in range(bounces):
        parts = [f"{n} {per[f'{n}@{b}']:.2f}" for n in names if f"{n}@{b}" in per]
        rows.append(", ".join(parts))
    return rows


def main():
    cells = []
    for raw in load():
        case, size, bounces = case_of(raw)
        cells.append({**raw, "case": case, "size": size, "bounces": bounces, "kind": kind_of(raw),
                      "bvh": raw["csv"]["bvh"], "ms": float(raw["csv"]["frame_ms_median"])})
    keys = sorted({(c["case"], c["size"], c["bounces"]) for c in cells})
    print("| case | size | bounces | binary: mega / unsorted / sorted | wide: mega / unsorted / sorted "
          "| best sorted over strongest unsorted | over fastest megakernel |")
    print("|---|---|---|---|---|---|---|")
    for case, size, bounces in keys:
        here = [c for c in cells if (c["case"], c["size"], c["bounces"]) == (case, size, bounces)]
        shown = []
        for bvh in ("binary", "wide"):
            m, u, s = (best(here, bvh=bvh, kind=k) for k in ("mega", "unsorted", "sorted"))
            shown.append(f"{m['ms']:.2f} / {u['ms']:.2f} / {s['ms']:.2f}")
        m, u, s = (best(here, kind=k) for k in ("mega", "unsorted", "sorted"))
        print(f"| {case} | {size} | {bounces} | {shown[0]} | {shown[1]} | {u['ms'] / s['ms']:.2f}x "
              f"({label(s)} against {label(u)}) | {m['ms'] / s['ms']:.2f}x ({m['bvh']}) |")
    print()
    for case, size, bounces in keys:
        if size != "4096x2048" or bounces != 4:
            continue
        here = [c for c in cells if (c["case"], c["size"], c["bounces"]) == (case, size, bounces)]
        u, s = best(here, kind="unsorted"), best(here, kind="sorted")
        print(f"{case}, 8.4M paths, 4 bounces: unsorted {label(u)} {u['ms']:.2f} ms, sorted {label(s)} {s['ms']:.2f} ms")
        for b, (a, z) in enumerate(zip(stages(u), stages(s))):
            print(f"  bounce {b}: unsorted {a}; sorted {z}")


if __name__ == "__main__":
    main()
