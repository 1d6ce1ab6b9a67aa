"""Issue 20's tables from one lavapipe sweep (run.sh): per case and bounce count, for the binary and the wide
BVH, the megakernel, the best unsorted frame (split or fused), the best sorted one (always or auto, split or
fused) and their ratios, and the wide/binary ratio of the unsorted split trace stage (summed over bounces).
Usage: python3 table.py results.csv"""
import csv
import statistics
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
cells = {}
for r in rows:
    case = (r["scene"].strip('"').split("/")[-1] + "@" + r["view"], int(r["bounces"]))
    c = cells.setdefault(case, {}).setdefault(r["bvh"], {})
    f = float(r["frame_ms_median"])
    if r["kernel"] == "megakernel":
        c["mega"] = f
    elif r["strategy"] == "none":
        c.setdefault("unsorted", []).append((f, r["trace_shade"]))
        if r["trace_shade"] == "split":
            c["trace"] = float(r["trace_ms"])
    else:
        c.setdefault("sorted", []).append((f, r["sort_policy"] + " " + r["trace_shade"]))

print("| case | bounces | BVH | megakernel | best unsorted | best sorted | sorted/unsorted | unsorted/megakernel |"
      " unsorted trace | trace wide/binary |")
print("|---|---|---|---|---|---|---|---|---|---|")
for (case, bounces), by in sorted(cells.items()):
    for bvh in ("binary", "wide"):
        c = by.get(bvh)
        if not c:
            continue
        u, s = min(c["unsorted"]), min(c["sorted"])
        tw = by["wide"]["trace"] / by["binary"]["trace"] if bvh == "wide" and "binary" in by else None
        print(f"| {case} | {bounces} | {bvh} | {c['mega']:.0f} | {u[0]:.0f} ({u[1]}) | {s[0]:.0f} ({s[1]}) | "
              f"{s[0] / u[0]:.2f} | {u[0] / c['mega']:.2f} | {c['trace']:.0f} | {'' if tw is None else f'{tw:.2f}'} |")

# One line per release: the spread of the wide/binary ratios of the unsorted trace and the best unsorted frame.
trace, frame = [], []
for (case, bounces), by in cells.items():
    if "binary" in by and "wide" in by:
        trace.append(by["wide"]["trace"] / by["binary"]["trace"])
        frame.append(min(by["wide"]["unsorted"])[0] / min(by["binary"]["unsorted"])[0])
if trace:
    print(f"\nwide/binary, unsorted split trace: {min(trace):.2f}-{max(trace):.2f} (median {statistics.median(trace):.2f}); "
          f"best unsorted frame: {min(frame):.2f}-{max(frame):.2f} (median {statistics.median(frame):.2f}), {len(trace)} cases")
