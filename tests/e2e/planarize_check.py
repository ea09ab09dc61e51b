#!/usr/bin/env python3
"""The independent check of facet planarize (issue 33), in numpy.

  planarize_check.py vase PATH
      writes a surface of revolution from its formula, radius
      6 + 1.5 sin(z / 2) about z, z 0..10 m, half way round, meshed 90 x 61
      with vt (angle, z): its meridians and parallels are a conjugate net.
  planarize_check.py check SURFACE.obj PLANARIZED.obj REPORT.json
      measures every quad of the planarized OBJ (the distance between the
      lines of its diagonals, over the longer diagonal) and every corner's
      distance to the surface's triangles by brute force (the nearest point
      of each triangle: its plane inside it, else its nearest side), and
      compares them with what facet reported in JSON. Prints ok / not ok
      lines.
"""
import json
import math
import sys

import numpy as np


def not_ok(name, detail):
    print("not ok - %s" % name)
    print("  %s" % detail)


def check(name, truth, detail=""):
    if truth:
        print("ok - %s" % name)
    else:
        not_ok(name, detail)


def write_vase(path):
    ns, nt = 90, 61
    with open(path, "w") as out:
        for j in range(nt + 1):
            for i in range(ns + 1):
                s, t = i / ns, j / nt
                a, z = math.pi * s, 10 * t
                r = 6 + 1.5 * math.sin(z / 2)
                out.write("v %.17g %.17g %.17g\nvt %.17g %.17g\n"
                          % (r * math.cos(a), r * math.sin(a), z, s, t))
        for j in range(nt):
            for i in range(ns):
                a = j * (ns + 1) + i + 1
                b, c, d = a + 1, a + ns + 2, a + ns + 1
                out.write("f %d/%d %d/%d %d/%d\n" % (a, a, b, b, c, c))
                out.write("f %d/%d %d/%d %d/%d\n" % (a, a, c, c, d, d))


def read_obj(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                vertices.append([float(x) for x in w[1:4]])
            elif w[0] == "f":
                faces.append([int(x.split("/")[0]) - 1 for x in w[1:]])
    return np.array(vertices), faces


def segment_distance(p, a, b):
    ab = b - a
    t = np.einsum("ij,ij->i", p - a, ab) / np.maximum(
        np.einsum("ij,ij->i", ab, ab), 1e-300)
    t = np.clip(t, 0, 1)
    q = a + t[:, None] * ab
    return np.linalg.norm(p - q, axis=1)


def mesh_distance(p, A, B, C):
    """The distance of point p to the nearest of the triangles ABC."""
    n = np.cross(B - A, C - A)
    nn = np.einsum("ij,ij->i", n, n)
    w = p - A
    h = np.einsum("ij,ij->i", w, n) / nn
    q = w - h[:, None] * n
    b1 = np.einsum("ij,ij->i", np.cross(q, C - A), n) / nn
    b2 = np.einsum("ij,ij->i", np.cross(B - A, q), n) / nn
    inside = (b1 >= 0) & (b2 >= 0) & (b1 + b2 <= 1)
    plane = np.abs(h) * np.sqrt(nn)
    P = np.broadcast_to(p, A.shape)
    sides = np.minimum(segment_distance(P, A, B),
                       np.minimum(segment_distance(P, B, C),
                                  segment_distance(P, C, A)))
    return float(np.min(np.where(inside, plane, sides)))


def diagonal_distance(c):
    d1, d2 = c[2] - c[0], c[3] - c[1]
    n = np.cross(d1, d2)
    length = np.linalg.norm(n)
    if length == 0:
        return 0.0
    return abs(np.dot(c[1] - c[0], n)) / length


def run_check(surface, planarized, report):
    sv, sf = read_obj(surface)
    tri = np.array([f for f in sf if len(f) == 3])
    A, B, C = sv[tri[:, 0]], sv[tri[:, 1]], sv[tri[:, 2]]
    pv, pf = read_obj(planarized)
    with open(report) as f:
        j = json.load(f)
    check("every quad of the OBJ is a quad, %d of them as reported"
          % j["quads"], len(pf) == j["quads"] and all(len(f) == 4 for f in pf),
          "faces %d, reported %d" % (len(pf), j["quads"]))
    check("every corner is in the OBJ, %d as reported" % j["corners"],
          len(pv) == j["corners"], "%d" % len(pv))
    relative = []
    for f in pf:
        c = pv[f]
        diagonal = max(np.linalg.norm(c[2] - c[0]), np.linalg.norm(c[3] - c[1]))
        relative.append(diagonal_distance(c) / diagonal)
    relative = np.array(relative)
    over = int(np.sum(relative > j["planarity_tolerance"]))
    check("the largest planarity is the one reported (%.3g)"
          % j["planarity_max"],
          abs(relative.max() - j["planarity_max"]) <=
          1e-9 * max(1, relative.max()) + 1e-12,
          "measured %.17g, reported %.17g" % (relative.max(),
                                               j["planarity_max"]))
    check("the quads over the tolerance are the %d reported" % j["quads_over"],
          over == j["quads_over"], "measured %d" % over)
    distance = np.array([mesh_distance(p, A, B, C) for p in pv])
    check("the largest distance to the surface is the one reported "
          "(%.4f mm)" % j["closeness_max_mm"],
          abs(distance.max() * 1000 - j["closeness_max_mm"]) <= 1e-6,
          "measured %.9f mm" % (distance.max() * 1000))
    check("the mean distance to the surface is the one reported",
          abs(distance.mean() * 1000 - j["closeness_mean_mm"]) <= 1e-6,
          "measured %.9f mm, reported %.9f"
          % (distance.mean() * 1000, j["closeness_mean_mm"]))
    feasible = over == 0 and distance.max() * 1000 <= j["closeness_budget_mm"]
    check("feasible is %s, as measured" % j["feasible"],
          feasible == j["feasible"], "measured %s" % feasible)


def main():
    if sys.argv[1] == "vase":
        write_vase(sys.argv[2])
    else:
        run_check(sys.argv[2], sys.argv[3], sys.argv[4])


if __name__ == "__main__":
    main()
