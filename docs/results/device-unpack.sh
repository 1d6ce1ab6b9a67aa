#!/usr/bin/env bash
# Sourced at the start of a device call by the results scripts (h200-sbvh/run*.sh and later): unpacks what
# travels packed (.ci/device-pack makes it: bash .ci/device-build; bash .ci/device-pack [NAME=BINARY...]): .dev/bins.tar.xz (build-device/raylab and any
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
# packedRaylab NAME: the raylab binary of variant NAME: build-device/raylab for `base`, else the one device-pack
# packed as NAME=BINARY (.dev/NAME/raylab).
packedRaylab() { [ "$1" = base ] && echo build-device/raylab || echo ".dev/$1/raylab"; }
# sortbenchRows NAME HEADER_PREFIX ROW_PREFIX BINARY SORTBENCH_ARGS...: one sortbench run (60 s at most) with every
# dispatch timed; its rows to $OUT/NAME.csv and $OUT/NAME-steps.csv behind ROW_PREFIX (appendRows); a run that fails
# goes to $OUT/errors.txt with its last lines, and adds no rows.
sortbenchRows() {
  local name=$1 header=$2 row=$3 bin=$4; shift 4
  rm -f /tmp/sb.csv /tmp/st.csv
  if timeout 60 $bin sortbench "$@" --csv /tmp/sb.csv --steps /tmp/st.csv > /tmp/sb.log 2>&1; then
    appendRows /tmp/sb.csv $OUT/$name.csv $header $row
    appendRows /tmp/st.csv $OUT/$name-steps.csv $header $row
  else
    echo "sortbench $row exit $?" >> $OUT/errors.txt; tail -3 /tmp/sb.log >> $OUT/errors.txt
  fi
}
# benchBinaries CSV CASES SIZES TIMEOUT NAME=BINARY...: the frame bench of each binary at 4 bounces, two-point keys,
# radix, split trace and shade, one round each, the binaries interleaved over two rounds; rows to $OUT/CSV behind
# (binary, round); a bench that fails or runs past TIMEOUT seconds goes to $OUT/errors.txt.
benchBinaries() {
  local csv=$1 cases=$2 sizes=$3 limit=$4; shift 4
  for round in 1 2; do
    for pair in "$@"; do
      local v=${pair%%=*} bin=${pair#*=}
      timeout $limit $bin bench --cases "$cases" --sizes $sizes --bounces 4 --strategies two-point --sorts radix \
        --trace-shades split --rounds 1 --no-detail --no-charts --out-dir /tmp/b-$v-$round \
        > /tmp/b-$v-$round.log 2>&1 || echo "bench $v $round exit $?" >> $OUT/errors.txt
      appendRows /tmp/b-$v-$round/results.csv $OUT/$csv binary,round $v,$round
    done
  done
}
