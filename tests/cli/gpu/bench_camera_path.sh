#!/usr/bin/env bash
# `raylab bench --camera-path` (issue 37): a short path with a cut, replayed by every cell; one
# path_frames.jsonl line per path frame of every cell and round with its figures, the cut where the path
# file has it, the cells' times over the path, motion.json's recovery recomputed here from the frames, the
# motion charts; the shards of such a sweep merged with their path frames; flags that make no sense with a
# path exit 2 with a one-line message.
set -eu
raylab="$1"
src="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
path="$src/tests/data/camera_paths/cut_at_2.json"

RAYLAB_VALIDATE=1 "$raylab" bench --camera-path "$path" --size 32x16 --bounces 3 --strategies average,two-point \
  --sort-policies always,auto --rounds 2 --warmup 0 --out-dir "$dir/b" >"$dir/out.txt" 2>&1 || { cat "$dir/out.txt"; exit 1; }
python3 - "$dir/b" "$path" <<'PY'
import csv, json, os, sys
out, path_file = sys.argv[1:3]
keyframes = json.load(open(path_file))["keyframes"]
n = keyframes[-1]["frame"] + 1
cut_frames = {k["frame"] for k in keyframes if k.get("cut")}
rows = list(csv.DictReader(open(os.path.join(out, "results.csv"))))
frames = [json.loads(l) for l in open(os.path.join(out, "path_frames.jsonl"))]
rounds = int(rows[0]["rounds"])
assert len(frames) == len(rows) * rounds * n, (len(frames), len(rows), rounds, n)
fields = ["path_frame", "cut", "camera", "frame_ms", "work_ms", "stage_ms", "rays", "prediction_error",
          "cell_hit_rate", "prediction_error_mean", "length_cache_occupancy", "length_cache_resets",
          "learning_restarted", "sorted_after", "measuring", "detailed", "cell", "round", "label", "strategy",
          "sort_policy", "camera_path"]
by = {}
for f in frames:
    missing = [k for k in fields if k not in f]
    assert not missing, (missing, f)
    assert f["cut"] == (f["path_frame"] in cut_frames), f
    assert f["learning_restarted"] == (f["path_frame"] == 0), f
    assert f["detailed"] == (f["round"] == 0), f
    # Every frame of a strategy with a length cache counts its resets (average has none); the others have none.
    assert f["length_cache_resets"] == (0 if f["strategy"] == "average" else None), f
    assert f["rays"][0] > 0 and (f["label"] == "megakernel" or len(f["rays"]) == 3), f["rays"]  # per bounce
    assert f["work_ms"] > 0 and f["frame_ms"] >= f["work_ms"] - 1e-9, f
    by.setdefault((f["cell"], f["round"]), []).append(f)
for (cell, rnd), fs in by.items():
    assert [f["path_frame"] for f in fs] == list(range(n)), (cell, rnd)
for r in rows:
    assert r["path_frames"] == str(n) and r["camera_path"] == path_file, r
    assert float(r["path_total_ms"]) > 0 and abs(float(r["path_mean_ms"]) * n - float(r["path_total_ms"])) < 1e-3 * float(r["path_total_ms"]), r
# Learned strategies measured their prediction error on the detailed replay; the unsorted cells none.
motion = json.load(open(os.path.join(out, "motion.json")))
tol = motion["recovery_tolerance"]
for c in motion["cells"]:
    errs = c["prediction_error"]
    if c["strategy"] == "none":
        assert all(e is None for e in errs) and c["recovery"] == [], c
        continue
    if c["sort_policy"] == "always":
        assert all(e is not None and e >= 0 for e in errs), c
    if all(e is None for e in errs):
        assert c["recovery"] == []
        continue
    assert [r["cut_frame"] for r in c["recovery"]] == sorted(cut_frames), c
    for rec in c["recovery"]:
        k = rec["cut_frame"]
        before = next((errs[f] for f in range(k - 1, -1, -1) if errs[f] is not None), None)
        assert rec["before"] == before, (rec, before)
        want = None
        if before is not None:
            nxt = min([f for f in cut_frames if f > k] + [n])
            want = next((f - k for f in range(k, nxt) if errs[f] is not None and errs[f] <= before * (1 + tol)), None)
        assert rec["frames"] == want and rec["recovered"] == (want is not None), (rec, want)
