"""export_sp_fit.py DB BOOK.xlsx KIND TRUTH: the fitted cylinder or cone of
every SP panel in an XLSX schedule (read by openpyxl), against the
surface developables.py wrote (KIND cylinder or cone; TRUTH its printed
values) and the panels' sp_deviation in the store (sqlite3). Prints one
"ok - ..." or "not ok - ..." line per check.

The tolerances come from each panel's own deviation d (the largest
distance of its samples from its fit, which the store holds), and its
extent: points within d of the true surface on a panel w wide and L
long along the rulings pin the rulings' direction to 2 d / L (rad); a
cylinder's radius to 2 d 8 R^2 / w^2 (the sagitta w^2 / 8R moves by
w^2 dR / 8R^2); its axis to that across; a cone's apex, s_far from the
panel's far end, to 2 d s_far / L."""
import math
import sqlite3
import sys

import openpyxl

db, book, kind, truth_file = sys.argv[1:5]
truth = {}
for line in open(truth_file):
    name, *values = line.split()
    truth[name] = [float(v) for v in values]
con = sqlite3.connect(db)
con.row_factory = sqlite3.Row
failed = 0


def check(name, ok, detail=""):
    global failed
    failed += not ok
    print(("ok - " if ok else "not ok - ") + name +
          ("" if ok else "  (" + str(detail)[:400] + ")"))


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def norm(a):
    return math.sqrt(dot(a, a))


def off_line(x, point, direction):
    q = sub(x, point)
    h = dot(q, direction)
    return math.sqrt(max(dot(q, q) - h * h, 0))


ws = openpyxl.load_workbook(book)["panels"]
header = [c.value for c in ws[1]]
rows = [dict(zip(header, r)) for r in ws.iter_rows(min_row=2,
                                                     values_only=True)]
stored = {(r["i"], r["j"]): r for r in con.execute(
    "SELECT * FROM panels WHERE run=1 AND option=1")}
check("every panel is built SP (%d)" % len(rows),
      rows and all(r["type as built"] == "SP" for r in rows))
axis = truth["axis"]
bad = []
for r in rows:
    s = stored[(r["column i"], r["row j"])]
    d = s["sp_deviation"]
    corners = [[s["c%d_%s" % (c, x)] for x in "xyz"] for c in range(4)]
    # Along the rulings: the panel's extent along the true axis; across:
    # the rest.
    along = [dot(sub(c, corners[0]), axis) for c in corners]
    L = max(along) - min(along)
    w = max(norm(sub(corners[1], corners[0])),
            norm(sub(corners[2], corners[3])))
    fitted = r["SP fitted surface"]
    direction = [r["SP axis direction %s" % x] for x in "xyz"]
    point = [r["SP axis point %s (m)" % x] for x in "xyz"]
    angle = math.acos(min(1, abs(dot(direction, axis))))
    why = []
    if fitted != kind:
        why.append("fitted %s" % fitted)
    if not abs(r["SP deviation (mm)"] / 1000 - d) <= 1e-6:
        why.append("deviation %s mm, stored %s m" % (r["SP deviation (mm)"],
                                                     d))
    if not angle <= 2 * d / L:
        why.append("axis %.3g rad off > %.3g" % (angle, 2 * d / L))
    if kind == "cylinder":
        R = truth["radius"][0]
        tol = 2 * d * 8 * R * R / (w * w)
        if not abs(r["SP cylinder radius (m)"] - R) <= tol:
            why.append("radius %r, tol %.3g" % (r["SP cylinder radius (m)"],
                                                tol))
        if not off_line(point, truth["axis_point"], axis) <= tol:
            why.append("axis point %.3g m off the axis" %
                       off_line(point, truth["axis_point"], axis))
        if any(r["SP cone %s" % x] is not None for x in
               ("apex x (m)", "apex y (m)", "apex z (m)",
                "half-angle (deg)")):
            why.append("a cylinder with a cone's cells")
    else:
        apex = [r["SP cone apex %s (m)" % x] for x in "xyz"]
        s_far = max(norm(sub(c, truth["apex"])) for c in corners)
        tol = 2 * d * s_far / L
        if not norm(sub(apex, truth["apex"])) <= tol:
            why.append("apex %.3g m off, tol %.3g" %
                       (norm(sub(apex, truth["apex"])), tol))
        half = r["SP cone half-angle (deg)"]
        if not abs(math.radians(half - truth["half_angle"][0])) <= 2 * d / L:
            why.append("half-angle %r deg" % half)
        if not dot(direction, axis) > 0:
            why.append("axis not from the apex towards the panel")
        if not off_line(point, truth["apex"], axis) <= tol:
            why.append("axis point off the axis")
        if r["SP cylinder radius (m)"] is not None:
            why.append("a cone with a cylinder's radius")
    if why:
        bad.append(((r["column i"], r["row j"]), why))
# The store keeps the same fit (schema v11's sp_* columns of panels),
# made by the evaluation, not the export: each number the workbook's, the
# half-angle in degrees as the workbook shows it.
columns = [("sp_axis_%s" % x, "SP axis point %s (m)" % x) for x in "xyz"] + \
    [("sp_direction_%s" % x, "SP axis direction %s" % x) for x in "xyz"] + \
    [("sp_radius", "SP cylinder radius (m)")] + \
    [("sp_apex_%s" % x, "SP cone apex %s (m)" % x) for x in "xyz"] + \
    [("sp_half_angle", "SP cone half-angle (deg)")] + \
    [("sp_bending_radius", "SP bending radius (m)")]
mismatch = []
for r in rows:
    s = stored[(r["column i"], r["row j"])]
    if s["sp_surface"] != r["SP fitted surface"]:
        mismatch.append(((r["column i"], r["row j"]), "sp_surface",
                         s["sp_surface"]))
    for col, head in columns:
        a, b = s[col], r[head]
        same = (a is None and b is None) or (
            a is not None and b is not None and
            abs(a - b) <= 1e-12 * max(1.0, abs(b)))
        if not same:
            mismatch.append(((r["column i"], r["row j"]), col, a, b))
check("the store's sp_* columns hold each SP panel's fitted %s as the "
      "workbook does (%d panels)" % (kind, len(rows)),
      rows and not mismatch, mismatch[:3])
check("every SP panel's fitted %s: its axis, %s and deviation as the "
      "surface and the store give them" %
      (kind, "radius" if kind == "cylinder" else "apex and half-angle"),
      not bad, bad[:3])
sys.exit(1 if failed else 0)
