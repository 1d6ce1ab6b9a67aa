#!/usr/bin/env bash
# Builds the fuzz build (RAYLAB_FUZZ=ON with clang: libFuzzer + ASan + UBSan over the parsers only) and runs
# each target for a bounded time, seeded from the project's inputs. Prints per target the executions, the
# coverage reached (libFuzzer's final cov/ft) and any finding; exits non-zero if any target found one.
#
#   bash tests/fuzz/run_fuzzers.sh [TARGET...]     targets: gltf sidecar ui_script bench_sweep settings_ini
#
#   RAYLAB_FUZZ_SECONDS   seconds per target (default 60)
#   RAYLAB_FUZZ_BUILD     build folder (default build-fuzz)
#   RAYLAB_FUZZ_WORK      where corpora and findings go (default $RAYLAB_FUZZ_BUILD/runs); a finding is
#                         kept as WORK/TARGET/crash-* (or leak-, timeout-, oom-): copy it to
#                         tests/fuzz/regressions/TARGET/ once fixed, and tests/cpu replays it.
#   RAYLAB_SHARED_SCENES  glTF seeds besides tests/data (default ../shared/scenes, read in place)
#   RAYLAB_FUZZ_JOBS      build jobs (default nproc)
set -uo pipefail
cd "$(dirname "$0")/../.."
root=$PWD
seconds="${RAYLAB_FUZZ_SECONDS:-60}"
build="${RAYLAB_FUZZ_BUILD:-build-fuzz}"
work="${RAYLAB_FUZZ_WORK:-$build/runs}"
shared="${RAYLAB_SHARED_SCENES:-$root/../shared/scenes}"
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(gltf sidecar ui_script bench_sweep settings_ini)

# Debian 12 has clang 14, Debian 13 clang 19: the unversioned names (packages clang, libclang-rt-dev).
cc="${CC:-clang}" cxx="${CXX:-clang++}"
command -v "$cxx" >/dev/null || { echo "run_fuzzers: $cxx not found (apt-get install clang libclang-rt-dev)"; exit 1; }
start=$SECONDS
# Debug: keeps the asserts (third-party code asserts too); the fuzz flags set -O1 themselves.
CC=$cc CXX=$cxx cmake -S . -B "$build" -G Ninja -DRAYLAB_FUZZ=ON -DCMAKE_BUILD_TYPE=Debug >/dev/null || exit 1
cmake --build "$build" -j "${RAYLAB_FUZZ_JOBS:-$(nproc)}" >"$build/build.log" 2>&1 || {
  tail -30 "$build/build.log"; echo "run_fuzzers: build failed"; exit 1; }
echo "run_fuzzers: built in $((SECONDS - start)) s"

# Seed folders of each target, read in place (libFuzzer adds what it finds to the first, the work corpus).
seeds_of() {
  case "$1" in
    gltf) echo "$root/tests/data $root/tests/data/malformed $root/tests/data/modes"
          [ -d "$shared" ] && find "$shared" -mindepth 1 -maxdepth 1 -type d | tr '\n' ' ' ;;
    sidecar) echo "$root/tests/fuzz/seeds/sidecar" ;;
    ui_script) echo "$work/ui_script/seeds" ;;  # made below from tests/data
    bench_sweep) echo "$root/tests/fuzz/seeds/bench_sweep" ;;
    settings_ini) echo "$root/tests/fuzz/seeds/settings_ini $root/tests/fuzz/seeds/sidecar" ;;
  esac
}
dict_of() { case "$1" in ui_script | bench_sweep | settings_ini | gltf) echo "$1" ;; *) echo json ;; esac; }
# Inputs as large as a scene file would be pointless to mutate; a glTF of a few KB reaches every check.
max_len_of() { case "$1" in gltf) echo 16384 ;; *) echo 4096 ;; esac; }

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:allocator_may_return_null=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
found=0
summary=()
for t in "${targets[@]}"; do
  bin="$build/tests/fuzz/fuzz_$t"
  [ -x "$bin" ] || { echo "run_fuzzers: no target '$t'"; exit 1; }
  out="$work/$t"
  mkdir -p "$out/corpus"
  # The UI scripts are the tests' own (tests/data/ui_script_*.txt), gathered into a folder for libFuzzer.
  if [ "$t" = ui_script ]; then
    mkdir -p "$out/seeds"
    cp "$root"/tests/data/ui_script_*.txt "$out/seeds/"
  fi
  # shellcheck disable=SC2046
  "$bin" "$out/corpus" $(seeds_of "$t") -dict="$root/tests/fuzz/dict/$(dict_of "$t").dict" \
    -max_total_time="$seconds" -max_len="$(max_len_of "$t")" -timeout=5 -rss_limit_mb=2048 -malloc_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$out/" -close_fd_mask=3 >"$out/log.txt" 2>&1
  rc=$?
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$out/log.txt" | grep -o '[0-9]*$' | tail -1)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$out/log.txt" | grep -o '[0-9]*$' | tail -1)
  last=$(grep -E '^#[0-9]+' "$out/log.txt" | grep -o 'cov: [0-9]* ft: [0-9]*' | tail -1)
  artifacts=$(find "$out" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | sort)
  line="$t: ${execs:-?} executions, ${rate:-?} exec/s, ${last:-cov/ft unknown}, corpus $(find "$out/corpus" -type f | wc -l) files"
  if [ $rc -ne 0 ] || [ -n "$artifacts" ]; then
    found=1
    line="$line, FINDING (libFuzzer exit $rc)"
    grep -E 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error|terminate called|SUMMARY' "$out/log.txt" | head -5
    for a in $artifacts; do line="$line"$'\n'"    input: $a"; done
    echo "    log: $out/log.txt"
  fi
  echo "$line"
  summary+=("$line")
done
echo "run_fuzzers: ${#targets[@]} targets x ${seconds} s, $((SECONDS - start)) s in all"
for l in "${summary[@]}"; do echo "  $l"; done
exit $found
