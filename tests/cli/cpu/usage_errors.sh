#!/usr/bin/env bash
# A usage error is short (issue 38): the error, a "did you mean" where a near name exists, and where the help
# is, in at most 5 lines (the whole usage after it used to scroll the error away: 60-90 lines), exit 2. A
# sweep naming a viewpoint its scene lacks (bench --cases, study SCENE@VIEW) is refused before it starts:
# exit 2 and no results folder, not a run whose every cell fails.
set -u
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
fail=0
check() {  # check WANTED_TEXT ARGS...: exit 2, at most 5 lines, WANTED_TEXT among them
  local want="$1"; shift
  local out got lines
  out=$(timeout 120 "$raylab" "$@" 2>&1); got=$?
  lines=$(printf '%s\n' "$out" | wc -l)
  if [ "$got" -ne 2 ]; then echo "FAIL: raylab $* exited $got, expected 2"; fail=1; fi
  if [ "$lines" -gt 5 ]; then echo "FAIL: raylab $* printed $lines lines (at most 5):"; printf '%s\n' "$out" | head -8; fail=1; fi
  if ! grep -qF -- "$want" <<<"$out"; then echo "FAIL: raylab $*: no '$want' in: $out"; fail=1; fi
  grep -q -- "--help" <<<"$out" || { echo "FAIL: raylab $* does not say where the help is"; fail=1; }
}
check "did you mean render?" rendr
check "did you mean --bounces?" render --bouncs 3
check "did you mean --bounces?" --bouncs 3
check "did you mean --quick?" study temple --quik
check "must be one of" render --strategy fastest
check "needs a value" render --frames
check "unknown option" bench --frobnicate 1
check "unknown flag" sortbench --frobnicate 1
check "--sort radix" sortbench --radix-tiles 4 --sort onesweep
check "--sort radix" sortbench --radix-rank partition --sort onesweep
check "not auto, ballot or partition" sortbench --radix-rank match
check "not bitonic" sortbench --steps steps.csv
check "did you mean --kinds?" tracebench --kind camera
check "unknown kind 'camra'" tracebench --kinds camra
check "unknown option '--bounces'" tracebench --bounces 3
check "--repeat" tracebench --repeat 0
check "give one of them" tracebench --bvh wide --bvhs sbvh
check "unknown BVH 'quad'" tracebench --bvhs sbvh,quad
check "learns lengths" tracebench --sort-rays gaussian
check "needs --sort-rays" tracebench --kinds bounce-sorted
check "--bounce-depth" tracebench --bounce-depth 9
check "--sort-earlier needs --sort-rays" tracebench --sort-earlier --bounce-depth 2
check "--sort-earlier needs --bounce-depth" tracebench --sort-earlier --sort-rays two-point
check "--export needs a folder" tracebench --export ""
check "--fetches counts the pair-node traversal" tracebench --fetches --bvhs sbvh,wide
check "did you mean hall?" bench --cases temple@hal --out-dir bench-out
[ -e bench-out ] && { echo "FAIL: a refused bench sweep left bench-out behind"; fail=1; }
check "did you mean hall?" study temple@hal --out-dir study-out
[ -e study-out ] && { echo "FAIL: a refused study left study-out behind"; fail=1; }
check "no viewpoint 'nowhere'" bench --cases cornell@front,temple-detail:20000@nowhere --out-dir bench-out
# Help texts: one usage line for bench, the study's default folder, clutter:N under --scene, the script's
# actions in the window's help (not "see app/ui_script.h"), --camera for render.
[ "$("$raylab" bench --help | grep -c '^usage:')" -eq 1 ] || { echo "FAIL: bench --help has more than one usage line"; fail=1; }
"$raylab" study --help | grep -q "default study-out" || { echo "FAIL: study --help names no default folder"; fail=1; }
"$raylab" render --help | grep -q "clutter:N" || { echo "FAIL: render --help omits clutter:N"; fail=1; }
"$raylab" render --help | grep -q -- "--camera" || { echo "FAIL: render --help has no --camera"; fail=1; }
"$raylab" --help | grep -q "ui_script.h" && { echo "FAIL: --help sends the reader to app/ui_script.h"; fail=1; }
[ "$fail" -eq 0 ] && echo "ok: usage errors in at most 5 lines with did-you-mean; bad sweep cases refused before any folder"
exit "$fail"
