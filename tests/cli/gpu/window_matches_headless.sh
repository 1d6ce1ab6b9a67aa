#!/usr/bin/env bash
# The window's figures are the headless ones (issue 18): for each strategy, and for two-point under the auto
# sort policy, the window under Xvfb (validation on, the default 40 ms render budget, so each frame renders
# over several UI frames) and `raylab render --stats` render the same settings; the medians of the GPU frame
# time and of each stage's time (summed over the bounces) agree, and auto's plan is the same: the same
# explore frames, and afterwards the same decision wherever headless found gain and cost clearly apart.
# Tolerance: the window's median within 0.5x-2x of the headless one, for the frame and for every stage
# taking at least 0.5 ms a frame. The machine the tests run on is shared, slow and busy (other builds and
# tests on 2 cores), so this is far wider than what the window achieves on a quiet machine (within 10%,
# docs/lab-window.md), but far narrower than the error it guards against: path-range slices made sorting
# look 15-80x dearer than it is.
set -eu
raylab="$1"
repo="$2"
source "$(dirname "$0")/../window_test_setup.sh"  # skips without a window; temporary folder; validation on
size=160x90 bounces=3 frames=5
strategies="none fixed average gaussian two-point"
{
  echo "set bounces $bounces"
  for s in $strategies; do printf 'set strategy %s\nwait %d\n' "$s" "$frames"; done
  printf 'set sort-policy auto\nwait %d\nquit\n' "$frames"
} >script.txt
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" "$raylab" --window-size $size --scale 1 \
  --frame-log log.jsonl --script script.txt >window.log 2>&1 || { echo "FAIL: the window exited $?"; tail -20 window.log; exit 1; }
if grep -q "validation error" window.log; then echo "FAIL: validation errors"; grep "validation error" window.log | head; exit 1; fi
for s in $strategies auto; do
  policy=always strategy=$s
  [ "$s" = auto ] && policy=auto strategy=two-point
  timeout 300 "$raylab" render --size $size --bounces $bounces --strategy $strategy --sort-policy $policy \
    --frames $frames --stats "$s.json" --out "$s.png" >"$s.log" 2>&1 || { echo "FAIL: render $s exited $?"; tail "$s.log"; exit 1; }
done

python3 - log.jsonl $bounces <<'PY'
import json, re, statistics, sys
LO, HI, MIN_MS = 0.5, 2.0, 0.5
BOUNCES = int(sys.argv[2])
rows = [json.loads(line) for line in open(sys.argv[1])]
# The window's completed frames per setting, from the first whole frame after each change on (the partial
# frame a change abandons never completes).
window, key = {}, None
for r in rows:
    if not r["frame_done"]:
        continue
    f = r["frame"]
    if len(f["sorted_after"]) != BOUNCES:
        continue  # the window's very first frames, before the script set the bounces
    key = "auto" if f["sort_policy"] == "auto" else f["strategy"]
    window.setdefault(key, []).append(f)
def headless(name):
    frames = json.load(open(name + ".json"))["frames"]
    out = []
    for f in frames:
        stages = {}
        for t in f["stages"]:
            stages[t["stage"]] = stages.get(t["stage"], 0.0) + t["ms"]
        out.append({"gpu_frame_ms": f["gpu_frame_ms"], "stages": stages,
                    "sorted_after": [b["sorted_after"] for b in f["bounces"]],
                    "sort_reasons": [b["sort_reason"] for b in f["bounces"]]})
    return out
failures = []
def compare(what, w, h):
    ratio = w / h if h > 0 else float("inf")
    print(f"{what:28s} window {w:9.2f} ms  headless {h:9.2f} ms  ratio {ratio:5.2f}")
    if not LO <= ratio <= HI:
        failures.append(f"{what}: window {w:.2f} ms, headless {h:.2f} ms")
for name in ["none", "fixed", "average", "gaussian", "two-point", "auto"]:
    w, h = window.get(name, []), headless(name)
    assert len(w) >= 3, f"{name}: only {len(w)} window frames"
    # Skip each side's first frame (pipelines made on first use).
    w, h = w[1:], h[1:]
    compare(name + " frame", statistics.median(f["gpu_frame_ms"] for f in w),
            statistics.median(f["gpu_frame_ms"] for f in h))
    for stage in sorted(set(h[0]["stages"]) | set(w[0]["stages"])):
        hm = statistics.median(f["stages"].get(stage, 0.0) for f in h)
        wm = statistics.median(f["stages"].get(stage, 0.0) for f in w)
        if max(hm, wm) >= MIN_MS:
            compare(f"{name} {stage}", wm, hm)
# auto: the window's first frames explore as headless ones do (sorted, then unsorted); after that, each
# bounce whose headless decisions all agree with a margin (gain and cost more than 2x apart in every
# frame) is decided alike in the window.
wa, ha = window["auto"], headless("auto")
for i in (0, 1):
    if wa[i]["sorted_after"] != ha[i]["sorted_after"]:
        failures.append(f"auto frame {i}: window plan {wa[i]['sorted_after']}, headless {ha[i]['sorted_after']}")
number = r"(-?[0-9.e+-]+)"
for b in range(len(ha[0]["sorted_after"]) - 1):
    clear = []
    for f in ha[2:]:
        m = re.match(rf"gain {number} (?:>|<=) cost {number}", f["sort_reasons"][b])
        if m:
            gain, cost = float(m.group(1)), float(m.group(2))
            clear.append(gain > 2 * cost if gain > 2 * cost or 2 * gain < cost else None)
    if clear and None not in clear and len(set(clear)) == 1:
        for f in wa[2:]:
            if f["sorted_after"][b] != clear[0]:
                failures.append(f"auto bounce {b}: headless always {clear[0]}, window {f['sort_reasons'][b]}")
if failures:
    print("FAIL:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("window matches headless")
PY
