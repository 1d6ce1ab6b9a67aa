#!/usr/bin/env bash
# Run inside the Debian 13 root: bash .ci/debian13 "bash /src/raylab/.d13cmd.sh" (this file as .d13cmd.sh at the
# repository root), after a CI run of that leg built /var/raylab/build.
set -e
B=/var/raylab/build/raylab
mkdir -p /src/raylab/d13out
cd /src/raylab/d13out
$B tracebench --scene /src/shared/scenes/Sponza/Sponza.gltf --view CameraMain --size 512x256 --bvhs sbvh,binary,wide --repeat 5 --warmup 2 --csv sponza.csv 2>&1 | grep -v "^warning" > sponza.txt
$B tracebench --scene temple --view hall --size 512x256 --bvhs sbvh,binary,wide --repeat 5 --warmup 2 --csv hall.csv > hall.txt
$B tracebench --scene temple --view hall --size 512x256 --bvhs sbvh --kinds bounce,bounce-sorted --sort-rays two-point --repeat 5 --warmup 2 --csv hall-sorted.csv > hall-sorted.txt
