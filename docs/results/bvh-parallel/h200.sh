#!/bin/bash
# The script of h200-run1.log, run on the H200 host (16 cores) from a folder holding raylab_bvh_report Release
# builds (each built as .ci/device-build builds, target raylab_bvh_report only) with Embree, TBB, tinygltf,
# libstb and the Vulkan loader in lib/ (the RPATH's $ORIGIN/lib):
#   before       2584deb (the serial phases, with --hash)
#   after        6bbb494 (primitives, flattening and collapse in parallel; plain resize)
#   after-pop    6bbb494 with the flattening's resize faulting its pages in on the threads (3b8d6ef less the
#                collapse's)
#   after-timed  6bbb494 printing the flattening's parts to stderr
cd "$(dirname "$0")"
xz -dkf lib/*.xz
echo "nproc $(nproc); $(uname -r)"; grep -E "MemTotal|MemAvailable" /proc/meminfo
s() { python3 -c "
import sys, json
for l in sys.stdin:
    r = json.loads(l)
    print('$1', r['scene'], 'prim %.0f embree %.0f flatten %.0f build %.0f (min %.0f, cpu %.0f) wide %.0f' % (r['primitives_ms_median'], r['embree_ms_median'], r['flatten_ms_median'], r['build_ms_median'], r['build_ms_min'], r['build_cpu_ms_median'], r['wide_collapse_ms_median']), r.get('hash_binary', ''), r.get('hash_wide', ''), flush=True)"; }
./after --repeats 1 temple-detail:10000000 | s warmup
for round in 1 2; do
  ./before --repeats 3 --hash temple-detail:10000000 | s "before#$round"
  ./after --repeats 3 --hash temple-detail:10000000 | s "after#$round"
  ./after-pop --repeats 3 --hash temple-detail:10000000 | s "after-pop#$round"
done
./before --repeats 3 --hash temple temple-detail:1000000 clutter:1000000 | s before
./after --repeats 3 --hash temple temple-detail:1000000 clutter:1000000 | s after
./after --repeats 3 --threads 1 --hash temple-detail:10000000 | s "after-1thread"
./after --repeats 3 --threads 4 --hash temple-detail:10000000 | s "after-4threads"
./after-timed --repeats 3 temple-detail:10000000 2>&1 | grep -v '^{'
echo done
