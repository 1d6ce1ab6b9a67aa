#!/usr/bin/env bash
# Device session (issue 21): what sorts the cluttered room best at 8.4M paths: strategies (oracle = the bound),
# both BVHs, grids and key bits, split and fused.
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
R=build-device/raylab
C="--cases clutter:1000000@overview --size 4096x2048 --bounces 4 --timed-frames 6 --warmup 4 --reference-spp 1 --no-charts"
( time timeout 200 $R bench $C --strategies dead-last,fixed,origin-direction,two-point,gaussian,oracle --bvhs binary,wide \
   --trace-shades split --sort-policies always --out-dir /tmp/a ) > $OUT/a.log 2>&1
( time timeout 150 $R bench $C --strategies two-point --bvhs wide --trace-shades split,fused --grids auto,32,128,32x16x32 \
   --sort-policies always --no-detail --out-dir /tmp/b ) > $OUT/b.log 2>&1
( time timeout 120 $R bench $C --strategies two-point,fixed --bvhs wide --trace-shades split --sort-bits-list 0,16 --fusions none,gather \
   --sort-policies always --no-detail --out-dir /tmp/c ) > $OUT/c.log 2>&1
python3 - /tmp/a /tmp/b /tmp/c > $OUT/room.csv <<'PY'
import csv, sys
out = None
for d in sys.argv[1:]:
    try: rows = list(csv.DictReader(open(d + '/results.csv')))
    except OSError: continue
    for r in rows:
        r = {'sweep': d[-1], **r}
        if out is None:
            out = csv.DictWriter(sys.stdout, fieldnames=list(r.keys()), extrasaction='ignore'); out.writeheader()
        out.writerow(r)
PY
echo done
