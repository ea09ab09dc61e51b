#!/usr/bin/env python3
"""obj_scaled.py FACTOR SRC DST: writes SRC with every vertex scaled by
FACTOR to DST (the rest as written), and prints the diagonal of SRC's
bounding box, from its own coordinates: what a file read in the wrong
units measures is said from it (in metres, a roof drawn in mm and read as
m is that many km across)."""
import math
import sys

factor, src, dst = float(sys.argv[1]), sys.argv[2], sys.argv[3]
lo, hi = [math.inf] * 3, [-math.inf] * 3
with open(src) as inp, open(dst, "w") as out:
    for line in inp:
        if line.startswith("v "):
            p = [float(x) for x in line.split()[1:4]]
            for k in range(3):
                lo[k], hi[k] = min(lo[k], p[k]), max(hi[k], p[k])
            line = "v %r %r %r\n" % tuple(x * factor for x in p)
        out.write(line)
print("%.1f" % math.dist(lo, hi))
