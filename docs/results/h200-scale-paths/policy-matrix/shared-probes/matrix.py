import csv, sys
def key(r): return (r["scene"].strip('"').split('/')[-1], r["width"]+"x"+r["height"], r["bounces"], r["trace_shade"])
rows = []
for fn in sys.argv[1:]:
    rows += list(csv.DictReader(open(fn)))
cells = {}
for r in rows:
    if r["kernel"] != "wavefront": continue
    k = key(r); f = float(r["frame_ms_median"])
    kind = "never" if r["strategy"] == "none" else r["sort_policy"]
    cells.setdefault(k, {})[kind] = f
ok = 0; miss = []
for k in sorted(cells):
    c = cells[k]
    if not all(x in c for x in ("never", "always", "auto")): print("incomplete", k, c); continue
    best = min(c["never"], c["always"]); r = c["auto"] / best
    good = r <= 1.02 or c["auto"] - best <= 0.05
    ok += good
    if not good: miss.append((k, c, r))
print(f"{ok} of {len(cells)} cells within 2% or 0.05 ms")
for k, c, r in miss: print("MISS", k, {x: round(v, 3) for x, v in c.items()}, round(r, 3))
