"""export_dxf.py DB RUN OPTION PATTERNS.dxf SCHEDULE.csv WxH MESH[:MESH...]
[exact]: an option's
flat patterns read back by ezdxf (not Facet), against the store read by
Python's sqlite3. SCHEDULE.csv is the same option's CSV schedule, read
only for its id -> (surface, i, j) key: the DXF's labels must be the
schedule's ids. WxH is the sheet size the export was given (mm); MESH
the option's OBJ files, read for their longest edge s. Prints
one "ok - ..." or "not ok - ..." line per check.

Truths and tolerances (t below is a panel's stored deviation from its
best-fit plane, d its stored sp_deviation from its fitted cylinder or
cone, D its stored diameter, k the larger of its stored |k1|, |k2|, A its
stored area, the mesh patch's):
  - FP and DP are cut to (drawn as) the outline projected onto the best-fit
    plane. The pattern's area is compared with that projected outline's
    area computed here from the DXF's own 3D outline and the store's
    normal, to 1e-6 relative (its correspondence to the panel checked by
    the store's four corners lying on it). Against A it can only be
    smaller, by at most what the tilt of the patch takes: a patch within
    t of its plane over a diameter D slopes at most about 8 t / D (a
    paraboloid cap: height 2 t over a half-width D / 2 at slope 4 (2t) /
    D), and a slope s shrinks area by 1 - cos = s^2 / 2: so A - area <=
    A 32 (t / D)^2.
  - SP is unrolled on the fitted surface, so its area is the fitted
    surface's over the outline moved onto it. The mesh patch lies within d
    of that surface: an offset d along the normal scales area by (1 + d
    k) at most (a cylinder: (R + d) / R), and an offset that varies by up
    to 2 d across D tilts it by up to 8 d / D, which (as above) changes
    area by 32 (d / D)^2. And A is the area of the mesh's facets, which
    are chords of the surface the panel is fitted to (on a coarse mesh
    the fit is made to the smooth surface through the vertices,
    sp_fit.h): a facet of edge s across a curvature k spans an angle s k
    and is shorter than its arc by the factor sin(s k / 2) / (s k / 2),
    1 - (s k)^2 / 24. So |area - A| <= A (2 d k + 32 (d / D)^2 + (s k)^2
    / 24): the 2 in 2 d k because the surface lies within d of the fit on
    either side.
  - The plane surface (facet example plane) has t = 0: its patterns are
    its panels, exactly (1e-9).
"""
import csv
import math
import sqlite3
import sys

import ezdxf

db, run, option, dxf, schedule, sheet = sys.argv[1], int(sys.argv[2]), \
    int(sys.argv[3]), sys.argv[4], sys.argv[5], sys.argv[6]
exact = len(sys.argv) > 8 and sys.argv[8] == "exact"


def longest_edge(path):
    """The longest edge of the OBJ's faces (m)."""
    vertices, longest = [], 0.0
    for line in open(path):
        part = line.split()
        if not part:
            continue
        if part[0] == "v":
            vertices.append(tuple(float(x) for x in part[1:4]))
        elif part[0] == "f":
            corners = [vertices[int(c.split("/")[0]) - 1] for c in part[1:]]
            for k in range(len(corners)):
                longest = max(longest, math.dist(
                    corners[k], corners[(k + 1) % len(corners)]))
    return longest


edge = max(longest_edge(path) for path in sys.argv[7].split(":"))
sheet_w, sheet_h = (float(v) for v in sheet.lower().split("x"))
con = sqlite3.connect(db)
con.row_factory = sqlite3.Row
failed = 0


def check(name, ok, detail=""):
    global failed
    failed += not ok
    print(("ok - " if ok else "not ok - ") + name +
          ("" if ok else "  (" + str(detail)[:400] + ")"))


def area2(points):
    s = 0.0
    for k in range(len(points)):
        x0, y0 = points[k]
        x1, y1 = points[(k + 1) % len(points)]
        s += x0 * y1 - x1 * y0
    return s / 2


def inside(p, poly):
    x, y = p
    hit = False
    for k in range(len(poly)):
        (x0, y0), (x1, y1) = poly[k], poly[(k + 1) % len(poly)]
        if (y0 > y) != (y1 > y) and \
                x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            hit = not hit
    return hit


def orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def segments_meet(a, b, c, d):
    d1, d2 = orient(c, d, a), orient(c, d, b)
    d3, d4 = orient(a, b, c), orient(a, b, d)
    if ((d1 > 0) != (d2 > 0) or d1 == 0 or d2 == 0) and \
            ((d3 > 0) != (d4 > 0) or d3 == 0 or d4 == 0):
        # Collinear pairs count only when their boxes meet.
        if d1 == d2 == d3 == d4 == 0:
            return max(min(a[0], b[0]), min(c[0], d[0])) <= \
                min(max(a[0], b[0]), max(c[0], d[0])) and \
                max(min(a[1], b[1]), min(c[1], d[1])) <= \
                min(max(a[1], b[1]), max(c[1], d[1]))
        return True
    return False


def overlap(p, q):
    """Brute force: an edge of p crosses or touches an edge of q, or one
    lies inside the other."""
    for k in range(len(p)):
        a, b = p[k], p[(k + 1) % len(p)]
        for m in range(len(q)):
            if segments_meet(a, b, q[m], q[(m + 1) % len(q)]):
                return True
    return inside(p[0], q) or inside(q[0], p)


def box(poly):
    xs, ys = [p[0] for p in poly], [p[1] for p in poly]
    return min(xs), min(ys), max(xs), max(ys)


doc = ezdxf.readfile(dxf)
auditor = doc.audit()
check("ezdxf reads it and its audit finds 0 errors (%d fixes)" %
      len(auditor.fixes), len(auditor.errors) == 0,
      [str(e) for e in auditor.errors[:3]])
check("its units are millimetres ($INSUNITS 4)",
      doc.header.get("$INSUNITS") == 4, doc.header.get("$INSUNITS"))
msp = doc.modelspace()
TYPES = ("FP", "SP", "DP")
patterns, labels, notes, frames, outlines = [], [], [], [], []
pattern_data, outline_data = [], []


def facet_xdata(e):
    """The entity's XDATA of the application FACET as {name: value}
    (name and value pairs), or None when it has none."""
    try:
        tags = list(e.get_xdata("FACET"))
    except Exception:
        return None
    return {tags[k].value: tags[k + 1].value
            for k in range(0, len(tags) - 1, 2)}


for e in msp:
    layer = e.dxf.layer
    if e.dxftype() == "POLYLINE":
        pts = list(e.points())
        if layer in TYPES:
            patterns.append((layer, [(p.x, p.y) for p in pts], e.is_closed))
            pattern_data.append(facet_xdata(e))
        elif layer == "SHEETS":
            frames.append([(p.x, p.y) for p in pts])
        elif layer.startswith("OUTLINE_3D_"):
            outlines.append((layer[len("OUTLINE_3D_"):],
                             [(p.x, p.y, p.z) for p in pts], e.is_closed))
            outline_data.append(facet_xdata(e))
    elif e.dxftype() == "TEXT" and layer in TYPES:
        where = e.dxf.align_point if e.dxf.hasattr("align_point") \
            else e.dxf.insert
        if e.dxf.text.isdigit():
            labels.append((layer, int(e.dxf.text), (where.x, where.y)))
        else:
            notes.append((layer, e.dxf.text, (where.x, where.y)))

# The schedule's key, and the store's panels.
rows = list(csv.DictReader(open(schedule)))
key = {int(r["id"]): (r.get("surface"), int(r["i"]), int(r["j"]))
       for r in rows}
opt = con.execute("SELECT * FROM options WHERE run=? AND number=?",
                  (run, option)).fetchone()
building = con.execute("SELECT count(*) FROM surfaces WHERE run=?",
                       (run,)).fetchone()[0] > 0
n = opt["panels"]
check("the schedule lists the option's %d panels" % n, len(key) == n,
      len(key))
check("one closed pattern per panel (%d)" % n,
      len(patterns) == n and all(c for _, _, c in patterns),
      len(patterns))
ids = sorted(i for _, i, _ in labels)
check("one label per panel, the schedule's ids 1..%d" % n,
      ids == list(range(1, n + 1)), ids[:10])
check("one closed 3D outline per panel", len(outlines) == n and
      all(c for _, _, c in outlines), len(outlines))

# Each label inside exactly one pattern, on its layer, and each pattern
# holding exactly one label.
holder = {}
bad = []
boxes_all = [box(poly) for _, poly, _ in patterns]
for layer, ident, at in labels:
    hits = [k for k, (pl, poly, _) in enumerate(patterns)
            if boxes_all[k][0] <= at[0] <= boxes_all[k][2] and
            boxes_all[k][1] <= at[1] <= boxes_all[k][3] and
            inside(at, poly)]
    if len(hits) != 1 or patterns[hits[0]][0] != layer:
        bad.append((ident, layer, hits))
    else:
        holder.setdefault(hits[0], []).append(ident)
