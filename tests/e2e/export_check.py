"""export_check.py: checks for tests/e2e/export.sh.

    export_check.py CHECK ARGS...

Each check prints nothing on success and exits 0; on failure it prints the
reason on stderr and exits 1. The option row comes from sqlite3 (python's
sqlite3 module, read-only).
"""
import csv
import json
import sqlite3
import struct
import sys
import zlib


def option_row(db, run, number):
    con = sqlite3.connect("file:%s?mode=ro" % db, uri=True)
    con.row_factory = sqlite3.Row
    row = con.execute("SELECT * FROM options WHERE run=? AND number=?",
                      (int(run), int(number))).fetchone()
    if row is None:
        raise SystemExit("no option %s of run %s" % (number, run))
    return dict(row)


def close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


def fail(msg):
    print(msg, file=sys.stderr)
    sys.exit(1)


def polygon_area(points):
    """Area of a planar polygon (any shape) by Newell's vector area."""
    sx = sy = sz = 0.0
    n = len(points)
    for k in range(n):
        x0, y0, z0 = points[k]
        x1, y1, z1 = points[(k + 1) % n]
        sx += y0 * z1 - z0 * y1
        sy += z0 * x1 - x0 * z1
        sz += x0 * y1 - y0 * x1
    return 0.5 * (sx * sx + sy * sy + sz * sz) ** 0.5


def read_mtl(path):
    kd, name = {}, None
    for line in open(path):
        w = line.split()
        if not w:
            continue
        if w[0] == "newmtl":
            name = w[1]
        elif w[0] == "Kd" and name is not None:
            kd[name] = tuple(float(x) for x in w[1:4])
    return kd


def check_obj(obj, mtl, db, run, number):
    import tinyobjloader
    o = option_row(db, run, number)
    kd = read_mtl(mtl)
    if set(kd) != {"FP", "SP", "DP"}:
        fail("mtl materials %s, want FP, SP, DP" % sorted(kd))
    if len(set(kd.values())) != 3:
        fail("mtl Kd not distinct: %s" % kd)
    reader = tinyobjloader.ObjReader()
    config = tinyobjloader.ObjReaderConfig()
    config.triangulate = False
    if not reader.ParseFromFile(obj, config):
        fail("tinyobjloader: %s" % reader.Error().strip())
    names = [m.name for m in reader.GetMaterials()]
    if sorted(names) != ["DP", "FP", "SP"]:
        fail("tinyobjloader materials %s" % names)
    shapes = reader.GetShapes()
    if len(shapes) != o["panels"]:
        fail("%d shapes, want %d panels" % (len(shapes), o["panels"]))
    shape_names = [s.name for s in shapes]
    if len(set(shape_names)) != len(shape_names) or \
            not all(n.startswith("panel_") for n in shape_names):
        fail("shape names not one panel_I_J each: %s" % shape_names[:10])
    v = list(reader.GetAttrib().vertices)
    area = {"FP": 0.0, "SP": 0.0, "DP": 0.0}
    count = {"FP": 0, "SP": 0, "DP": 0}
    for s in shapes:
        mesh = s.mesh
        idx = [i.vertex_index for i in mesh.indices]
        mats = set()
        at = 0
        for f, nv in enumerate(mesh.num_face_vertices):
            pts = [tuple(v[3 * idx[at + k] + c] for c in range(3))
                   for k in range(nv)]
            at += nv
            m = names[mesh.material_ids[f]] if mesh.material_ids[f] >= 0 else None
            if m is None:
                fail("face without a material in %s" % s.name)
            mats.add(m)
            area[m] += polygon_area(pts)
        if len(mats) != 1:
            fail("shape %s has materials %s" % (s.name, mats))
        count[mats.pop()] += 1
    for t in ("FP", "SP", "DP"):
        if count[t] != o[t.lower() + "_count"]:
            fail("%s: %d groups, want %d" % (t, count[t], o[t.lower() + "_count"]))
    for t in ("SP", "DP"):
        if not close(area[t], o[t.lower() + "_area"], 1e-6):
            fail("%s area %.12g, option says %.12g" % (t, area[t], o[t.lower() + "_area"]))
    fp, want = area["FP"], o["fp_area"]
    if not close(fp, want, 1e-3) or fp > want * (1 + 1e-9) + 1e-12:
        fail("FP area %.12g, option says %.12g" % (fp, want))


def connect_db(path):
    return sqlite3.connect("file:%s?mode=ro" % path, uri=True)


