#!/usr/bin/env python3
"""The tables of README.md from this folder's CSVs (tracebench --fetches on lavapipe) and the H200's timings of
the same ray sets (../h200-tree-variants/tracebench.csv, ba3d351: 2048x1024, sbvh, bounce rays unsorted and
sorted by two-point keys). Bytes a ray a warp: each warp's distinct pair nodes (64 B) and leaf entries (48 B)
over its 32 rays, what its lanes' reads come to once shared."""
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = [("hall", "temple", "hall"), ("openings", "temple", "openings"), ("sponza", "Sponza", "CameraMain"),
          ("clutter", "clutter:1000000", "overview"), ("detail", "temple-detail:1000000", "hall")]


def rows(path):
    with open(path) as f:
        return {r["kind"]: r for r in csv.DictReader(f)}


def reread(r):
    """The share of a warp's load bytes that read what the warp had read before: the most its L1 could serve."""
    return 100 * (1 - warp_bytes(r) / load_bytes(r))


def counted(prefix):
    """Each scene of SCENES with its rows of PREFIX-SCENE.csv, where it was counted."""
    for name, scene, view in SCENES:
        path = os.path.join(HERE, f"{prefix}-{name}.csv")
        if os.path.exists(path):
            yield name, scene, view, rows(path)


def warp_bytes(r):
    return float(r["warp_nodes_per_ray"]) * 64 + float(r["warp_entries_per_ray"]) * 48


def load_bytes(r):
    """The bytes of the loads a warp issues in lockstep (each iteration's distinct reads), a ray."""
    return float(r["node_requests_per_ray"]) * 64 + float(r["entry_requests_per_ray"]) * 48


def lane_bytes(r):
    return float(r["nodes_per_ray"]) * 64 + float(r["entries_per_ray"]) * 48


def h200_rates():
    rates = {}
    with open(os.path.join(HERE, "..", "h200-tree-variants", "tracebench.csv")) as f:
        for r in csv.DictReader(f):
            key = (r["bvh"], r["scene"], r["view"], r["kind"])
            if r["width"] == "2048" and r["sort_rays"] == "two-point" and key not in rates:
                rates[key] = (float(r["rays_per_second"]), float(r["warp_efficiency"]))
    return rates


def oracle(name):
    """The same bounce rays in the oracle key's order (the true hit point), where counted."""
    path = os.path.join(HERE, f"oracle-{name}.csv")
    if not os.path.exists(path):
        return "-"
    o = rows(path)["bounce-sorted"]
    return f"{float(o['warp_efficiency']):.3f}, {warp_bytes(o):.0f}, {load_bytes(o):.0f}"


def timed(prefix, bvh):
    """Each scene's unsorted and sorted rows of PREFIX-SCENE.csv with the H200's (rays/s, warp efficiency) of the
    same rays through the tree `bvh`. The counts are of the rays the H200 traced: their warp efficiencies are the
    H200's (to the 4th place)."""
    h200 = h200_rates()
    for name, scene, view, t in counted(prefix):
        u, s = t["bounce"], t["bounce-sorted"]
        (ru, eu), (rs, es) = h200[(bvh, scene, view, "bounce")], h200[(bvh, scene, view, "bounce-sorted")]
        assert abs(float(u["warp_efficiency"]) - eu) < 2e-3 and abs(float(s["warp_efficiency"]) - es) < 2e-3, name
        yield name, u, s, (ru, eu), (rs, es)