md = open(os.path.join(out, "motion.md")).read()
assert all(c["label"] in md for c in motion["cells"]), md
print("ok: bench along a camera path,", len(frames), "path frames")
PY
# The motion charts, where matplotlib is there to draw them.
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  stem=$(basename "$path" .json)
  for chart in motion_frame_ms motion_prediction_error; do
    [ -s "$dir/b/${chart}_temple-$stem.png" ] || { echo "FAIL: no ${chart}_temple-$stem.png"; ls "$dir/b"; exit 1; }
  done
  echo "ok: motion charts"
fi

# Shards of a camera-path sweep merge into its path frames and motion summaries: every cell round's frames
# once, in cell, round and frame order, each line as its shard wrote it, and a motion.json row per cell.
shard_sweep=(--camera-path "$path" --size 16x8 --bounces 2 --strategies two-point --sort-policies always --rounds 1
             --warmup 0 --no-charts)
for i in 0 1; do
  "$raylab" bench "${shard_sweep[@]}" --shard $i/2 --out-dir "$dir/s$i" >"$dir/s$i.txt" 2>&1 || { cat "$dir/s$i.txt"; exit 1; }
done
"$raylab" bench --merge "$dir/s1" "$dir/s0" --out-dir "$dir/m" --no-charts >"$dir/m.txt" 2>&1 || { cat "$dir/m.txt"; exit 1; }
python3 - "$dir" "$path" <<'PY'
import json, os, sys
d, path_file = sys.argv[1:3]
n = json.load(open(path_file))["keyframes"][-1]["frame"] + 1
lines = lambda f: [json.loads(l) for l in open(os.path.join(d, f, "path_frames.jsonl"))]
shards = lines("s0") + lines("s1")
merged = lines("m")
key = lambda f: (f["cell"], f["round"], f["path_frame"])
assert [key(f) for f in merged] == sorted(key(f) for f in shards), [key(f) for f in merged]
cells = sorted({f["cell"] for f in merged})
assert cells == [0, 1, 2] and len(merged) == 3 * n, (cells, len(merged))  # megakernel, none, two-point
assert all(f == next(s for s in shards if key(s) == key(f)) for f in merged)
motion = json.load(open(os.path.join(d, "m", "motion.json")))
assert [c["cell"] for c in motion["cells"]] == cells, motion
print("ok: merged shards of a camera-path sweep,", len(merged), "path frames")
PY

# Refusals: exit 2, one line, naming the problem; no folder made.
refuse() {
  local want="$1"; shift
  local out rc=0
  out=$("$raylab" bench --size 16x8 --bounces 2 --strategies average --out-dir "$dir/x" "$@" 2>&1) || rc=$?
  [ "$rc" = 2 ] || { echo "FAIL: exit $rc for $*: $out"; exit 1; }
  [ "$(wc -l <<<"$out")" -le 2 ] || { echo "FAIL: too long for $*: $out"; exit 1; }
  grep -qF -- "$want" <<<"$out" || { echo "FAIL: no '$want' for $*: $out"; exit 1; }
}
refuse "not both" --camera-path "$path" --cases temple@hall
refuse "--timed-frames does not apply" --camera-path "$path" --timed-frames 4
refuse "--reference-spp does not apply" --camera-path "$path" --reference-spp 4
refuse "did you mean builtin:walk?" --camera-path builtin:wallk
refuse "cannot open" --camera-path "$dir/missing.json"
[ ! -e "$dir/x" ] || { echo "FAIL: a refused bench made its folder"; exit 1; }
echo "ok: refusals"
