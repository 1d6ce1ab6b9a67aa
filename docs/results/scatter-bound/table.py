#!/usr/bin/env python3
"""Tables of run.sh's sortbench rows: ms a sort by variant and tile shape (median of the rounds, their range), and the
three scatters' sum at 8.4M pairs. Usage: python3 table.py [folder]"""
import csv
import statistics
import sys
from collections import defaultdict

folder = sys.argv[1] if len(sys.argv) > 1 else "."
sorts = defaultdict(list)
for r in csv.DictReader(open(f"{folder}/shape.csv")):
    sorts[(r["variant"], r["group"], r["kpt"], r["dist"], int(r["n"]))].append(float(r["median_ms"]))
scatters = defaultdict(lambda: defaultdict(float))
for r in csv.DictReader(open(f"{folder}/shape-steps.csv")):
    if r["step"].startswith("scatter/"):
        scatters[(r["variant"], r["group"], r["kpt"], r["dist"], int(r["n"]))][r["round"]] += float(r["median_ms"])
counts = sorted({k[4] for k in sorts})
print("| variant | group | keys an invocation | keys | " + " | ".join(f"{n / 1e6:.2f}M" for n in counts)
      + " | scatters at 8.4M |")
print("|---" * (5 + len(counts)) + "|")
for key in sorted({k[:4] for k in sorts}, key=lambda k: (k[3], k[0], -int(k[1]), -int(k[2]))):
    cells = []
    for n in counts:
        v = sorts.get(key + (n,))
        cells.append(f"{statistics.median(v):.3f} ({min(v):.3f}-{max(v):.3f})" if v else "")
    sc = scatters.get(key + (max(counts),))
    cells.append(f"{statistics.median(sc.values()):.3f}" if sc else "")
    print(f"| {key[0]} | {key[1]} | {key[2]} | {key[3]} | " + " | ".join(cells) + " |")
