import sys, collections, statistics
rows=[l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]
d=collections.defaultdict(dict)
for r,code,t,cpu,c,load,wall in rows:
    d[(int(r),code)][float(t)]=(float(cpu),int(c),float(wall))
codes=sorted({k[1] for k in d})
rounds=sorted({k[0] for k in d})
rate={}
for k,v in d.items():
    if len(v)<2: continue
    (t1,a),(t2,b)=sorted(v.items())
    rate[k]=((b[1]-a[1])/(b[2]-a[2])/1e6,(b[1]-a[1])/(b[0]-a[0])/1e6)
print('round', ' '.join(f'{c}(wall,cpu)' for c in codes))
for r in rounds:
    print(r, ' '.join(f'{rate[(r,c)][0]:.3f},{rate[(r,c)][1]:.3f}' if (r,c) in rate else '-' for c in codes))
ref=sys.argv[2] if len(sys.argv)>2 else 'smallenburg'
for c in codes:
    if c==ref: continue
    w=[rate[(r,c)][0]/rate[(r,ref)][0] for r in rounds if (r,c) in rate and (r,ref) in rate]
    u=[rate[(r,c)][1]/rate[(r,ref)][1] for r in rounds if (r,c) in rate and (r,ref) in rate]
    if w: print(f'{c}/{ref}: wall median {statistics.median(w):.3f} ({min(w):.3f}-{max(w):.3f}), cpu median {statistics.median(u):.3f} ({min(u):.3f}-{max(u):.3f}), n={len(w)}')
