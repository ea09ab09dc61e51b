#!/usr/bin/env python3
import sys
# combine.py OUT IN...: one OBJ of every input's objects, indices offset.
out = open(sys.argv[1], 'w')
nv = nvt = 0
for path in sys.argv[2:]:
    dv = dvt = 0
    for line in open(path):
        t = line.split()
        if not t or t[0].startswith('#'):
            continue
        if t[0] == 'v':
            dv += 1
        elif t[0] == 'vt':
            dvt += 1
        elif t[0] == 'f':
            refs = []
            for r in t[1:]:
                p = r.split('/')
                p[0] = str(int(p[0]) + nv)
                if len(p) > 1 and p[1]:
                    p[1] = str(int(p[1]) + nvt)
                refs.append('/'.join(p))
            line = 'f ' + ' '.join(refs) + '\n'
        out.write(line)
    nv += dv
    nvt += dvt