def main():
    print("2048x1024 bounce rays, unsorted -> sorted by two-point keys")
    print("| scene | H200 G rays/s | H200 gain | warp efficiency | slots a ray | bytes a ray, lanes | "
          "bytes a ray a warp | warp bytes | MB a window | oracle: warp efficiency, bytes a ray a warp, loads a ray | "
          "loads a ray (bytes) | loads unsorted / sorted | loads the warp read before |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, u, s, (ru, eu), (rs, es) in timed("2k", "sbvh"):
        print(f"| {name} | {ru * 1e-9:.2f} -> {rs * 1e-9:.2f} | {rs / ru:.3f}x | {eu:.3f} -> {es:.3f} | "
              f"{100 * (eu / es - 1):+.1f}% | {lane_bytes(u):.0f} | {warp_bytes(u):.0f} -> {warp_bytes(s):.0f} | "
              f"{100 * (warp_bytes(s) / warp_bytes(u) - 1):+.1f}% | {float(u['window_megabytes']):.1f} -> "
              f"{float(s['window_megabytes']):.1f} | {oracle(name)} | {load_bytes(u):.0f} -> {load_bytes(s):.0f} | "
              f"{load_bytes(u) / load_bytes(s):.3f}x | "
              f"{reread(u):.0f}% -> {reread(s):.0f}% |")
    print()
    print("The same rays through the plain binary tree (binary-SCENE.csv; out of sample: the model was read off the "
          "sbvh rows)")
    print("| scene | H200 gain | warp slots a ray | distinct bytes a ray | loads a ray (bytes) | loads, unsorted / sorted |")
    print("|---|---|---|---|---|---|")
    for name, u, s, (ru, eu), (rs, es) in timed("binary", "binary"):
        print(f"| {name} | {rs / ru:.3f}x | {100 * (eu / es - 1):+.1f}% | {warp_bytes(u):.0f} -> {warp_bytes(s):.0f} | "
              f"{load_bytes(u):.0f} -> {load_bytes(s):.0f} | {load_bytes(u) / load_bytes(s):.3f}x |")
    print()
    print("The H200's gain fitted as a power of one count (or two), over both trees' rows")
    fits()
    print()
    print("Loads a ray (bytes) of the same 2048x1024 bounce rays (sbvh) in each order")
    loads_by_key()
    print()
    print("1280x720, unsorted -> sorted by two-point keys (bounce), and shadow rays (unsorted)")
    print("| scene | warp efficiency | bytes a ray a warp | warp bytes | loads a ray (bytes) | MB a window | "
          "shadow: bytes a ray a warp, loads a ray, MB a window |")
    print("|---|---|---|---|---|---|---|")
    for name, _, _, t in counted("720p"):
        u, s, sh = t["bounce"], t["bounce-sorted"], t["shadow"]
        print(f"| {name} | {float(u['warp_efficiency']):.3f} -> {float(s['warp_efficiency']):.3f} | "
              f"{warp_bytes(u):.0f} -> {warp_bytes(s):.0f} | {100 * (warp_bytes(s) / warp_bytes(u) - 1):+.1f}% | "
              f"{load_bytes(u):.0f} -> {load_bytes(s):.0f} ({100 * (load_bytes(s) / load_bytes(u) - 1):+.1f}%) | "
              f"{float(u['window_megabytes']):.1f} -> {float(s['window_megabytes']):.1f} | "
              f"{warp_bytes(sh):.0f}, {load_bytes(sh):.0f}, {float(sh['window_megabytes']):.1f} |")


def loads_by_key():
    """The loads a ray of the 2048x1024 bounce rays in every order counted: pixel tiles (unsorted), each key."""
    keys = ["two-point", "oracle", "origin-direction", "origin", "fixed", "direction"]
    print("| scene | unsorted (pixel tiles) | " + " | ".join(keys) + " |")
    print("|---" * (len(keys) + 2) + "|")
    for name, _, _, t in counted("2k"):
        cells = [f"{load_bytes(t['bounce']):.0f}"]
        for key in keys:
            path = {"two-point": f"2k-{name}.csv", "oracle": f"oracle-{name}.csv"}.get(key, f"key-{key}-{name}.csv")
            path = os.path.join(HERE, path)
            cells.append(f"{load_bytes(rows(path)['bounce-sorted']):.0f}" if os.path.exists(path) else "-")
        print(f"| {name} | " + " | ".join(cells) + " |")


def gain_points():
    """(H200 gain, loads ratio, distinct-bytes ratio, warp efficiency ratio) of each scene and tree, unsorted over
    sorted by two-point keys: the ten points the fits below are made over."""
    points = []
    for prefix, bvh in (("2k", "sbvh"), ("binary", "binary")):
        for _, u, s, (ru, eu), (rs, es) in timed(prefix, bvh):
            points.append((rs / ru, load_bytes(u) / load_bytes(s), warp_bytes(u) / warp_bytes(s), es / eu))
    return points


def fits():
    """Least squares of log(gain) on the logs of one count (one exponent, no intercept), and of two; the error of
    each point is exp(residual) - 1."""
    points = gain_points()
    names = {1: "loads", 2: "distinct bytes", 3: "warp efficiency"}
    y = [math.log(p[0]) for p in points]
    print(f"| counts | exponents | rms error | largest error |  ({len(points)} points)")
    print("|---|---|---|---|")
    for cols in ((1,), (2,), (3,), (1, 2), (1, 3)):
        x = [[math.log(p[c]) for c in cols] for p in points]
        a = [[sum(r[i] * r[j] for r in x) for j in range(len(cols))] for i in range(len(cols))]
        b = [sum(r[i] * yi for r, yi in zip(x, y)) for i in range(len(cols))]
        if len(cols) == 1:
            coef = [b[0] / a[0][0]]
        else:
            det = a[0][0] * a[1][1] - a[0][1] * a[1][0]
            coef = [(b[0] * a[1][1] - a[0][1] * b[1]) / det, (a[0][0] * b[1] - a[1][0] * b[0]) / det]
        errors = [math.exp(yi - sum(c * v for c, v in zip(coef, r))) - 1 for r, yi in zip(x, y)]
        rms = math.sqrt(sum(e * e for e in errors) / len(errors))
        print(f"| {' + '.join(names[c] for c in cols)} | {', '.join(f'{c:.2f}' for c in coef)} | {100 * rms:.1f}% | "
              f"{100 * max(abs(e) for e in errors):.1f}% |")


def device_run(path):
    """run-h200.sh's CSV: each scene's rates of both orders (medians over its runs) against the loads' ratio."""
    import statistics
    rates = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            rates.setdefault((r["scene"], r["view"], r["sort_rays"], r["kind"]), []).append(float(r["rays_per_second"]))
    print("| scene | order | G rays/s unsorted -> sorted (median of runs) | gain | loads, unsorted / sorted |")
    print("|---|---|---|---|---|")
    for name, scene, view, t in counted("2k"):
        scene_key = "Sponza" if name == "sponza" else scene
        for order, csv_rows in (("two-point", t), ("oracle", rows(os.path.join(HERE, f"oracle-{name}.csv")))):
            u = rates.get((scene_key, view, order, "bounce"))
            s = rates.get((scene_key, view, order, "bounce-sorted"))
            if not u or not s:
                continue
            mu, ms = statistics.median(u), statistics.median(s)
            print(f"| {name} | {order} | {mu * 1e-9:.2f} -> {ms * 1e-9:.2f} | {ms / mu:.3f}x | "
                  f"{load_bytes(t['bounce']) / load_bytes(csv_rows['bounce-sorted']):.3f}x |")


if __name__ == "__main__":
    if len(sys.argv) > 1:
        device_run(sys.argv[1])
    else:
        main()
