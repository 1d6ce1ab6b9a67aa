#!/usr/bin/env bash
# Every strategy x heatmap pair, each with one of the kernels and sorts (the wavefront with no sort, bitonic or
# radix, or the megakernel) so that every strategy and every heatmap also meets every one of those, through
# `raylab render` (tiny image, one frame, two bounces, validation on): each either renders a PNG (exit 0) or
# is refused with exit 2 and a message saying why the heatmap is unavailable. Never a crash (139), a runtime
# failure or an empty image. The names come from the program's own help and messages. Renders run four at a
# time: most of a run is start-up waiting. Pairs, not the whole product: the product (every strategy x heatmap
# x kernel-and-sort) was four times the renders and CI's longest test (134 s), and its triples found nothing
# the pairs do not reach.
set -u
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export RAYLAB_VALIDATE=1
strategies=$("$raylab" render --help | sed -n 's/.*--strategy \([a-z|-]*\).*/\1/p' | tr '|' ' ')
heatmaps=$("$raylab" render --heatmap '?' 2>&1 | sed -n 's/.*must be one of \([a-z|-]*\).*/\1/p' | tr '|' ' ')
[ -n "$strategies" ] && [ -n "$heatmaps" ] || { echo "FAIL: cannot list strategies/heatmaps"; exit 1; }

# The heatmap colouring options, the compaction and trace-shade join the product by rotation (line n takes
# key colour n mod 3, scale n mod 2, range n mod 5, compaction n / 3 mod 2, trace-shade n / 6 mod 3): every
# option meets every view, strategy and kernel without multiplying the renders.
one() {  # n kernel sort strategy heatmap -> a line "RESULT kernel sort strategy heatmap"
  local n="$1"; shift
  local colours=(cell rank hash) scales=(linear log) ranges=(auto 1:50 auto auto 0.5:8) compactions=(none shade) traceShades=(split fused loop)
  local name="$1-$2-$3-$4" out rc height
  out=$(timeout 120 "$raylab" render --size 32x16 --bounces 2 --frames 1 --kernel "$1" --sort "$2" \
        --strategy "$3" --heatmap "$4" --heatmap-key-colour "${colours[n % 3]}" --heatmap-scale "${scales[n % 2]}" \
        --heatmap-range "${ranges[n % 5]}" --compaction "${compactions[n / 3 % 2]}" --trace-shade "${traceShades[n / 6 % 3]}" --out "$dir/$name.png" 2>&1)
  rc=$?
  # A heatmap PNG carries its legend below the 16 rows of the image (IHDR height, bytes 20..23).
  height=$( [ -s "$dir/$name.png" ] && od -An -tu1 -j20 -N4 "$dir/$name.png" | awk '{print $1*16777216+$2*65536+$3*256+$4}')
  if [ $rc -eq 0 ] && [ -s "$dir/$name.png" ] && { [ "$4" = none ] || [ "${height:-0}" -gt 16 ]; }; then echo "rendered $*"
  elif [ $rc -eq 2 ] && grep -q "^raylab render: --heatmap $4" <<<"$out"; then echo "refused $*"
  else echo "FAIL $* exit $rc: $(head -2 <<<"$out" | tr '\n' ' ')"; fi
}
export -f one
export raylab dir
# Strategy i with heatmap j takes kernel-and-sort (i + j) mod 4: with at least 4 strategies and 4 heatmaps each
# strategy and each heatmap meets all four. The megakernel sorts nothing (--sort is the wavefront's): it comes
# with the default sort only.
kernel_sorts=(wavefront:none wavefront:bitonic wavefront:radix megakernel:radix)
n=0 i=0
for st in $strategies; do
  j=0
  for h in $heatmaps; do
    ks=${kernel_sorts[(i + j) % ${#kernel_sorts[@]}]}
    echo "$n ${ks%%:*} ${ks##*:} $st $h"; n=$((n + 1)) j=$((j + 1))
  done
  i=$((i + 1))
done | xargs -P 4 -L 1 bash -c 'one "$@"' _ >"$dir/results.txt"

total=$(wc -l <"$dir/results.txt")
rendered=$(grep -c "^rendered" "$dir/results.txt")
refused=$(grep -c "^refused" "$dir/results.txt")
fail=0
if grep "^FAIL" "$dir/results.txt"; then fail=1; fi
# The trace's own views exist for every combination; every other view renders somewhere.
if grep -E "^refused .* (none|traversal-steps|warp-efficiency)$" "$dir/results.txt"; then
  echo "FAIL: a view every combination has was refused"; fail=1
fi
for h in $heatmaps; do
  grep -q "^rendered .* $h$" "$dir/results.txt" || { echo "FAIL: heatmap $h rendered nowhere"; fail=1; }
done
want=$(( $(wc -w <<<"$strategies") * $(wc -w <<<"$heatmaps") ))
[ "$total" -eq "$want" ] || { echo "FAIL: $total results for $want combinations"; fail=1; }
# Every strategy and every heatmap met every kernel-and-sort (the pairs' design needs 4 of each).
for ks in "${kernel_sorts[@]}"; do
  k=${ks%%:*} so=${ks##*:}
  for st in $strategies; do
    grep -qE "^(rendered|refused) $k $so $st " "$dir/results.txt" || { echo "FAIL: $st never ran with $k $so"; fail=1; }
  done
  for h in $heatmaps; do
    grep -qE "^(rendered|refused) $k $so [a-z-]+ $h$" "$dir/results.txt" || { echo "FAIL: heatmap $h never ran with $k $so"; fail=1; }
  done
done
echo "$total combinations: $rendered rendered, $refused refused with a reason"
exit $fail
