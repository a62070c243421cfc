import sys, statistics as st, collections, re
before={}
for line in open('before.txt'):
    p=line.split()
    if len(p)<3 or line.startswith('#'): continue
    s,e=p[0],p[1]
    if 'TIMEOUT' in line: before[(s,e)]={'wall':'>300 (timeout)'}; continue
    d=dict(x.split('=') for x in p[2:]); before[(s,e)]=d
after=collections.defaultdict(list)
for f in sys.argv[1:]:
    for line in open(f):
        p=line.split()
        if len(p)<14: continue
        after[(p[1],p[2])].append(p)
scenes=sorted({k[0] for k in after})
print("| scene | `fast` wall s | `slabs` before: wall s | rollbacks | undone | `slabs` after: wall s | ratio to `fast` | CPU s `fast` / `slabs` | windows | rollbacks | undone | merged events / all |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for s in scenes:
    f=after[(s,'fast')]; sl=after[(s,'slabs')]
    fw=st.median(float(r[4]) for r in f); sw=st.median(float(r[4]) for r in sl)
    fc=st.median(float(r[13]) for r in f); sc=st.median(float(r[13]) for r in sl)
    b=before.get((s,'slabs'),{}); bf=before.get((s,'fast'),{})
    x=sl[-1]
    print(f"| {s} | {fw:.3f} | {b.get('wall','?')} | {b.get('rollbacks','?')} | {b.get('undone','?')} | {sw:.3f} | {sw/fw:.2f} | {fc:.2f} / {sc:.2f} | {x[7]} | {x[8]} | {x[9]} | {x[11]} / {x[6]} |")
