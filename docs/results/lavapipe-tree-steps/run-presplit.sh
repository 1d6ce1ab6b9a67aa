#!/usr/bin/env bash
# Early split clipping before Embree's build (the prototype presplit.patch: not in main): the largest references cut
# in two at their box's middle, a budget of RL_PRESPLIT x the triangle count, before rtcBuildBVH (which then adds
# its own spatial splits); duplicates of one triangle in a leaf are dropped. Counted as run-harness.sh counts, over
# tracebench --export's rays: Sponza at 2048x1024, the temple's hall and temple-detail:1000000 at 1024x512.
# RL_PRESPLIT_AREA=1 orders the references by box area less the triangle's share (RL_PRESPLIT_K times it); without
# it, by the area the cut saves. RL_PRESPLIT_ROOT=f: only while the largest reference's box is over f of the scene
# box's. Run from the repository root after run-harness.sh (it reuses its folder).
set -eu
D=docs/results/lavapipe-tree-steps
T=${TMPDIR:-/tmp}/tree-steps
for c in "temple hall" "temple-detail:1000000 hall"; do
  set -- $c
  [ -d $T/${1%%:*}-$2 ] || ./build/raylab tracebench --scene $1 --view $2 --size 1024x512 --kinds camera,bounce,shadow \
    --repeat 1 --warmup 0 --check 0 --export $T/${1%%:*}-$2 > /dev/null
done
git apply --check $D/presplit.patch
cp renderer/bvh/bvh.cpp $T/bvh_pre.cpp && (cd $T && patch -s bvh_pre.cpp < "$OLDPWD/$D/presplit.patch")
g++ -O2 -std=c++20 -DGLM_FORCE_RADIANS -DGLM_FORCE_DEPTH_ZERO_TO_ONE -I . -I build/generated $D/raylab_steps.cpp \
  $T/bvh_pre.cpp renderer/bvh/bvh_reinsert.cpp -o $T/raylab_pre -Wl,--allow-multiple-definition \
  build/libraylab_core.a -lembree3 -ltbb -lvulkan -ltinygltf -lstb -lpthread
K="camera bounce shadow"
{
  for sc in sponza temple-hall temple-detail-hall; do
    for p in 0 0.0001 0.001 0.01; do
      echo "# $sc, presplit by area, $p"; RL_PRESPLIT_AREA=1 RL_PRESPLIT=$p $T/raylab_pre $T/$sc $K
    done
    echo "# $sc, presplit by the area saved, 0.001"; RL_PRESPLIT=0.001 $T/raylab_pre $T/$sc $K
    echo "# $sc, presplit by area less 2.5x the triangle's, 0.001"; RL_PRESPLIT_K=2.5 RL_PRESPLIT_AREA=1 RL_PRESPLIT=0.001 $T/raylab_pre $T/$sc $K
    for f in 0.05 0.01; do
      echo "# $sc, presplit by area while a box is over $f of the scene box's, 0.01"
      RL_PRESPLIT_ROOT=$f RL_PRESPLIT_AREA=1 RL_PRESPLIT=0.01 $T/raylab_pre $T/$sc $K
    done
  done
} | tee $D/presplit.txt
