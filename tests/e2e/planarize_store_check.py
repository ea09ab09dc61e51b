#!/usr/bin/env python3
"""The independent check of a stored planarized option (issue 33).

  planarize_store_check.py SURFACE.obj DB RUN OPTION PLANARIZE.json

reads the option's row and its panels straight from the SQLite file
(sqlite3, not facet), recomputes with numpy (planarize_check.py's brute
force) every quad's planarity from the stored corners c0..c3 and every
corner's distance to the surface's triangles, and compares them with the
stored closeness_reached, closeness_mean, planarity_reached, planar_over,
each panel's corner_distance and type (FP exactly when its quad is planar
within 0.1 % of its diagonal), and with what facet planarize --json said
for the same grid and budget (PLANARIZE.json). Prints ok / not ok lines.
"""
import json
import sqlite3
import sys

import numpy as np

from planarize_check import check, diagonal_distance, mesh_distance, read_obj


def main():
    surface, db, run, option, report = sys.argv[1:6]
    with open(report) as f:
        j = json.load(f)
    con = sqlite3.connect(db)
    row = con.execute(
        "SELECT planarized, closeness_reached, closeness_mean,"
        " planarity_reached, planar_over, feasible, cost, fp_count, nu, nv"
        " FROM options WHERE run = ? AND number = ?",
        (run, option)).fetchone()
    budget = con.execute("SELECT planarize_closeness_mm FROM runs"
                         " WHERE id = ?", (run,)).fetchone()[0]
    panels = con.execute(
        "SELECT i, j, type, corner_distance, c0_x, c0_y, c0_z, c1_x, c1_y,"
        " c1_z, c2_x, c2_y, c2_z, c3_x, c3_y, c3_z FROM panels"
        " WHERE run = ? AND option = ? ORDER BY j, i",
        (run, option)).fetchall()
    (planarized, reached, mean, planarity, over, feasible, cost, fp,
     nu, nv) = row
    check("the option is stored planarized", planarized == 1, repr(row))
    check("its %d x %d panels are stored, one per cell" % (nu, nv),
          len(panels) == nu * nv, "%d panels" % len(panels))
    sv, sf = read_obj(surface)
    tri = np.array([f for f in sf if len(f) == 3])
    A, B, C = sv[tri[:, 0]], sv[tri[:, 1]], sv[tri[:, 2]]
    # Each corner once (neighbouring panels share it), by its grid node.
    offsets = ((0, 0), (1, 0), (1, 1), (0, 1))
    nodes = {}
    for p in panels:
        c = np.array(p[4:16], dtype=float).reshape(4, 3)
        for k, (di, dj) in enumerate(offsets):
            nodes.setdefault((p[0] + di, p[1] + dj), c[k])
    corners = {key: mesh_distance(x, A, B, C) for key, x in nodes.items()}
    relative, types_ok, panel_ok = [], True, True
    for p in panels:
        kind, corner_distance = p[2], p[3]
        c = np.array(p[4:16], dtype=float).reshape(4, 3)
        diagonal = max(np.linalg.norm(c[2] - c[0]),
                       np.linalg.norm(c[3] - c[1]))
        r = diagonal_distance(c) / diagonal
        relative.append(r)
        types_ok &= kind == ("FP" if r <= 1e-3 else "DP")
        d = [corners[(p[0] + di, p[1] + dj)] for di, dj in offsets]
        panel_ok &= abs(max(d) - corner_distance) <= 1e-9
    relative = np.array(relative)
    distance = np.array(list(corners.values()))
    check("the stored planarity_reached is the largest measured on the "
          "stored corners (%.3g)" % relative.max(),
          abs(relative.max() - planarity) <= 1e-9 * max(1, planarity) +
          1e-12, "stored %r" % planarity)
    check("the stored closeness_reached is the largest corner distance to "
          "the surface, by brute force (%.6f mm)" % (distance.max() * 1000),
          abs(distance.max() - reached) <= 1e-9, "stored %r m" % reached)
    check("the stored closeness_mean is the mean corner distance",
          abs(distance.mean() - mean) <= 1e-9, "stored %r m, measured %r"
          % (mean, distance.mean()))
    check("every panel's corner_distance is its corners' largest",
          panel_ok, "")
    check("a panel is FP exactly when its quad is planar within 0.1 %",
          types_ok, "")
    check("the run stores its closeness budget", budget is not None, "")
    missed = sum(1 for p, r in zip(panels, relative)
                 if r > 1e-3 or p[3] > budget / 1000)
    check("planar_over counts the quads that missed (%d)" % missed,
          over == missed, "stored %r" % over)
    check("an option with a quad that missed is infeasible",
          missed == 0 or not feasible, "feasible %r" % feasible)
    check("facet planarize --json reached the same closeness",
          abs(j["closeness_max_mm"] - reached * 1000) <= 1e-6,
          "planarize %r mm, stored %r m" % (j["closeness_max_mm"], reached))
    check("facet planarize --json reached the same planarity",
          abs(j["planarity_max"] - planarity) <= 1e-9,
          "planarize %r, stored %r" % (j["planarity_max"], planarity))
    check("facet planarize --json missed the same quads",
          j["quads_missed"] == over, "%r" % j["quads_missed"])
    check("facet planarize --json priced it the same (%.2f USD)" % cost,
          abs(j["cost_usd"] - cost) <= 1e-6 * cost and j["fp_count"] == fp,
          "planarize %r USD %r FP" % (j["cost_usd"], j["fp_count"]))


main()
