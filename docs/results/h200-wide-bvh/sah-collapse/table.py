#!/usr/bin/env python3
"""The sorting study on the wide BVH, greedy against SAH-optimal collapse (study-greedy.csv, study-sah.csv):
per case, size and bounce count, the megakernel, the best unsorted frame (split or fused) and the best sorted
frame, median ms, for each collapse; then sah over greedy for each. Usage: python3 table.py [DIR]"""
import csv
import os
import statistics
import sys

here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))


def load(how):
    cells = {}
    for r in csv.DictReader(open(os.path.join(here, f"study-{how}.csv"))):
        key = (r["scene"].split("/")[-1], r["view"], f'{r["width"]}x{r["height"]}', int(r["bounces"]))
        kind = "mega" if r["kernel"] == "megakernel" else ("unsorted" if r["strategy"] == "none" else "sorted")
        ms = float(r["frame_ms_median"])
        c = cells.setdefault(key, {})
        c[kind] = min(c.get(kind, ms), ms)
    return cells


greedy, sah = load("greedy"), load("sah")
print("| case | size | bounces | greedy: megakernel / unsorted / sorted | sah: megakernel / unsorted / sorted "
      "| sah/greedy unsorted | sah/greedy sorted | speed-up of sorting, unsorted / sorted (greedy, sah) |")
print("|---|---|---|---|---|---|---|---|")
ratios = {"unsorted": [], "sorted": [], "mega": []}
for key in sorted(greedy, key=lambda k: (k[0], k[1], k[2], k[3])):
    if key not in sah:
        continue
    g, s = greedy[key], sah[key]
    for kind in ratios:
        ratios[kind].append(s[kind] / g[kind])
    print(f"| {key[0]}@{key[1]} | {key[2]} | {key[3]} | {g['mega']:.2f} / {g['unsorted']:.2f} / {g['sorted']:.2f} "
          f"| {s['mega']:.2f} / {s['unsorted']:.2f} / {s['sorted']:.2f} | {s['unsorted'] / g['unsorted']:.3f} "
          f"| {s['sorted'] / g['sorted']:.3f} | {g['unsorted'] / g['sorted']:.2f}x, {s['unsorted'] / s['sorted']:.2f}x |")
for kind, values in ratios.items():
    print(f"sah/greedy {kind}: median {statistics.median(values):.3f}, range {min(values):.3f}-{max(values):.3f}, "
          f"{len(values)} cells")