check("every label lies in one pattern of its layer, every pattern holds "
      "one label", not bad and len(holder) == len(patterns) and
      all(len(v) == 1 for v in holder.values()), bad[:3])
pattern_of = {v[0]: patterns[k] for k, v in holder.items()}

# Layers as built.
built = {}
if not building:
    for r in con.execute("SELECT * FROM panels WHERE run=? AND option=?",
                         (run, option)):
        built[(None, r["i"], r["j"])] = r
    check("the store holds the option's panels", len(built) == n, len(built))
    bad = [(i, pattern_of[i][0], built[key[i]]["built_type"])
           for i in pattern_of if pattern_of[i][0] !=
           built[key[i]]["built_type"]]
    check("each pattern on the layer of its panel's type as built", not bad,
          bad[:3])
else:
    counts = {}
    for i, (layer, _, _) in pattern_of.items():
        surface = key[i][0]
        counts[(surface, layer)] = counts.get((surface, layer), 0) + 1
    names = [r[0] for r in con.execute(
        "SELECT name FROM surfaces WHERE run=? ORDER BY surface", (run,))]
    srows = con.execute("SELECT * FROM option_surfaces WHERE run=? AND "
                        "option=? ORDER BY surface", (run, option)).fetchall()
    bad = [(name, t, counts.get((name, t), 0), s[t.lower() + "_count"])
           for name, s in zip(names, srows) for t in TYPES
           if counts.get((name, t), 0) != s[t.lower() + "_count"]]
    check("each surface's patterns per layer as many as option_surfaces' "
          "panels per type as built", not bad, bad[:3])
dp = [i for i, p in pattern_of.items() if p[0] == "DP"]
noted = set()
for _, t, at in notes:
    for i in dp:
        if t == "DP: not developable" and inside(at, pattern_of[i][1]):
            noted.add(i)
bad = [i for i in dp if i not in noted]
check("each of the %d DP patterns is marked not developable" % len(dp),
      not bad, bad[:5])

# Sheets: frames of the size given; every pattern inside one; no two
# patterns on a sheet overlap.
bad = [f for f in frames if len(f) != 4 or
       abs(box(f)[2] - box(f)[0] - sheet_w) > 1e-6 or
       abs(box(f)[3] - box(f)[1] - sheet_h) > 1e-6]
check("%d sheet frames, each %g x %g mm" % (len(frames), sheet_w, sheet_h),
      frames and not bad, bad[:2])
frame_boxes = [box(f) for f in frames]
on_sheet = {}
bad = []
for i, (layer, poly, _) in pattern_of.items():
    b = box(poly)
    hits = [k for k, f in enumerate(frame_boxes) if b[0] >= f[0] and
            b[1] >= f[1] and b[2] <= f[2] and b[3] <= f[3]]
    if len(hits) != 1:
        bad.append((i, b))
    else:
        on_sheet.setdefault(hits[0], []).append(i)
check("every pattern inside one sheet's frame", not bad, bad[:3])
pairs = 0
bad = []
for k, members in on_sheet.items():
    boxes = {i: box(pattern_of[i][1]) for i in members}
    for x in range(len(members)):
        for y in range(x + 1, len(members)):
            a, b = members[x], members[y]
            p, q = boxes[a], boxes[b]
            pairs += 1
            if p[0] > q[2] or q[0] > p[2] or p[1] > q[3] or q[1] > p[3]:
                continue  # boxes apart: the polygons are
            if overlap(pattern_of[a][1], pattern_of[b][1]):
                bad.append((k, a, b))
# Pairs must be there to check: sheets that hold one pattern each would
# pass whatever the packer did.
check("no two patterns on a sheet overlap (%d pairs on %d sheets)" %
      (pairs, len(on_sheet)), not bad and
      (pairs > 0 or len(pattern_of) <= len(frames)), bad[:3])

