#!/usr/bin/env python3
"""Issue 34's targets from the stats JSONs of run.sh: per render, the median work time of detailed and
undetailed frames (frames 2 on), the unattributed share, the stage sums of frames 2 on (flat: their spread),
the counters stage, and wall against GPU time. Usage: analyse.py DIR (the unpacked stats.tar.xz)."""
import json
import os
import statistics
import sys


def spread(values):
    return "%.2f (%.2f-%.2f)" % (statistics.median(values), min(values), max(values))


def main(folder):
    print("| render | frames | work ms, detailed | work ms, not detailed | detailed / not | counters ms "
          "| unattributed % of frame | stage sum ms, frames 2-39 | wall / GPU |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".json"):
            continue
        doc = json.load(open(os.path.join(folder, name)))
        frames = doc["frames"][2:]
        detailed = [f["work_ms"] for f in frames if f["detailed"]]
        plain = [f["work_ms"] for f in frames if not f["detailed"]]
        ratio = "%.3f" % (statistics.median(detailed) / statistics.median(plain)) if detailed and plain else "n/a"
        counters = [f["instrument_ms"] for f in frames if f["detailed"]]
        unattributed = [100 * f["unattributed_ms"] / f["gpu_frame_ms"] for f in frames]
        sums = [f["stage_sum_ms"] for f in frames]
        wall = sum(f["wall_ms"] for f in frames) / sum(f["gpu_frame_ms"] for f in frames)
        print("| %s | %d | %s | %s | %s | %s | %s | %s | %.2f |" % (
            name[:-5], len(doc["frames"]), spread(detailed) if detailed else "n/a", spread(plain) if plain else "n/a",
            ratio, spread(counters) if counters else "n/a", spread(unattributed), spread(sums), wall))


if __name__ == "__main__":
    main(sys.argv[1])
