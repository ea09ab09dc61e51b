"""project_check.py: what `facet info --json` says of a project, against
an independent reading of its files.

    project_check.py INFO.json FILE.obj...

Per file, Python reads the OBJ by hand (v, vt, f, o, g; polygons as fans)
and Debian's tinyobjloader reads it too; the surfaces are the file's
objects, else its groups, else the file (project.h). Checks, per surface:
its name and order, its triangle count (both readers) and its area
(triangle areas summed by brute force, 1e-9 relative); then the totals.
Prints "ok - ..." / "not ok - ..." lines; exits 1 on any mismatch.
"""
import json
import math
import os
import sys

import tinyobjloader


def brute_force(path):
    """[(name, triangles, area)] in order of first statement."""
    v, surfaces, order = [], {}, []
    has_o = has_g = False
    with open(path) as f:
        lines = f.read().splitlines()
    for line in lines:
        w = line.split()
        if w and w[0] == "o" and len(w) > 1:
            has_o = True
        if w and w[0] == "g" and len(w) > 1:
            has_g = True
    key = "o" if has_o else ("g" if has_g else None)
    stem = os.path.basename(path)
    if stem.endswith(".obj"):
        stem = stem[:-4]
    current = stem if key is None else ""
    for line in lines:
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            v.append(tuple(float(x) for x in w[1:4]))
        elif w[0] == key:
            current = " ".join(w[1:])
            if current not in surfaces:
                surfaces[current] = [0, 0.0]
                order.append(current)
        elif w[0] == "f":
            idx = [int(c.split("/")[0]) for c in w[1:]]
            idx = [i - 1 if i > 0 else len(v) + i for i in idx]
            if current not in surfaces:
                surfaces[current] = [0, 0.0]
                order.append(current)
            for k in range(1, len(idx) - 1):
                a, b, c = v[idx[0]], v[idx[k]], v[idx[k + 1]]
                e1 = [b[i] - a[i] for i in range(3)]
                e2 = [c[i] - a[i] for i in range(3)]
                cr = [e1[1] * e2[2] - e1[2] * e2[1],
                      e1[2] * e2[0] - e1[0] * e2[2],
                      e1[0] * e2[1] - e1[1] * e2[0]]
                surfaces[current][0] += 1
                surfaces[current][1] += 0.5 * math.sqrt(sum(x * x for x in cr))
    return [(n, surfaces[n][0], surfaces[n][1]) for n in order
            if surfaces[n][0] > 0]


def tiny(path):
    """{name: triangles} as tinyobjloader groups the faces into shapes."""
    reader = tinyobjloader.ObjReader()
    config = tinyobjloader.ObjReaderConfig()
    config.triangulate = True
    if not reader.ParseFromFile(path, config):
        raise RuntimeError(reader.Error().strip())
    counts = {}
    for s in reader.GetShapes():
        counts[s.name] = counts.get(s.name, 0) + len(s.mesh.indices) // 3
    return counts


def main():
    info = json.load(open(sys.argv[1]))
    files = sys.argv[2:]
    want = []
    for path in files:
        want += [(n, t, a, path) for n, t, a in brute_force(path)]
    got = info["surfaces"]
    bad = 0

    def check(ok, name):
        nonlocal bad
        print(("ok - " if ok else "not ok - ") + name)
        bad += not ok

    check([s["name"] for s in got] == [w[0] for w in want],
          "surface names and order (%d surfaces)" % len(want))
    check(all(s["triangles"] == w[1] for s, w in zip(got, want)),
          "triangles per surface, against a Python count")
    worst = max(abs(s["area"] - w[2]) / w[2] for s, w in zip(got, want))
    check(worst < 1e-9, "area per surface, against a brute-force sum "
          "(worst %.2g relative)" % worst)
    check(info["triangles"] == sum(w[1] for w in want), "total triangles")
    total = sum(w[2] for w in want)
    check(abs(info["area"] - total) < 1e-9 * total, "total area")
    agree = True
    for path in files:
        counts = tiny(path)
        mine = {s["name"]: s["triangles"] for s in got if s["file"] == path}
        if len(mine) > 1 and counts != mine:
            agree = False
            print("  tinyobjloader %s: %s" % (path, sorted(counts.items())[:5]))
    check(agree, "names and triangles per surface, against tinyobjloader")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
