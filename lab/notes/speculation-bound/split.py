# usage: jfr print --events jdk.ExecutionSample run.jfr > samples.txt; python3 split.py samples.txt
import sys,re,collections
# per sample: top frame method; keep samples whose stack contains FastRun
samples=[];cur=None
for line in open(sys.argv[1]):
    if line.startswith('jdk.ExecutionSample'):
        if cur: samples.append(cur)
        cur=[];continue
    m=re.match(r'\s+([\w.$]+(?:\.[\w$<>]+))\(.*?\)\s+line:\s*(\d+)',line)
    if m and cur is not None: cur.append(m.group(1))
if cur: samples.append(cur)
fast=[s for s in samples if any('FastRun' in f for f in s)]
print('samples',len(samples),'in FastRun',len(fast))
# classify by the outermost interesting frame under FastRun
cls=collections.Counter()
for s in fast:
    top=s[0]
    if any(x in ' '.join(s) for x in ['predictFull','predictAfterCrossing']): c='predict (parallel in K&H)'
    elif 'CalendarQueue' in top: c='queue'
    elif 'DiscTable' in ' '.join(s) or 'FastRun.run' == s[-1] and len(s)<3: c='setup'
    else: c='other: '+top.split('.')[-2]+'.'+top.split('.')[-1]
    # queue calls made from within collide (remove/insert) counted as queue
    cls[c]+=1
for k,v in cls.most_common(): print('%5.1f%% %s'%(100*v/len(fast),k))
