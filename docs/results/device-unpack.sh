#!/usr/bin/env bash
# Sourced at the start of a device call by the results scripts (h200-sbvh/run*.sh and later): unpacks what
# travels packed (h200-true-figures/run.sh says how it is made): .dev/bins.tar.xz (build-device/raylab and any
# other binaries, its tinygltf and TBB, Sponza, the Debian packages raylab needs there) and the Embree library,
# then copies the libraries beside every other raylab packed under .dev/*/ (the binaries compared with it).
tar -xJf .dev/bins.tar.xz
for f in .dev/carry/gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
for other in .dev/*/raylab; do
  [ -e "$other" ] && mkdir -p "$(dirname "$other")/lib" && cp build-device/lib/*.so* "$(dirname "$other")/lib/"
done
# What every run then uses: Sponza's path, a scratch folder and the GPU's name and driver in $OUT.
S=.dev/sponza/Sponza.gltf
mkdir -p /tmp/out
nvidia-smi --query-gpu=name,driver_version --format=csv > $OUT/gpu.txt 2>&1
# appendRows CSV OUT HEADER_PREFIX ROW_PREFIX: CSV's rows appended to OUT, each behind ROW_PREFIX; OUT starts with
# CSV's header behind HEADER_PREFIX (the columns the prefixes fill).
appendRows() {
  [ -s "$2" ] || head -1 "$1" | sed "s/^/$3,/" > "$2"
  tail -n +2 "$1" | sed "s/^/$4,/" >> "$2"
}