def check_csv(path, db, run, number):
    """The schedule (panels only, one unit per column, named in the
    header) and its totals beside it (PATH-totals.csv) against the
    options row and the stored panels."""
    o = option_row(db, run, number)
    rows = list(csv.DictReader(open(path, newline="")))
    want = ["id", "i", "j", "class", "type", "area_m2", "deviation_m", "k1",
            "k2", "K", "H", "eps", "p_dist_m4", "diameter_m", "trimmed",
            "corner_planarity_m", "price_usd_m2", "cost_usd"] + [
            "c%d_%s_m" % (c, x) for c in range(4) for x in "xyz"] + [
            "mould_family", "built_type", "sp_deviation_m", "worst_gap_mm",
            "worst_kink_deg", "misfit_reason", "corner_distance_m",
            "corner_moved_m"]
    header = list(rows[0].keys()) if rows else []
    if header != want:
        fail("csv header %s, want %s" % (header, want))
    if len(rows) != o["panels"]:
        fail("%d panel rows, want %d" % (len(rows), o["panels"]))
    if any(r["id"] == "total" for r in rows):
        fail("a totals row in the panel schedule")
    totals_path = path[:-4] + "-totals.csv"
    totals = list(csv.DictReader(open(totals_path, newline="")))
    if len(totals) != 1:
        fail("%s: %d rows, want one" % (totals_path, len(totals)))
    t = totals[0]
    for key, col in (("area_m2", "area"), ("cost_usd", "cost"),
                     ("fp_area_m2", "fp_area"), ("dp_cost_usd", "dp_cost"),
                     ("planarity_m", "planarity"),
                     ("max_deviation_m", "max_deviation"),
                     ("panels", "panels"), ("feasible", "feasible"),
                     ("joint_length_m", "joint_length"), ("moulds", "moulds"),
                     ("area_cost_usd", "area_cost"),
                     ("mould_cost_usd", "mould_cost"),
                     ("max_gap_mm", "max_gap"), ("max_kink_deg", "max_kink"),
                     ("sp_misfits", "sp_misfits"),
                     ("gaps_over", "gaps_over")):
        if float(t[key]) != o[col]:
            fail("totals %s %s, options row %r" % (key, t[key], o[col]))
    # A panel's cost is its area's; the panel, joint and mould terms are
    # the option's.
    s = sum(float(r["cost_usd"]) for r in rows)
    if not close(s, float(t["area_cost_usd"]), 1e-9):
        fail("panel costs add to %.12g, totals %s" % (s, t["area_cost_usd"]))
    families = {r["mould_family"] for r in rows if r["mould_family"] != ""}
    if len(families) != o["moulds"]:
        fail("%d mould families in the schedule, options row %r"
             % (len(families), o["moulds"]))
    stored = {(i, j): (d, g, k, b, m) for i, j, d, g, k, b, m in
              connect_db(db).execute(
        "SELECT i, j, deviation, worst_gap, worst_kink, built_type,"
        " coalesce(misfit_reason, '') FROM panels WHERE run = ? AND"
        " option = ?", (int(run), int(number)))}
    for r in rows:
        x = stored.get((int(r["i"]), int(r["j"])))
        if x is None:
            continue
        if float(r["deviation_m"]) != x[0]:
            fail("panel %s %s deviation_m %s, stored %r" % (r["i"], r["j"],
                                                            r["deviation_m"], x[0]))
        if (float(r["worst_gap_mm"]) != x[1] or
                float(r["worst_kink_deg"]) != x[2] or
                r["built_type"] != x[3] or r["misfit_reason"] != x[4]):
            fail("panel %s %s as built %r, stored %r" % (r["i"], r["j"], r, x))
    # The option's misfits are its panels with a reason.
    if sum(1 for r in rows if r["misfit_reason"]) != o["sp_misfits"]:
        fail("misfits in the schedule %d, options row %r" % (
            sum(1 for r in rows if r["misfit_reason"]), o["sp_misfits"]))
    if len({(r["i"], r["j"]) for r in rows}) != len(rows):
        fail("csv panel (i,j) repeated")


def keyset(j, prefix=""):
    keys = set()
    if isinstance(j, dict):
        for k, v in j.items():
            keys.add(prefix + k)
            keys |= keyset(v, prefix + k + ".")
    elif isinstance(j, list) and j and isinstance(j[0], dict):
        for item in j:
            keys |= keyset(item, prefix + "[].")
    return keys


def check_json(path, classify_json, db, run, number):
    o = option_row(db, run, number)
    j = json.load(open(path))
    c = json.load(open(classify_json))
    if keyset(j) != keyset(c):
        fail("key sets differ: only in export %s, only in classify %s"
             % (sorted(keyset(j) - keyset(c)), sorted(keyset(c) - keyset(j))))
    t = j["totals"]
    compared = 0
    for k, want in o.items():
        if k in t and isinstance(t[k], (int, float)) and want is not None:
            compared += 1
            if not close(float(t[k]), float(want), 1e-9):
                fail("totals.%s = %r, store has %r" % (k, t[k], want))
    if compared < 10:
        fail("only %d totals compared" % compared)
    if len(j["panels"]) != o["panels"]:
        fail("%d panels, want %d" % (len(j["panels"]), o["panels"]))
    if j["grid"] != {"nu": o["nu"], "nv": o["nv"]}:
        fail("grid %s, option %dx%d" % (j["grid"], o["nu"], o["nv"]))


def png_pixels(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail("%s is not a PNG" % path)
    at, idat, width = 8, b"", None
    while at < len(data):
        n, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + n]
        if kind == b"IHDR":
            width, height, depth, ctype = struct.unpack(">IIBB", body[:10])
        elif kind == b"IDAT":
            idat += body
        at += 12 + n
    return width, zlib.decompress(idat)


