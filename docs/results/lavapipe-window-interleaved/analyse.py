"""Issue 18's table from measure.sh's rounds: per method, the median over rounds of each pair's
window/headless ratio (frame, sort, every stage of at least 5% of the frame) and of the ratios to unsorted;
the spread (min-max over rounds) beside it. Frame 1 of each run is left out (pipelines built on first use)."""
import glob, json, os, statistics, sys

med = statistics.median
METHODS = ["none", "fixed", "average", "gaussian", "two-point", "auto"]


def window_frames(path):
    out = []
    for line in open(path):
        r = json.loads(line)
        if r.get("frame_done") and len(r["frame"].get("sorted_after", [])) == 4:
            out.append(r["frame"])
    return out[1:]


def headless_frames(path):
    out = []
    for f in json.load(open(path))["frames"]:
        st = {}
        for t in f["stages"]:
            st[t["stage"]] = st.get(t["stage"], 0) + t["ms"]
        out.append({"gpu_frame_ms": f["gpu_frame_ms"], "stages": st})
    return out[1:]


def figures(frames):
    stages = sorted({s for f in frames for s in f["stages"]})
    return {"frame": med(f["gpu_frame_ms"] for f in frames),
            "stages": {s: med(f["stages"].get(s, 0) for f in frames) for s in stages}}


def main(top):
    rounds = sorted(glob.glob(os.path.join(top, "r*")))
    pairs = {m: [] for m in METHODS}  # (window figures, headless figures) per round
    for r in rounds:
        for m in METHODS:
            w, h = os.path.join(r, m + ".window.jsonl"), os.path.join(r, m + ".json")
            if os.path.exists(w) and os.path.exists(h):
                pairs[m].append((figures(window_frames(w)), figures(headless_frames(h))))
    print(f"{len(rounds)} rounds; medians over rounds of each pair's window/headless ratio [min-max]")
    print(f"{'method':10s} {'frame':>18s} {'sort':>18s} | worst stage of >= 5% of the frame")
    worst_all = 1.0
    for m in METHODS:
        ps = pairs[m]
        if not ps:
            continue
        fr = [w["frame"] / h["frame"] for w, h in ps]
        so = [w["stages"].get("sort", 0) / h["stages"]["sort"] for w, h in ps if h["stages"].get("sort", 0) > 0]
        worst, worst_name = 1.0, ""
        for s in ps[0][1]["stages"]:
            if med(h["stages"].get(s, 0) for _, h in ps) < 0.05 * med(h["frame"] for _, h in ps):
                continue
            ratio = med(w["stages"].get(s, 0) / h["stages"][s] for w, h in ps if h["stages"].get(s, 0) > 0)
            if abs(ratio - 1) > abs(worst - 1):
                worst, worst_name = ratio, s
        worst_all = max(worst_all, abs(med(fr) - 1) + 1, abs(worst - 1) + 1)
        span = lambda xs: f"{med(xs):5.2f} [{min(xs):.2f}-{max(xs):.2f}]" if xs else f"{'-':>18s}"
        print(f"{m:10s} {span(fr):>18s} {span(so):>18s} | {worst_name} {worst:.2f}  (ms: window {med(w['frame'] for w, _ in ps):.1f}, headless {med(h['frame'] for _, h in ps):.1f})")
    print("ratios to unsorted, window over headless (median over rounds of the rounds' own ratios):")
    for m in METHODS[1:]:
        rs = [(w["frame"] / wn["frame"]) / (h["frame"] / hn["frame"])
              for (w, h), (wn, hn) in zip(pairs[m], pairs["none"])]
        if rs:
            print(f"  {m:10s} {med(rs):.3f} [{min(rs):.3f}-{max(rs):.3f}]")
    print("auto's plans (sorted_after per bounce, frame by frame), window against headless:")
    for r in rounds:
        w = [json.loads(l)["frame"] for l in open(os.path.join(r, "auto.window.jsonl")) if json.loads(l).get("frame_done")]
        h = json.load(open(os.path.join(r, "auto.json")))["frames"]
        wp = [f["sorted_after"] for f in w if len(f.get("sorted_after", [])) == 4]
        hp = [[b["sorted_after"] for b in f["bounces"]] for f in h]
        n = min(len(wp), len(hp))
        same = sum(wp[i] == hp[i] for i in range(n))
        print(f"  {os.path.basename(r)}: {same} of {n} frames alike; last plans window {wp[n - 1]} headless {hp[n - 1]}")
    print(f"largest departure of a median from 1: {worst_all - 1:.3f}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
