#!/usr/bin/env python3
"""The relaxed shell of `shellpack shell --walls GAP` (plates at z = +-gap/2 about the mesh's
centre, the origin for an rndmesh sphere) as a packing OFF that `shellpack analyze` reads:
walls at z = 0 and the gap (z not periodic), x and y periodic in a 10 x 10 box, the material
and the final turgor as key lines.

    plates_to_packing.py SHELL.off SHELL.csv OUT.off [KEY=VALUE ...]
"""
import csv
import sys

src, table, out = sys.argv[1:4]
keys = sys.argv[4:]
lines = [l for l in open(src) if l.strip() and not l.startswith('#')]
nv, nf = map(int, lines[1].split()[:2])
last = list(csv.DictReader(l for l in open(table) if not l.startswith('#')))[-1]
gap = float(last['gap_u'])
with open(out, 'w') as o:
    o.write('OFF\n# box 10 10 %r\n# periodic 1 1 0\n# shells 1 %d\n' % (gap, nv))
    for k in keys + ['turgor=%s' % last['turgor_P']]:
        o.write('# %s\n' % k)
    o.write('%d %d 0\n' % (nv, nf))
    for l in lines[2:2 + nv]:
        x, y, z = map(float, l.split())
        o.write('%r %r %r\n' % (x + 5, y + 5, z + gap / 2))
    o.writelines(lines[2 + nv:2 + nv + nf])
