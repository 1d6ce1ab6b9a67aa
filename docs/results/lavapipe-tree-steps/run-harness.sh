#!/usr/bin/env bash
# The tree comparison of this folder's README: the same Sponza rays (2048x1024, tracebench --export) counted through
# tinybvh's trees and ours on the CPU. Needs tinybvh's tiny_bvh.h (1.6.7; not part of the project: fetch it to
# TINYBVH_DIR). Run from the repository root after building.
set -eu
D=docs/results/lavapipe-tree-steps
T=${TMPDIR:-/tmp}/tree-steps; mkdir -p $T
./build/raylab tracebench --scene ../shared/scenes/Sponza/Sponza.gltf --view CameraMain --size 2048x1024 --bvhs sbvh \
  --sort-rays two-point --repeat 1 --warmup 0 --check 1024 --export $T/sponza > $T/tracebench.txt
g++ -O2 -std=c++20 -I "$TINYBVH_DIR" $D/tinybvh_steps.cpp -o $T/tinybvh_steps -lpthread
sed -e 's/args.intersectionCost = spatial ? kSpatialSplitIntersectionCost : 1.0f;/args.intersectionCost = spatial ? float(std::atof(std::getenv("RL_INT_COST") ? std::getenv("RL_INT_COST") : "1.5")) : 1.0f;/' \
    -e 's/kSpatialSplitBudget \* triangles.size()/(std::getenv("RL_SPLIT_BUDGET") ? std::atof(std::getenv("RL_SPLIT_BUDGET")) : kSpatialSplitBudget) * triangles.size()/' \
    -e '1i #include <cstdlib>' renderer/bvh/bvh.cpp > $T/bvh_env.cpp
g++ -O2 -std=c++20 -DGLM_FORCE_RADIANS -DGLM_FORCE_DEPTH_ZERO_TO_ONE -I . -I build/generated $D/raylab_steps.cpp \
  $T/bvh_env.cpp renderer/bvh/bvh_reinsert.cpp -o $T/raylab_steps -Wl,--allow-multiple-definition \
  build/libraylab_core.a -lembree3 -ltbb -lvulkan -ltinygltf -lstb -lpthread
K="camera bounce shadow"
{
  echo "# tinybvh BuildHQ";                 $T/tinybvh_steps $T/sponza $K
  echo "# tinybvh Build (binned SAH)";      TB_PLAIN=1 $T/tinybvh_steps $T/sponza $K
  echo "# tinybvh Build + Optimize(25)";    TB_PLAIN=1 TB_OPT=25 $T/tinybvh_steps $T/sponza $K
  echo "# tinybvh BuildHQ + Optimize(25)";  TB_OPT=25 $T/tinybvh_steps $T/sponza $K
  echo "# raylab binary";                   $T/raylab_steps $T/sponza plain $K
  for cfg in "1 8" "0.5 8" "1.5 8" "2 8" "1 4" "1 16" "1.5 4"; do
    set -- $cfg; echo "# raylab sbvh, intersection cost $1, leaves $2"; RL_INT_COST=$1 RL_LEAF=$2 $T/raylab_steps $T/sponza $K
  done
  echo "# raylab sbvh, split budget 1.0";   RL_SPLIT_BUDGET=1.0 $T/raylab_steps $T/sponza $K
  for p in "5 0.01" "25 0.01" "25 0.05" "25 0.2"; do
    set -- $p; echo "# raylab sbvh, reinsert $1 passes of $2"; RL_REINSERT=$1 RL_FRACTION=$2 $T/raylab_steps $T/sponza $K
  done
} | tee $D/harness.txt
