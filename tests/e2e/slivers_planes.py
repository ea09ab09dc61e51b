#!/usr/bin/env python3
"""Writes the planes of slivers.sh, from their formulas (z = 0, vt = (x, y)
in metres), as OBJ files:

  l.obj      object L: a rectangle 10.3 m x 6 m and a strip 11 m x 1 m along
             its foot (the L's outline cuts the 1 m grid of its 11 m x 6 m
             box at x = 10.3 m);
  two.obj    objects L and plain, a rectangle 10 m x 6 m beside it (x from
             20 m): a building of two faces.

Each cell of a 0.25 m lattice (with lines at 10.3 m and 10.65 m) that lies
inside the outline is two triangles."""
import sys


def lattice(lo, hi, extra):
    xs = [lo + 0.25 * k for k in range(int(round((hi - lo) / 0.25)) + 1)]
    return sorted(set(round(x, 9) for x in xs + extra if lo <= x <= hi))


def plane(name, xs, ys, keep, first):
    """Lines of object name over the cells of xs x ys that keep(x, y) holds
    (x, y the cell's far corner); vertices numbered from first."""
    out = ["o %s" % name]
    for y in ys:
        for x in xs:
            out.append("v %.17g %.17g 0" % (x, y))
            out.append("vt %.17g %.17g" % (x, y))
    nx = len(xs)
    for j in range(len(ys) - 1):
        for i in range(nx - 1):
            if not keep(xs[i + 1], ys[j + 1]):
                continue
            a = first + j * nx + i
            b, c, d = a + 1, a + 1 + nx, a + nx
            out.append("f %d/%d %d/%d %d/%d" % (a, a, b, b, c, c))
            out.append("f %d/%d %d/%d %d/%d" % (a, a, c, c, d, d))
    return out, len(xs) * len(ys)


def main():
    folder = sys.argv[1]
    ys = lattice(0, 6, [])
    l_lines, count = plane("L", lattice(0, 11, [10.3, 10.65]), ys,
                           lambda x, y: x <= 10.3 + 1e-9 or y <= 1 + 1e-9, 1)
    plain, _ = plane("plain", lattice(20, 30, []), ys, lambda x, y: True,
                     1 + count)
    with open(folder + "/l.obj", "w") as f:
        f.write("\n".join(l_lines) + "\n")
    with open(folder + "/two.obj", "w") as f:
        f.write("\n".join(l_lines + plain) + "\n")


main()
