#!/usr/bin/env bash
# The window's figures are the headless ones (issue 18): for each strategy, and for two-point under the auto
# sort policy, the window under Xvfb (validation on, the default 40 ms render budget, so each frame renders
# over several UI frames) and `raylab render --stats` render the same settings, and from medians over the
# frames (each side's first frame left out: pipelines made on first use):
#   - each stage's share of its frame (stages taking at least 10% of it on both sides, and the sort) agrees
#     within 0.1x-10x,
#   - each strategy's frame time over the unsorted one (the speed-accuracy panel's ratios) within 0.1x-10x,
#   - the frame and every stage time within 0.1x-10x,
#   - auto explores alike (its first six frames' plans are headless's), then decides every bounce from
#     measured gain and cost, and the cost it measured for each bounce's sort is headless's within 0.1x-10x.
#     (Which way a bounce goes can differ: at this size gain and cost are a few ms, and auto's gain is the
#     difference of one sorted and one unsorted explore frame, which this machine's noise can turn around.)
# The tolerances are this wide because the machine the tests run on is shared, slow and busy (load 6-9 on 2
# cores made the same headless frame take 22-82 ms); the shares are taken within each frame, so load mostly
# cancels in them, and they are the tight check (0.5x-2x failed once in three runs while other builds ran: the
# window's shade share 0.16 against headless's 0.35; 0.2x-5x failed on Debian 13 beside the 9-minute GPU-AV
# subset: fixed's frame over unsorted read 4.25 in the window and 0.75 headless, whose unsorted frame took 49 ms
# against the window's 16). These are sanity bounds, not speed claims. Measured by hand on a quieter machine the window is within
# about 10% of headless (docs/lab-window.md). The error this guards against was 15-80x (fixed 15x, two-point
# 100x its unsorted frame): path-range slices made sorting that much dearer than it is.
set -eu
raylab="$1"
repo="$2"
source "$(dirname "$0")/../window_test_setup.sh"  # skips without a window; temporary folder; validation on
size=160x90 bounces=3 frames=6
auto_frames=10  # auto warms up (2 frames) and explores (4) before it decides
strategies="none fixed average gaussian two-point"
{
  echo "set bounces $bounces"
  for s in $strategies; do printf 'set strategy %s\nwait %d\n' "$s" "$frames"; done
  printf 'set sort-policy auto\nwait %d\nquit\n' "$auto_frames"
} >script.txt
timeout 600 bash "$on_xvfb" 1280x720x24 "$raylab" --window-size $size --scale 1 \
  --frame-log log.jsonl --script script.txt >window.log 2>&1 || { echo "FAIL: the window exited $?"; tail -20 window.log; exit 1; }
if grep -q "validation error" window.log; then echo "FAIL: validation errors"; grep "validation error" window.log | head; exit 1; fi
for s in $strategies auto; do
  policy=always strategy=$s
  n=$frames
  [ "$s" = auto ] && policy=auto strategy=two-point n=$auto_frames
  timeout 300 "$raylab" render --size $size --bounces $bounces --strategy $strategy --sort-policy $policy \
    --frames $n --stats "$s.json" --out "$s.png" >"$s.log" 2>&1 || { echo "FAIL: render $s exited $?"; tail "$s.log"; exit 1; }
done

python3 - log.jsonl $bounces <<'PY'
import json, re, statistics, sys
BOUNCES = int(sys.argv[2])
rows = [json.loads(line) for line in open(sys.argv[1])]
# The window's completed frames per setting (the partial frame a change abandons never completes).
window = {}
for r in rows:
    if not r["frame_done"]:
        continue
    f = r["frame"]
    if len(f["sorted_after"]) != BOUNCES:
        continue  # the window's very first frames, before the script set the bounces
    window.setdefault("auto" if f["sort_policy"] == "auto" else f["strategy"], []).append(f)
