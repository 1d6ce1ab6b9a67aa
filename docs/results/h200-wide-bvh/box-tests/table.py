#!/usr/bin/env python3
"""README.md's tables: each variant's wide-BVH frame / trace ms (mean of the two rounds' medians) and its frame
time over main's (base3), from b2f.csv and hitmask.csv (lines: variant,round,<bench CSV row>)."""
import csv
import os
from collections import defaultdict

HERE = os.path.dirname(os.path.abspath(__file__))


def load(name):
    header, cells = None, defaultdict(lambda: defaultdict(list))
    with open(os.path.join(HERE, name)) as f:
        for line in f.read().splitlines():
            variant, _, rest = line.split(",", 2)
            fields = next(csv.reader([rest]))
            if fields[0] == "device":
                header = fields
                continue
            r = dict(zip(header, fields))
            scene = "Sponza" if "Sponza" in r["scene"] else ("temple-detail:1000000" if "detail" in r["scene"] else "hall")
            kind = "megakernel" if r["kernel"] == "megakernel" else ("sorted" if r["strategy"] != "none" else "unsorted")
            if r["bvh"] == "wide":
                cells[(scene, kind)][variant].append((float(r["frame_ms_median"]), float(r["trace_ms"])))
    return cells


def mean(values):
    return sum(values) / len(values)


def table(name, variants):
    cells = load(name)
    print(f"| case | cell | {' | '.join(variants)} | {' | '.join(v + ' / base3' for v in variants[1:])} |")
    print("|---" * (2 + 2 * len(variants) - 1) + "|")
    for (scene, kind), by in cells.items():
        frame = {v: mean([x[0] for x in by[v]]) for v in variants}
        trace = {v: mean([x[1] for x in by[v]]) for v in variants}
        shown = [f"{frame[v]:.2f}" if kind == "megakernel" else f"{frame[v]:.2f} / {trace[v]:.2f}" for v in variants]
        print(f"| {scene} | {kind} | {' | '.join(shown)} | {' | '.join(f'{frame[v] / frame[variants[0]]:.3f}' for v in variants[1:])} |")


if __name__ == "__main__":
    table("b2f.csv", ["base3", "b2f"])
    print()
    table("hitmask.csv", ["base3", "hitmask", "hitmaskb"])
