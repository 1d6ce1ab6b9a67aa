import csv,sys
for p in sys.argv[1:]:
    rs=list(csv.DictReader(open(p)))
    t={}
    for r in rs:
        sc=r['scene'].split('/')[-1].replace('.gltf','')
        meth='megakernel' if r['kernel']=='megakernel' else ('unsorted' if r['strategy']=='none' else 'two-point')
        t[(sc,r['bvh'],meth)]=float(r['frame_ms_median'])
    print(p)
    for sc in ['Sponza','temple']:
        for meth in ['megakernel','unsorted','two-point']:
            s=t.get((sc,'sbvh',meth))
            print(f"  {sc} {meth}: sbvh {s:.0f} ms; binary/sbvh {t[(sc,'binary',meth)]/s:.2f}x, wide/sbvh {t[(sc,'wide',meth)]/s:.2f}x")
