import json, statistics, sys
rows = [json.loads(l) for l in open("log.jsonl")]
window = {}
for r in rows:
    if not r["frame_done"]: continue
    f = r["frame"]
    if len(f["sorted_after"]) != 4: continue
    window.setdefault("auto" if f["sort_policy"] == "auto" else f["strategy"], []).append(f)
def head(name):
    out = []
    for f in json.load(open(name + ".json"))["frames"]:
        st = {}
        for t in f["stages"]: st[t["stage"]] = st.get(t["stage"], 0) + t["ms"]
        out.append({"gpu_frame_ms": f["gpu_frame_ms"], "stages": st})
    return out
med = statistics.median
print(f"{'method':10s} {'win frame':>9s} {'head frame':>10s} {'ratio':>5s} | {'win sort':>8s} {'head sort':>9s} {'ratio':>5s} | {'win cov':>7s} {'head cov':>8s} | worst stage ratio")
base = {}
for name in ["none", "fixed", "average", "gaussian", "two-point", "auto"]:
    w = window.get(name, [])[1:]; h = head(name)[1:]
    wf = med(f["gpu_frame_ms"] for f in w); hf = med(f["gpu_frame_ms"] for f in h)
    ws = med(f["stages"].get("sort", 0) for f in w); hs = med(f["stages"].get("sort", 0) for f in h)
    wc = med(sum(f["stages"].values()) / f["gpu_frame_ms"] for f in w); hc = med(sum(f["stages"].values()) / f["gpu_frame_ms"] for f in h)
    worst = ""
    wr = 1
    for st in h[0]["stages"]:
        a = med(f["stages"].get(st, 0) for f in w); b = med(f["stages"].get(st, 0) for f in h)
        if b > 0.05 * hf and abs(a / b - 1) > abs(wr - 1): wr = a / b; worst = f"{st} {a:.1f}/{b:.1f} = {wr:.2f}"
    base[name] = (wf, hf)
    print(f"{name:10s} {wf:9.1f} {hf:10.1f} {wf/hf:5.2f} | {ws:8.1f} {hs:9.1f} {ws/hs if hs else 0:5.2f} | {wc:7.2f} {hc:8.2f} | {worst}  (n={len(w)},{len(h)})")
print("ratios to unsorted (speed-accuracy):")
for name in ["fixed", "average", "gaussian", "two-point", "auto"]:
    a = base[name][0] / base["none"][0]; b = base[name][1] / base["none"][1]
    print(f"  {name:10s} window {a:.3f} headless {b:.3f}  ratio {a/b:.3f}")