# Areas. The 3D outline of id k is the k-th (both in id order): checked by
# the store's corners of panel k lying on it. A single surface's panels
# are in the store, row by row; a building's are not (option_surfaces
# holds each surface's sums), so there each panel's numbers are the
# schedule's, and their sums per surface and type are held to the store's.
def panel_of(i):
    if not building:
        s = built[key[i]]
        return {"area": s["area"], "deviation": s["deviation"],
                "diameter": s["diameter"], "sp_deviation": s["sp_deviation"],
                "k": max(abs(s["k1"]), abs(s["k2"])),
                "corners": [tuple(s["c%d_%s" % (c, x)] for x in "xyz")
                            for c in range(4)],
                "normal": (s["normal_x"], s["normal_y"], s["normal_z"])}
    r = rows[i - 1]
    return {"area": float(r["area_m2"]), "deviation": float(r["deviation_m"]),
            "diameter": float(r["diameter_m"]),
            "sp_deviation": float(r["sp_deviation_m"] or "nan"),
            "k": max(abs(float(r["k1"])), abs(float(r["k2"]))),
            "corners": [tuple(float(r["c%d_%s_m" % (c, x)] or "nan")
                              for x in "xyz")
                        for c in range(4)], "normal": None}


bad_match, bad_plane, bad_fp, bad_sp, worst = [], [], [], [], {}
sums, slack_sums = {}, {}
for i in range(1, n + 1):
    s = panel_of(i)
    layer, poly, _ = pattern_of[i]
    out3 = [tuple(c / 1000 for c in p) for p in outlines[i - 1][1]]
    if not all(any(math.dist(c, p) < 1e-6 for p in out3)
               for c in s["corners"]
               if c[0] is not None and not math.isnan(c[0])):
        bad_match.append(i)
        continue
    area = area2(poly) / 1e6  # mm^2 -> m^2
    A = s["area"]
    # The DXF's coordinates are rounded to 1e-6 mm: each edge moves by
    # under 1e-9 m, the area by under the perimeter times that (a moved
    # quad's pattern has exactly its panel's area, so only this is left).
    rounding = 1e-9 * sum(math.dist(poly[k], poly[(k + 1) % len(poly)])
                          for k in range(len(poly))) / 1000
    slack = 0.0
    if layer in ("FP", "DP") and s["normal"] is not None:
        # Newell's area vector of the 3D outline, along the normal: its
        # projection's signed area seen from the normal's side.
        v = [0.0, 0.0, 0.0]
        for k in range(len(out3)):
            a, b = out3[k], out3[(k + 1) % len(out3)]
            v[0] += (a[1] - b[1]) * (a[2] + b[2])
            v[1] += (a[2] - b[2]) * (a[0] + b[0])
            v[2] += (a[0] - b[0]) * (a[1] + b[1])
        projected = sum(x * y for x, y in zip(v, s["normal"])) / 2
        if not abs(area - projected) <= 1e-6 * abs(projected):
            bad_plane.append((i, area, projected))
    if layer == "FP":
        t, D = s["deviation"], s["diameter"]
        slack = A * 32 * (t / D) ** 2
        if not (area <= A * (1 + 1e-9) + rounding and
                A - area <= slack + 1e-9 * A + rounding):
            bad_fp.append((i, area, A, slack))
        worst["FP"] = max(worst.get("FP", 0), (A - area) / A)
    elif layer == "SP":
        d, D = s["sp_deviation"], s["diameter"]
        slack = A * (2 * d * s["k"] + 32 * (d / D) ** 2 +
                     (edge * s["k"]) ** 2 / 24)
        if not abs(area - A) <= slack + 1e-9 * A:
            bad_sp.append((i, area, A, slack))
        worst["SP"] = max(worst.get("SP", 0), abs(area - A) / A)
    k = (key[i][0], layer)
    sums[k] = sums.get(k, 0) + area
    slack_sums[k] = slack_sums.get(k, 0) + slack + 1e-9 * A
check("each 3D outline passes through its panel's stored corners",
      not bad_match, bad_match[:5])
if not building:
    check("FP and DP patterns: their area that of the 3D outline projected "
          "onto the stored best-fit plane (1e-6)", not bad_plane,
          bad_plane[:3])
check("FP patterns: area within A 32 (t/D)^2 under the panel's area "
      "(worst %.2g relative)" % worst.get("FP", 0), not bad_fp, bad_fp[:3])
check("SP patterns: area within A (2 d k + 32 (d/D)^2 + (s k)^2/24) of "
      "the panel's area (worst %.2g relative)" % worst.get("SP", 0), not bad_sp,
      bad_sp[:3])
if building:
    bad = []
    for name, s in zip(names, srows):
        for t in ("FP", "SP"):
            got = sums.get((name, t), 0)
            want = s[t.lower() + "_area"]
            if not abs(got - want) <= slack_sums.get((name, t), 0) + 1e-9:
                bad.append((name, t, got, want))
    check("each surface's FP and SP pattern areas add up to "
          "option_surfaces' within their panels' tolerances summed", not bad,
          bad[:3])
