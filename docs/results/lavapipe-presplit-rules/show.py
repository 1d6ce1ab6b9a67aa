import csv,sys,collections
rows=list(csv.DictReader(open(sys.argv[1])))
base={};tab=collections.defaultdict(dict)
for r in rows:
    k=(r['case'],r['kind'])
    cost=float(r['mean_steps'])/float(r['warp_efficiency'])
    if r['presplit']=='0': base[k]=cost
    else: tab[(r['case'],r['presplit'],r['kind'])][r['mode']]=100*(cost/base[k]-1)
modes=sorted({m for v in tab.values() for m in v})
print('case F kind '+' '.join(modes))
for k,v in tab.items(): print(*k, ' '.join('%6.1f'%v[m] if m in v else '     -' for m in modes))