def check_png(path):
    """Not a single colour: decode with PIL if there, else count bytes."""
    try:
        from PIL import Image
        colours = Image.open(path).convert("RGBA").getcolors(1 << 24)
        if colours is None or len(colours) < 3:
            fail("%s has %s colours" % (path, None if colours is None else len(colours)))
        return
    except ImportError:
        pass
    _, raw = png_pixels(path)
    if len(set(raw)) < 8:
        fail("%s looks blank (%d distinct bytes)" % (path, len(set(raw))))


def png_rgba(path):
    """The rows of an 8-bit RGB or RGBA PNG (rsvg-convert's), unfiltered,
    and its bytes a pixel."""
    data = open(path, "rb").read()
    at, idat = 8, b""
    while at < len(data):
        n, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + n]
        if kind == b"IHDR":
            width, height, depth, ctype = struct.unpack(">IIBB", body[:10])
            if depth != 8 or ctype not in (2, 6):
                fail("%s: not 8-bit RGB or RGBA (depth %d, colour type %d)" % (path, depth, ctype))
            bpp = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        at += 12 + n
    raw, stride, rows = zlib.decompress(idat), bpp * width, []
    prev = bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, bpp, rows


def check_nothing_beyond(path, edge):
    """Nothing drawn right of column edge: the page rendered wider than it
    is (its viewBox widened, no background there), so that a legend that
    runs past the page's edge shows as pixels beyond it."""
    width, height, bpp, rows = png_rgba(path)
    for y, line in enumerate(rows):
        for x in range(int(edge), width):
            r, g, b = line[bpp * x:bpp * x + 3]
            a = line[bpp * x + 3] if bpp == 4 else 255
            if a > 0 and (r, g, b) != (255, 255, 255):
                fail("%s: pixel (%d, %d) right of the page's edge is drawn (%d, %d, %d, %d)"
                     % (path, x, y, r, g, b, a))


def check_pngs_differ(a, b):
    if open(a, "rb").read() == open(b, "rb").read():
        fail("%s and %s are the same image" % (a, b))


def check_obj_panels(obj, db, run, number):
    """The OBJ's structure, read as plain text: one object per type holding
    that type's panel groups; every full-cell FP panel one planar quad; no
    FP face whose fan holds a zero-area triangle."""
    con = sqlite3.connect(db)
    cells = {(i, j): (t, trimmed, d) for i, j, t, trimmed, d in con.execute(
        "SELECT i, j, type, trimmed, diameter FROM panels WHERE run = ? AND "
        "option = ?", (int(run), int(number)))}
    if not cells:
        fail("no stored panels for run %s option %s" % (run, number))
    verts, obj_type, group, faces = [], None, None, {}
    objects = []
    for line in open(obj):
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            verts.append(tuple(float(x) for x in w[1:4]))
        elif w[0] == "o":
            obj_type = w[1]
            objects.append(obj_type)
        elif w[0] == "g":
            group = w[1]
        elif w[0] == "usemtl":
            if w[1] != obj_type:
                fail("group %s is %s inside object %s" % (group, w[1], obj_type))
        elif w[0] == "f":
            faces.setdefault(group, []).append(
                [verts[int(c.split("/")[0]) - 1] for c in w[1:]])
    want = [t for t in ("FP", "SP", "DP") if any(c[0] == t for c in cells.values())]
    if objects != want:
        fail("objects %s, want one per type present: %s" % (objects, want))
    quads = zero = 0
    for (i, j), (t, trimmed, d) in cells.items():
        fs = faces.get("panel_%d_%d" % (i, j))
        if fs is None:
            fail("no group for panel %d %d" % (i, j))
        if t != "FP":
            continue
        if not trimmed:
            if len(fs) != 1 or len(fs[0]) != 4:
                fail("full-cell FP panel %d %d: %d faces of %s corners, want "
                     "one quad" % (i, j, len(fs), [len(f) for f in fs]))
            a, b, c, e = fs[0]
            u = [b[k] - a[k] for k in range(3)]
            v = [c[k] - a[k] for k in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                 u[0] * v[1] - u[1] * v[0]]
            ln = sum(x * x for x in n) ** 0.5
            off = abs(sum(n[k] * (e[k] - a[k]) for k in range(3))) / ln
            if off > 1e-9 * d:
                fail("FP quad %d %d is not planar: %.3g m" % (i, j, off))
            quads += 1
        for f in fs:
            total = polygon_area(f)
            for k in range(1, len(f) - 1):
                if polygon_area([f[0], f[k], f[k + 1]]) <= 1e-12 * total:
                    zero += 1
    if zero:
        fail("%d zero-area triangles in the fans of FP faces" % zero)
    print("%d full-cell FP quads, no zero-area triangle" % quads)


def main():
    check, args = sys.argv[1], sys.argv[2:]
    {"obj": check_obj, "obj_panels": check_obj_panels, "csv": check_csv, "json": check_json,
     "png": check_png, "pngs_differ": check_pngs_differ,
     "nothing_beyond": check_nothing_beyond}[check](*args)


if __name__ == "__main__":
    main()
