#!/usr/bin/env python3
"""The study's table from the bench CSVs: per case, size and bounce count, the megakernel, the strongest unsorted
wavefront frame (best of split and fused), the best two-point frame, and the ratios; then the trace stage's rays
per second (camera, bounces >= 1) of the unsorted split frame. Usage: table.py study-4.csv study-8.csv"""
import csv
import sys


def f(v):
    return float(v) if v not in ("", None) else float("nan")


rows = [r for path in sys.argv[1:] for r in csv.DictReader(open(path))]
cells = {}
for r in rows:
    key = (r["scene"].split("/")[-1].replace(".gltf", ""), r["view"], int(r["width"]) * int(r["height"]),
           int(r["bounces"]))
    c = cells.setdefault(key, {"mk": float("inf"), "un": float("inf"), "so": float("inf")})
    ms = f(r["frame_ms_median"])
    if r["kernel"] == "megakernel":
        c["mk"] = min(c["mk"], ms)
    elif r["strategy"] == "none":
        if ms < c["un"]:
            c["un"], c["un_label"] = ms, r["label"]
        if r["trace_shade"] == "split":
            c["cam"], c["bnc"] = f(r["trace_camera_rays_per_second"]), f(r["trace_bounce_rays_per_second"])
    elif ms < c["so"]:
        c["so"], c["so_label"], c["so_row"] = ms, r["label"], r
print("| scene | view | paths | bounces | megakernel ms | best unsorted ms | best two-point ms | sorted / unsorted |"
      " sorted / megakernel | sorted: keys + sort ms | trace G rays/s camera / bounces |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for key in sorted(cells):
    c = cells[key]
    r = c["so_row"]
    reorder = f(r["keys_ms"]) + f(r["sort_ms"]) + (f(r["reorder_ms"]) if r["reorder_ms"] else 0.0)
    print("| %s | %s | %.1fM | %d | %.2f | %.2f | %.2f | %.3fx | %.3fx | %.2f | %.2f / %.2f |" % (
        key[0], key[1], key[2] / 1e6, key[3], c["mk"], c["un"], c["so"], c["un"] / c["so"], c["mk"] / c["so"],
        reorder, c.get("cam", float("nan")) / 1e9, c.get("bnc", float("nan")) / 1e9))
