#!/usr/bin/env python3
"""Writes the buildings of seams.sh from their formulas, as OBJ files of
one object per face (v in metres, vt the face's own coordinates in metres,
each cell of its lattice two triangles):

  hinge.obj      A: the plane z = 0, x from -4 to 0, y from 0 to 3;
                 B: the plane through the line x = z = 0 bent up by 30
                 degrees, (s cos 30, y, s sin 30) for s from 0 to 4: two
                 faces meeting along a seam of 3 m at a crease of 30 deg;
  hinge_apart.obj  the same with B moved 2 mm along x (no seam within 1 mm,
                 one within 3 mm);
  box.obj        a box corner: the floor z = 0 and the walls x = 0 and
                 y = 0, each 2 m x 2 m: three seams of 2 m at 90 degrees;
  thirds.obj     a cylinder of radius 3 m and height 4 m about z cut along
                 three rulings (at 0, 120 and 240 degrees) into three
                 faces, each of 8 facets of 15 degrees."""
import math
import sys


def face(name, point, ns, nt, s_len, t_len, first):
    """Lines of object name: point(s, t) over an ns x nt lattice of
    s in [0, 1], t in [0, 1]; vt (s s_len, t t_len); vertices numbered
    from first."""
    out = ["o %s" % name]
    for j in range(nt + 1):
        for i in range(ns + 1):
            s, t = i / ns, j / nt
            x, y, z = point(s, t)
            out.append("v %.17g %.17g %.17g" % (x, y, z))
            out.append("vt %.17g %.17g" % (s * s_len, t * t_len))
    n = ns + 1
    for j in range(nt):
        for i in range(ns):
            a = first + j * n + i
            b, c, d = a + 1, a + 1 + n, a + n
            out.append("f %d/%d %d/%d %d/%d" % (a, a, b, b, c, c))
            out.append("f %d/%d %d/%d %d/%d" % (a, a, c, c, d, d))
    return out, (ns + 1) * (nt + 1)


def write(path, faces):
    lines, first = [], 1
    for f in faces:
        out, count = face(*f, first)
        lines += out
        first += count
    with open(path, "w") as fh:
        fh.write("\n".join(lines) + "\n")


def main(folder):
    c, s = math.cos(math.pi / 6), math.sin(math.pi / 6)

    def hinge(apart):
        return [("A", lambda u, v: (-4 + 4 * u, 3 * v, 0), 16, 12, 4, 3),
                ("B", lambda u, v: (apart + 4 * u * c, 3 * v, 4 * u * s),
                 16, 12, 4, 3)]

    write(folder + "/hinge.obj", hinge(0))
    write(folder + "/hinge_apart.obj", hinge(0.002))
    write(folder + "/box.obj", [
        ("floor", lambda u, v: (2 * u, 2 * v, 0), 8, 8, 2, 2),
        ("wall_x", lambda u, v: (0, 2 * u, 2 * v), 8, 8, 2, 2),
        ("wall_y", lambda u, v: (2 * u, 0, 2 * v), 8, 8, 2, 2)])
    r, h = 3.0, 4.0

    def third(k):
        start = 2 * math.pi * k / 3
        return lambda u, v: (r * math.cos(start + u * 2 * math.pi / 3),
                             r * math.sin(start + u * 2 * math.pi / 3),
                             h * v)

    arc = r * 2 * math.pi / 3
    write(folder + "/thirds.obj",
          [("third%d" % k, third(k), 8, 2, arc, h) for k in range(3)])


main(sys.argv[1])
