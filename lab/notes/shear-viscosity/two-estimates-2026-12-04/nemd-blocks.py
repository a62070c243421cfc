# η* = −⟨Pxy⟩/γ̇ (γ̇ = 0.05) of the sheared runs nemd-scenes.py writes: the first tenth dropped, time-weighted means of 20 blocks
import csv,math,sys
for phi in sys.argv[1:]:
    rows=[tuple(map(float,(r['t0'],r['t1'],r['Pxy']))) for r in csv.DictReader(open(f'nemd-report-{phi}/stress.csv'))]
    skip=len(rows)//10; rows=rows[skip:]
    B=20; n=len(rows); means=[]
    for b in range(B):
        part=rows[b*n//B:(b+1)*n//B]
        w=sum(t1-t0 for t0,t1,_ in part); means.append(-sum(p*(t1-t0) for t0,t1,p in part)/w/0.05)
    m=sum(means)/B; se=math.sqrt(sum((x-m)**2 for x in means)/(B-1)/B)
    print(f"phi {phi}: intervals {n} after skipping {skip} (t from {rows[0][0]:.0f} to {rows[-1][1]:.0f}), eta* = {m:.4f} +- {se:.4f} ({B} blocks)")