# Each panel's XDATA (issue 33): its id on every polyline of it; a
# planarized option's moved panels also their corner distance and move.
pattern_id = {id(pattern_of[i]): i for i in pattern_of}
bad = [(k, d) for k, d in enumerate(pattern_data)
       if d is None or d.get("PanelId") !=
       str(pattern_id.get(id(patterns[k]), "unlabelled"))]
bad += [(k, d) for k, d in enumerate(outline_data)
        if d is None or d.get("PanelId") != str(k + 1)]
check("every pattern and 3D outline carries its panel's id as XDATA "
      "(FACET PanelId)", not bad, bad[:3])
MEASURES = ("CornerDistance_mm", "CornerMoved_mm")
planarized = opt["planarized"] == 1
if not planarized:
    bad = [d for d in pattern_data + outline_data
           if d is not None and any(m in d for m in MEASURES)]
    check("a classified option moved no corner: no corner distance or move "
          "in any panel's XDATA (not measured, never 0)", not bad, bad[:3])
else:
    import numpy as np
    from planarize_check import diagonal_distance, mesh_distance, read_obj
    sv, sf = read_obj(sys.argv[7])
    tri = np.array([f for f in sf if len(f) == 3])
    A, B, C = sv[tri[:, 0]], sv[tri[:, 1]], sv[tri[:, 2]]
    moved, bad_quad, bad_flat, bad_store, bad_far, bad_none = 0, [], [], \
        [], [], []
    for i in range(1, n + 1):
        s = built[key[i]]
        d = outline_data[i - 1] or {}
        if s["corner_distance"] is None:
            if any(m in d for m in MEASURES):
                bad_none.append(i)
            continue
        moved += 1
        q = np.array(outlines[i - 1][1]) / 1000  # mm -> m
        corners = np.array([[s["c%d_%s" % (c, x)] for x in "xyz"]
                            for c in range(4)])
        # The moved quad itself: its four corners, each a stored corner.
        if len(q) != 4 or max(min(np.linalg.norm(corners - p, axis=1))
                              for p in q) > 1e-9:
            bad_quad.append((i, len(q)))
            continue
        diagonal = max(np.linalg.norm(q[2] - q[0]), np.linalg.norm(q[3] - q[1]))
        relative = diagonal_distance(q) / diagonal
        # Planar to the option's reported planarity, less the DXF's
        # rounding of its coordinates to a nanometre.
        if relative > opt["planarity_reached"] + 1e-8 or \
                (s["built_type"] == "FP" and relative > 1e-3 + 1e-8):
            bad_flat.append((i, relative, opt["planarity_reached"]))
        got = (float(d.get("CornerDistance_mm", "nan")),
               float(d.get("CornerMoved_mm", "nan")))
        want = (s["corner_distance"] * 1000, s["corner_moved"] * 1000)
        if not all(abs(a - b) <= 1e-12 * max(1, abs(b))
                   for a, b in zip(got, want)) or \
                pattern_data[[k for k, v in enumerate(patterns)
                              if v is pattern_of[i]][0]] != d:
            bad_store.append((i, got, want))
        brute = 1000 * max(mesh_distance(p, A, B, C) for p in q)
        if not abs(got[0] - brute) <= 1e-5:
            bad_far.append((i, got[0], brute))
    check("a planarized option: each moved panel's 3D outline is its moved "
          "quad, its four stored corners (%d panels)" % moved,
          moved > 0 and not bad_quad, bad_quad[:3])
    check("each moved quad planar within the option's reported planarity "
          "%.3g (and 1e-3 when FP)" % opt["planarity_reached"],
          not bad_flat, bad_flat[:3])
    check("XDATA CornerDistance_mm and CornerMoved_mm as the panels table, "
          "the same on its pattern", not bad_store, bad_store[:3])
    check("XDATA CornerDistance_mm the brute-force distance of the quad's "
          "corners to the surface's triangles (1e-5 mm, numpy)",
          not bad_far, bad_far[:3])
    check("a panel not moved (trimmed) has no corner distance or move",
          not bad_none, bad_none[:3])
if exact:
    bad = [(i, area2(pattern_of[i][1]) / 1e6, panel_of(i)["area"])
           for i in pattern_of if not abs(
               area2(pattern_of[i][1]) / 1e6 - panel_of(i)["area"])
           <= 1e-9 * panel_of(i)["area"]]
    check("a plane: every pattern's area its panel's (1e-9)", not bad,
          bad[:3])
sys.exit(1 if failed else 0)
