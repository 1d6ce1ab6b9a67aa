#!/usr/bin/env bash
# The key-bits sweep of this folder (issue 36): the first bounce's virtual warp efficiency when the bounce rays are
# sorted by a key's top bits (tracebench --sort-rays S --sort-bits N), on lavapipe. Steps and warp efficiency do not
# depend on the device; the times in the CSVs are lavapipe's and mean nothing here. Run from the repository root.
set -eu
S=../shared/scenes/Sponza/Sponza.gltf
tb() { ./build/raylab tracebench --size 2048x1024 --repeat 1 --warmup 0 --check 256 --csv /tmp/kb.csv "$@" >/dev/null; }
append() { [ -s "$1" ] || head -1 /tmp/kb.csv > "$1"; tail -n +2 /tmp/kb.csv >> "$1"; }
out=docs/results/lavapipe-key-bits
for c in "temple hall" "temple openings" "$S CameraMain" "temple-detail:1000000 hall" "clutter:1000000 overview"; do
  set -- $c
  bits="0 20 16 15 12 8"; [ "$1" = clutter:1000000 ] && bits="0 16 8"
  for b in $bits; do
    tb --scene "$1" --view "$2" --kinds bounce,bounce-sorted --sort-rays two-point --sort-bits $b; append $out/sort-bits.csv
  done
done
for c in "temple hall" "$S CameraMain"; do
  set -- $c
  for k in fixed origin direction origin-direction two-point oracle; do
    for b in 0 16 8; do
      tb --scene "$1" --view "$2" --kinds bounce-sorted --sort-rays $k --sort-bits $b; append $out/strategies.csv
    done
  done
done
# Later bounces (--bounce-depth D: the rays leave the hits of D - 1 earlier bounces, traced by tracebench), by pixel
# (depth.csv) and, for the combined keys, in the order the earlier bounces' sorts left them (--sort-earlier,
# earlier.csv).
for c in "temple hall" "$S CameraMain"; do
  set -- $c
  for d in 2 3; do
    ks="fixed origin direction origin-direction two-point oracle"; [ $d = 3 ] && ks="origin origin-direction two-point"
    kinds=bounce,bounce-sorted
    for k in $ks; do
      tb --scene "$1" --view "$2" --bounce-depth $d --kinds $kinds --sort-rays $k; append $out/depth.csv
      kinds=bounce-sorted
      case $k in two-point|origin-direction)
        tb --scene "$1" --view "$2" --bounce-depth $d --sort-earlier --kinds bounce,bounce-sorted --sort-rays $k
        append $out/earlier.csv;;
      esac
    done
  done
done
# The ranked-cells prototype (not in main): git apply $out/ranked-cells.patch; build; then
# RL_PROTO_RANK=1|2|3 ./build/raylab tracebench --scene temple --view hall --size 2048x1024 --kinds bounce-sorted \
#   --sort-rays two-point --sort-bits 0|16 --repeat 1 --warmup 0 --check 64   (the same with Sponza CameraMain)
