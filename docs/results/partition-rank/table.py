#!/usr/bin/env python3
"""The tables of README.md from the CSVs the device calls wrote here (run.sh, run2.sh, run3.sh): the sort alone,
ballot against partition (rank.csv, rank-steps.csv); the frame (frame.csv); two sorted passes against three
(bits.csv). Each figure is the median over the rounds of each round's median."""
import csv
import os
import statistics
import sys

here = os.path.dirname(os.path.abspath(__file__))


def rows(name):
    path = os.path.join(here, name)
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []


def med(values):
    values = [float(v) for v in values if v not in ("", None)]
    return statistics.median(values) if values else float("nan")


def spread(values):
    values = [float(v) for v in values if v not in ("", None)]
    return (min(values), max(values)) if values else (float("nan"), float("nan"))


def sort_alone():
    r = rows("rank.csv")
    if not r:
        return
    print("## The sort alone (rank.csv): ms a sort, 23-bit keys, median of rounds (round spread)\n")
    print("| keys | pairs | ballot | partition | change |")
    print("|---|---|---|---|---|")
    for dist in ("uniform", "few"):
        for n in sorted({int(x["n"]) for x in r}):
            cell = {}
            for rank in ("ballot", "partition", "leader"):
                ms = [x["median_ms"] for x in r if x["dist"] == dist and int(x["n"]) == n and x["variant"] == rank]
                cell[rank] = (med(ms), spread(ms))
            b, p = cell["ballot"], cell["partition"]
            print(f"| {dist} | {n / 1e6:.2f}M | {b[0]:.3f} ({b[1][0]:.3f}-{b[1][1]:.3f}) | "
                  f"{p[0]:.3f} ({p[1][0]:.3f}-{p[1][1]:.3f}) | {100 * (p[0] / b[0] - 1):+.1f}% |")
    s = rows("rank-steps.csv")
    if not s:
        return
    print("\nEach pass's dispatches at the largest count, uniform keys (rank-steps.csv), ms:\n")
    n = max(int(x["n"]) for x in s)
    steps = sorted({x["step"] for x in s if int(x["n"]) == n})
    print("| step | ballot | partition |")
    print("|---|---|---|")
    for step in steps:
        v = [med(x["median_ms"] for x in s if x["step"] == step and int(x["n"]) == n and x["dist"] == "uniform"
                 and x["variant"] == rank) for rank in ("ballot", "partition", "leader")]
        print(f"| {step} | {v[0]:.4f} | {v[1]:.4f} |")


def frame_table(name, key, variants, title):
    r = rows(name)
    if not r:
        return
    print(f"\n## {title} ({name}): ms a frame, medians of the rounds\n")
    print("| case | size | " + " | ".join(f"sort {v}" for v in variants) + " | " +
          " | ".join(f"trace {v}" for v in variants) + " | " + " | ".join(f"sorted frame {v}" for v in variants) +
          " | megakernel | unsorted |")
    print("|" + "---|" * (2 + 3 * len(variants) + 2))
    cases = []
    for x in r:
        c = (os.path.basename(x["scene"]).replace(".gltf", "") + "@" + x["view"], f'{x["width"]}x{x["height"]}')
        if c not in cases:
            cases.append(c)
    for scene, size in cases:
        def pick(label_test, variant=None):
            return [x for x in r if os.path.basename(x["scene"]).replace(".gltf", "") + "@" + x["view"] == scene
                    and f'{x["width"]}x{x["height"]}' == size and label_test(x)
                    and (variant is None or key(x) == variant)]
        sorted_rows = {v: pick(lambda x: x["strategy"] != "none" and x["kernel"] == "wavefront", v) for v in variants}
        mk = med(x["frame_ms_median"] for x in pick(lambda x: x["kernel"] == "megakernel"))
        un = med(x["frame_ms_median"] for x in pick(lambda x: x["kernel"] == "wavefront" and x["strategy"] == "none"))
        cols = [f'{med(x["sort_ms"] for x in sorted_rows[v]):.3f}' for v in variants]
        cols += [f'{med(x["trace_ms"] for x in sorted_rows[v]):.3f}' for v in variants]
        cols += [f'{med(x["frame_ms_median"] for x in sorted_rows[v]):.3f}' for v in variants]
        print(f"| {scene} | {size} | " + " | ".join(cols) + f" | {mk:.3f} | {un:.3f} |")


if __name__ == "__main__":
    sort_alone()
    frame_table("frame.csv", lambda x: x["binary"], ("ballot", "partition"), "The frame, ballot against partition")
    frame_table("bits.csv", lambda x: x["sort_bits"], ("0", "16"), "All sorted bits (0) against the top 16")
    sys.exit(0)