def headless(name):
    out = []
    for f in json.load(open(name + ".json"))["frames"]:
        stages = {}
        for t in f["stages"]:
            stages[t["stage"]] = stages.get(t["stage"], 0.0) + t["ms"]
        out.append({"gpu_frame_ms": f["gpu_frame_ms"], "stages": stages,
                    "sorted_after": [b["sorted_after"] for b in f["bounces"]],
                    "sort_reasons": [b["sort_reason"] for b in f["bounces"]]})
    return out
failures = []
def compare(what, w, h, lo, hi, unit="ms"):
    ratio = w / h if h > 0 else float("inf")
    print(f"{what:30s} window {w:9.3f} {unit:5s} headless {h:9.3f} {unit:5s} ratio {ratio:5.2f}")
    if not lo <= ratio <= hi:
        failures.append(f"{what}: window {w:.3f}, headless {h:.3f} (allowed ratio {lo}-{hi})")
def median(frames, field):
    return statistics.median(field(f) for f in frames)
names = ["none", "fixed", "average", "gaussian", "two-point", "auto"]
sides = {}
for name in names:
    w, h = window.get(name, []), headless(name)
    assert len(w) >= 3 and len(h) >= 3, f"{name}: {len(w)} window frames, {len(h)} headless"
    sides[name] = (w[1:], h[1:])
unsorted = [median(frames, lambda f: f["gpu_frame_ms"]) for frames in sides["none"]]
for name, (w, h) in sides.items():
    frame = [median(w, lambda f: f["gpu_frame_ms"]), median(h, lambda f: f["gpu_frame_ms"])]
    compare(name + " frame", *frame, 0.1, 10.0)
    if name != "none":
        compare(name + " frame / unsorted", frame[0] / unsorted[0], frame[1] / unsorted[1], 0.1, 10.0, "")
    for stage in sorted(set(h[0]["stages"]) | set(w[0]["stages"])):
        ms = [median(w, lambda f: f["stages"].get(stage, 0.0)), median(h, lambda f: f["stages"].get(stage, 0.0))]
        share = [median(w, lambda f: f["stages"].get(stage, 0.0) / f["gpu_frame_ms"]),
                 median(h, lambda f: f["stages"].get(stage, 0.0) / f["gpu_frame_ms"])]
        # Small stages (generate: 1-3 ms) swing by 5x under load; the sort, whose cost slicing once
        # multiplied, is always compared.
        if min(share) >= 0.10 or stage == "sort":
            compare(f"{name} {stage}", *ms, 0.1, 10.0)
            compare(f"{name} {stage} share", *share, 0.1, 10.0, "")
# auto: the window's first frames warm up and explore as headless ones do (sorted and unsorted alternately);
# after that every bounce but the last is decided from measured gain and cost (or probed, rarely), and the
# costs are headless's.
wa, ha = window["auto"], headless("auto")
EXPLORE = 6
for i in range(EXPLORE):
    if wa[i]["sorted_after"] != ha[i]["sorted_after"]:
        failures.append(f"auto frame {i}: window plan {wa[i]['sorted_after']}, headless {ha[i]['sorted_after']}")
decision = re.compile(r"gain (-?[0-9.e+-]+) (?:>|<=) cost ([0-9.e+-]+) ms")
for b in range(BOUNCES - 1):
    costs = []
    for side, frames in (("window", wa[EXPLORE:]), ("headless", ha[EXPLORE:])):
        frames = [f for f in frames if not f["sort_reasons"][b].startswith("probe")]
        found = [decision.match(f["sort_reasons"][b]) for f in frames]
        if not frames or not all(found):
            failures.append(f"auto bounce {b}: {side} did not decide from measurements: "
                            f"{[f['sort_reasons'][b] for f in frames]}")
            break
        costs.append(statistics.median(float(m.group(2)) for m in found))
    if len(costs) == 2:
        compare(f"auto bounce {b} sort cost", *costs, 0.1, 10.0)
if failures:
    print("FAIL:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("window matches headless")
PY
