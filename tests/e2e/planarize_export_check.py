#!/usr/bin/env python3
"""The files a fabricator gets of a planarized option (issue 33 item 3).

  planarize_export_check.py SURFACE.obj DB RUN OPTION CLASSIFIED PREFIX

reads what facet export wrote for the planarized OPTION (PREFIX-p.csv,
.json, .xlsx, .obj) and for the classified option CLASSIFIED (PREFIX-c.*)
and checks them against the panels table, read with sqlite3, not facet:
- every panel's corner_distance and corner_moved are in the CSV (metres,
  exactly), the JSON and the XLSX (millimetres, openpyxl), and empty,
  null or blank for the classified option, never 0;
- the OBJ's quads, measured with numpy alone: each is planar to 0.1 % of
  its diagonal, and its corners lie as far from the surface's triangles as
  the schedule says, within the distance the OBJ's projection onto the
  best-fit plane may move them (the panel's corner_planarity).
Prints ok / not ok lines.
"""
import csv
import json
import sqlite3
import sys

import numpy as np
import openpyxl

from planarize_check import check, diagonal_distance, mesh_distance, read_obj


def stored(db, run, option):
    con = sqlite3.connect(db)
    rows = con.execute(
        "SELECT i, j, corner_distance, corner_moved, corner_planarity"
        " FROM panels WHERE run = ? AND option = ?", (run, option)).fetchall()
    return {(r[0], r[1]): r[2:] for r in rows}


def csv_rows(path):
    return {(int(r["i"]), int(r["j"])): r
            for r in csv.DictReader(open(path, newline=""))}


def json_panels(path):
    with open(path) as f:
        return {(p["i"], p["j"]): p for p in json.load(f)["panels"]}


def xlsx_rows(path):
    ws = openpyxl.load_workbook(path, read_only=True)["panels"]
    it = ws.iter_rows(values_only=True)
    header = list(next(it))
    return {(r[header.index("column i")], r[header.index("row j")]):
            dict(zip(header, r)) for r in it}


def close(a, b, tolerance):
    return a is not None and b is not None and abs(a - b) <= tolerance


def obj_quads(path):
    """The panel groups' faces of an exported OBJ: {(i, j): corners}."""
    v, quads, group = [], {}, None
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                v.append([float(x) for x in w[1:4]])
            elif w[0] == "g" and w[1].startswith("panel_"):
                _, i, j = w[1].split("_")
                group = (int(i), int(j))
            elif w[0] == "f" and group is not None:
                idx = [int(x.split("/")[0]) - 1 for x in w[1:]]
                quads.setdefault(group, []).append(np.array([v[k] for k in idx]))
    return quads


def main():
    surface, db, run, option, classified, prefix = sys.argv[1:7]
    run, option, classified = int(run), int(option), int(classified)
    truth = stored(db, run, option)
    check("the planarized option's panels have a corner distance and move",
          truth and all(t[0] is not None and t[1] is not None
                        for t in truth.values()), truth)

    c, j, x = (csv_rows(prefix + "-p.csv"), json_panels(prefix + "-p.json"),
               xlsx_rows(prefix + "-p.xlsx"))
    bad = [k for k, t in truth.items()
           if float(c[k]["corner_distance_m"]) != t[0] or
           float(c[k]["corner_moved_m"]) != t[1]]
    check("CSV: corner_distance_m and corner_moved_m of every panel, exactly "
          "as stored (%d panels)" % len(truth), not bad and len(c) == len(truth),
          bad[:5])
    bad = [k for k, t in truth.items()
           if j[k]["corner_distance"] != t[0] or j[k]["corner_moved"] != t[1]]
    check("JSON: corner_distance and corner_moved of every panel, exactly",
          not bad and len(j) == len(truth), bad[:5])
    bad = [k for k, t in truth.items()
           if not close(x[k]["corner distance (mm)"], t[0] * 1000, 1e-9) or
           not close(x[k]["corner moved (mm)"], t[1] * 1000, 1e-9)]
    check("XLSX: corner distance and corner moved (mm) of every panel",
          not bad and len(x) == len(truth), bad[:5])

    ct = stored(db, run, classified)
    cc, cj, cx = (csv_rows(prefix + "-c.csv"), json_panels(prefix + "-c.json"),
                  xlsx_rows(prefix + "-c.xlsx"))
    check("a classified option moved no corner: NULL in the store",
          ct and all(t[0] is None and t[1] is None for t in ct.values()))
    check("and empty in its CSV, null in its JSON, blank in its XLSX",
          all(r["corner_distance_m"] == "" and r["corner_moved_m"] == ""
              for r in cc.values()) and
          all(p["corner_distance"] is None and p["corner_moved"] is None
              for p in cj.values()) and
          all(r["corner distance (mm)"] is None and
              r["corner moved (mm)"] is None for r in cx.values()),
          "some panel has a value")

    sv, sf = read_obj(surface)
    tri = np.array([f for f in sf if len(f) == 3])
    A, B, C = sv[tri[:, 0]], sv[tri[:, 1]], sv[tri[:, 2]]
    quads = obj_quads(prefix + "-p.obj")
    planar, far = [], []
    for k, t in truth.items():
        faces = quads.get(k, [])
        if len(faces) != 1 or len(faces[0]) != 4:
            planar.append((k, "not one quad"))
            continue
        q = faces[0]
        diagonal = max(np.linalg.norm(q[2] - q[0]), np.linalg.norm(q[3] - q[1]))
        if diagonal_distance(q) > 1e-3 * diagonal:
            planar.append((k, diagonal_distance(q) / diagonal))
        d = max(mesh_distance(p, A, B, C) for p in q)
        if abs(d - t[0]) > t[2] + 1e-9:
            far.append((k, d, t[0], t[2]))
    check("OBJ: every panel one quad, planar within 0.1 %% of its diagonal "
          "(numpy, %d quads)" % len(truth), not planar, planar[:5])
    check("OBJ: every quad's corners as far from the surface as the schedule "
          "says (numpy's brute force)", not far, far[:5])


if __name__ == "__main__":
    main()
