#!/usr/bin/env bash
# One device session, first command (issue 22): the thesis's table and quick studies of Sponza and the hall.
# The GPU machine has no matplotlib: the reports are made afterwards, here, from the folders (see README.md).
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
tar -xJf .dev/bins.tar.xz && xz -dkf build-device/lib/*.xz
B=build-device
nvidia-smi --query-gpu=name,driver_version --format=csv > $OUT/gpu.txt 2>&1
( time timeout 200 $B/raylab study temple --thesis --out-dir /tmp/thesis ) > $OUT/thesis.log 2>&1
( time timeout 190 $B/raylab study .dev/sponza/Sponza.gltf@CameraMain --quick --out-dir /tmp/study-sponza ) > $OUT/study-sponza.log 2>&1
( time timeout 150 $B/raylab study temple@hall --quick --out-dir /tmp/study-hall ) > $OUT/study-hall.log 2>&1
tar -cJf $OUT/studies.tar.xz -C /tmp thesis study-sponza study-hall
echo done
