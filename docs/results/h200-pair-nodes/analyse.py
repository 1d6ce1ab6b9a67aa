#!/usr/bin/env python3
"""Trace rays per second per bounce (rays / trace ms, from each frame's stages), and frame times, medians over
frames 2 on and then over the rounds (min-max over rounds). Usage: analyse.py DIR (stats.tar.xz unpacked; also h200-sbvh's trace*.tar.xz)."""
import collections
import glob
import json
import os
import statistics
import sys


def trace_rates(frame):
    rays = {i: b["rays"] for i, b in enumerate(frame["bounces"])}
    ms = collections.Counter()
    for s in frame["stages"]:
        if s["stage"] == "trace":
            ms[s["bounce"]] += s["ms"]
    return {b: rays[b] / (ms[b] * 1e-3) / 1e9 for b in ms if ms[b] > 0}


def main(folder):
    rows = collections.defaultdict(list)  # (kind, bin, bvh, size) -> per-round figures
    for path in sorted(glob.glob(os.path.join(folder, "*.json"))):
        parts = os.path.basename(path)[:-5].split("-")
        if len(parts) != 5:  # kind-binary-bvh-size-round; other files (facts) are no frames
            continue
        kind, binary, bvh, size, _ = parts
        frames = json.load(open(path))["frames"][2:]
        rates = [trace_rates(f) for f in frames]
        rows[(kind, binary, bvh, size)].append({
            "b0": statistics.median(r[0] for r in rates),
            "b1": statistics.median(r[1] for r in rates if 1 in r) if any(1 in r for r in rates) else float("nan"),
            "work": statistics.median(f["work_ms"] for f in frames)})
    fmt = lambda v: "%.2f (%.2f-%.2f)" % (statistics.median(v), min(v), max(v))
    print("| run | traversal | tree | size | camera rays G/s | bounce-1 rays G/s | frame work ms |")
    print("|---|---|---|---|---|---|---|")
    for key in sorted(rows):
        r = rows[key]
        print("| %s | %s | %s | %s | %s | %s | %s |" % (key + (fmt([x["b0"] for x in r]), fmt([x["b1"] for x in r]),
                                                        fmt([x["work"] for x in r]))))


if __name__ == "__main__":
    main(sys.argv[1])
