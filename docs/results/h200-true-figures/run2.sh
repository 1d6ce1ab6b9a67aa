#!/usr/bin/env bash
# Issue 34 on the H200, second device call, after the bench's rounds and auto's settling (branch bench-rounds)
# were merged: the studies the issue names at 8.4M paths (Sponza for the unseen BreakfastRoom, which is not
# here; the temple's hall), --quick with its 3 rounds; then the detailed render of run.sh again for average,
# whose distinct-key pass now reads each bit before its atomic. Carry as run.sh says.
tar -xJf .dev/bins.tar.xz
for f in .dev/carry/gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
B=build-device/raylab
S=.dev/sponza/Sponza.gltf
( time timeout 300 $B study $S@CameraMain --quick --out-dir /tmp/study-sponza ) > $OUT/study-sponza.log 2>&1
( time timeout 150 $B study temple@hall --quick --out-dir /tmp/study-hall ) > $OUT/study-hall.log 2>&1
$B render --scene $S --view CameraMain --size 4096x2048 --bounces 4 --frames 40 --strategy average \
  --stats /tmp/average-every2.json --detail-every 2 --out /tmp/x.png > /dev/null 2>&1
tar -cJf $OUT/studies.tar.xz -C /tmp study-sponza study-hall average-every2.json
echo done
