# Writes fastc_checked.c: fastc.c with every index into rec, ir, cellHead, heap and qhead checked
# against its array's length, as the JVM checks every array access (abort() where Java would throw).
# usage: python3 make_checked.py  (in this folder), then
#        gcc -O3 -march=native -ffp-contract=off -o fastc_checked fastc_checked.c -lm
import re

def checked(source, name, length):
    out, i = [], 0
    pattern = re.compile(r'\b' + name + r'\[')
    while True:
        m = pattern.search(source, i)
        if not m:
            out.append(source[i:])
            return ''.join(out)
        out.append(source[i:m.start()])
        j, depth = m.end(), 1
        while depth:
            depth += {'[': 1, ']': -1}.get(source[j], 0)
            j += 1
        out.append('%s[CK(%s,%s)]' % (name, source[m.end():j - 1], length))
        i = j

s = open('fastc.c').read()
for name, length in [('rec', 'nrec'), ('ir', 'nir'), ('cellHead', 'ncell'), ('heap', 'heapCap'), ('qhead', 'buckets')]:
    s = checked(s, name, length)
s = s.replace('#include <time.h>', '''#include <time.h>
static long nrec, nir, ncell;
#define CK(i, n) ({ long _i = (i); if ((unsigned long) _i >= (unsigned long) (n)) abort(); _i; })''')
s = s.replace('    rec = malloc(sizeof(double) * (size_t) n * ST);',
              '    rec = malloc(sizeof(double) * (size_t) n * ST);\n'
              '    nrec = (long) n * ST; nir = (long) n * IS; ncell = (long) cols * rows;')
open('fastc_checked.c', 'w').write(s)
