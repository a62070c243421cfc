import sys,statistics as st,re
for f in sys.argv[1:]:
    case=None; j=None; out={}
    for line in open(f):
        m=re.match(r'# N=(\d+) phi ([\d.]+)',line)
        if m: case=(int(m.group(1)),m.group(2)); continue
        if line.startswith('fast,'): j=float(line.split(',')[3])
        elif line.startswith('c,'):
            c=float(line.split(',')[2]); out.setdefault(case,[]).append((j,c))
    print(f)
    for case,v in out.items():
        rs=[c/j for j,c in v]
        print('  N=%d phi %s rounds %d java %.3f (%.3f-%.3f) C %.3f (%.3f-%.3f) C/java mean %.2f range %.2f-%.2f'%(case[0],case[1],len(v),st.mean(x[0] for x in v)/1e6,min(x[0] for x in v)/1e6,max(x[0] for x in v)/1e6,st.mean(x[1] for x in v)/1e6,min(x[1] for x in v)/1e6,max(x[1] for x in v)/1e6,st.mean(rs),min(rs),max(rs)))
