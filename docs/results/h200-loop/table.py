#!/usr/bin/env python3
"""The bounce loop's table (README.md) from run.sh's results.csv: ms a frame, medians over the rounds."""
import csv
import statistics
import sys
from collections import defaultdict

rows = list(csv.DictReader(open(sys.argv[1] if len(sys.argv) > 1 else 'results.csv')))
cells = defaultdict(list)
for x in rows:
    case = (x['scene'].split('/')[-1], x['view'], f"{x['width']}x{x['height']}")
    cells[case + (x['kernel'], x['strategy'], x['trace_shade'])].append(float(x['frame_ms_median']))
cases = sorted({k[:3] for k in cells}, key=lambda k: (k[0], k[1], int(k[2].split('x')[0])))
shades = tuple(t for t in ('split', 'fused', 'loop') if any(k[5] == t for k in cells))  # those the bench ran
print(f"| scene | view | size | megakernel | unsorted {' / '.join(shades)} | two-point {' / '.join(shades)} "
      '| best unsorted / megakernel | best wavefront vs megakernel | best sorted vs best unsorted |')
print('|---|---|---|---|---|---|---|---|---|')
for c in cases:
    med = lambda k, s, t: statistics.median(cells[c + (k, s, t)])
    mk = med('megakernel', 'none', 'split')
    unsorted = [med('wavefront', 'none', t) for t in shades]
    sorted_ = [med('wavefront', 'two-point', t) for t in shades]
    best_u, best_s = min(unsorted), min(sorted_)
    best_w = min(best_u, best_s)
    print(f"| {c[0].replace('.gltf', '')} | {c[1]} | {c[2]} | {mk:.3f} | "
          f"{' / '.join(f'{v:.3f}' for v in unsorted)} | {' / '.join(f'{v:.3f}' for v in sorted_)} | "
          f"{best_u / mk:.3f} | {(best_w / mk - 1) * 100:+.1f}% | {best_u / best_s:.3f}x |")
