"""export_xlsx.py DB RUN OPTION BOOK.xlsx [RADIUS]: an option's XLSX schedule read
back by openpyxl (not Facet) against the store read by Python's sqlite3.
Prints one "ok - ..." or "not ok - ..." line per check.

The truth: a single surface's option has its panels in the panels table,
panel by panel; a building's has each surface's counts, areas and costs
in option_surfaces; both have their totals in the options row, in the
units docs/store.md gives (max_deviation in m, shown in mm)."""
import math
import sqlite3
import sys

import openpyxl

db, run, option, book = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), \
    sys.argv[4]
con = sqlite3.connect(db)
con.row_factory = sqlite3.Row
wb = openpyxl.load_workbook(book)
failed = 0


def check(name, ok, detail=""):
    global failed
    failed += not ok
    print(("ok - " if ok else "not ok - ") + name +
          ("" if ok else "  (" + str(detail)[:300] + ")"))


def close(a, b, rel=1e-12, cent=False):
    if a is None or b is None:
        return a is None and b is None
    if cent:
        return abs(a - b) < 0.005
    return abs(a - b) <= rel * max(1.0, abs(a), abs(b))


building = con.execute("SELECT count(*) FROM surfaces WHERE run=?",
                       (run,)).fetchone()[0] > 0
row = con.execute("SELECT * FROM options WHERE run=? AND number=?",
                  (run, option)).fetchone()
# A building's run that found its seams (a welding tolerance) has them.
welded = con.execute("SELECT weld_mm IS NOT NULL FROM runs WHERE id=?",
                     (run,)).fetchone()[0]
want = (["panels", "moulds", "surfaces"] + (["seams"] if welded else []) +
        ["totals"]) if building else ["panels", "moulds", "totals"]
check("sheets %s" % want, wb.sheetnames == want, wb.sheetnames)

# Every sheet: its header frozen, its numbers numbers.
TEXT = {"surface", "type as classed", "type as built", "class", "type",
        "SP fitted surface", "surface a", "surface b",
        "quantity", "label", "unit"}
for ws in wb:
    check("%s: the header row is frozen" % ws.title, ws.freeze_panes == "A2",
          ws.freeze_panes)
    header = [c.value for c in ws[1]]
    bad = []
    for r in ws.iter_rows(min_row=2):
        for h, c in zip(header, r):
            if c.value is None or h in TEXT:
                continue
            if c.data_type != "n" or isinstance(c.value, str) or \
                    c.number_format == "General":
                bad.append((ws.title, c.coordinate, c.value, c.data_type,
                            c.number_format))
    check("%s: every number is a number cell with a number format" %
          ws.title, not bad, bad[:3])
    units = [h for h in header if "(" in h]
    check("%s: units in the header row" % ws.title,
          units or "unit" in header, header)


def table(ws):
    header = [c.value for c in ws[1]]
    return [dict(zip(header, r)) for r in
            ws.iter_rows(min_row=2, values_only=True)]


panels = table(wb["panels"])
check("panels: one row per panel (%d)" % row["panels"],
      len(panels) == row["panels"], len(panels))
check("panels: ids 1..N", [p["id"] for p in panels] ==
      list(range(1, len(panels) + 1)))
if not building:
    stored = {(r["i"], r["j"]): r for r in con.execute(
        "SELECT * FROM panels WHERE run=? AND option=?", (run, option))}
    check("panels: the store holds the option's panels",
          len(stored) == len(panels), len(stored))
    bad = []
    for p in panels:
        s = stored.get((p["column i"], p["row j"]))
        if s is None or p["type as classed"] != s["type"] or \
                p["type as built"] != s["built_type"] or \
                p["class"] != s["class"] or \
                not close(p["area (m^2)"], s["area"]) or \
                not close(p["cost (USD)"], s["cost"], cent=True) or \
                not close(p["deviation (mm)"], s["deviation"] * 1000,
                          rel=1e-9) or \
                p["mould family"] != s["mould_family"]:
            bad.append((p, dict(s) if s else None))
    check("panels: every panel's type, class, area, deviation, mould and "
          "cost as stored", not bad, bad[:1])
else:
    names = [r[0] for r in con.execute(
        "SELECT name FROM surfaces WHERE run=? ORDER BY surface", (run,))]
    rows = con.execute("SELECT * FROM option_surfaces WHERE run=? AND "
                       "option=? ORDER BY surface", (run, option)).fetchall()
    bad = []
    for name, s in zip(names, rows):
        mine = [p for p in panels if p["surface"] == name]
        for t in ("FP", "SP", "DP"):
            of = [p for p in mine if p["type as built"] == t]
            if len(of) != s[t.lower() + "_count"] or not close(
                    sum(p["area (m^2)"] for p in of), s[t.lower() + "_area"],
                    rel=1e-9):
                bad.append((name, t, len(of), s[t.lower() + "_count"]))
        if not close(sum(p["cost (USD)"] for p in mine), s["area_cost"],
                     cent=True):
            bad.append((name, "cost", sum(p["cost (USD)"] for p in mine),
                        s["area_cost"]))
    check("panels: each surface's panels, by type as built, count and area "
          "as option_surfaces holds them, their cost to the cent", not bad,
          bad[:3])
    surfaces = table(wb["surfaces"])
    check("surfaces: one row per surface (%d)" % len(names),
          [s["surface"] for s in surfaces] == names,
          [s["surface"] for s in surfaces])
    bad = [(s["surface"], s["panels"], r["panels"], s["cost (USD)"],
            r["cost"]) for s, r in zip(surfaces, rows)
           if s["panels"] != r["panels"] or s["U panels"] != r["nu"] or
           s["V panels"] != r["nv"] or
           not close(s["cost (USD)"], r["cost"], cent=True) or
           not close(s["area (m^2)"], r["area"])]
    check("surfaces: grids, panels, areas and costs as stored", not bad,
          bad[:3])
    # The example plane is a 20 m x 15 m rectangle (facet example): each
    # of its panels is 20/U m along i and 15/V m across, by construction.
    plane = [s for s in surfaces if s["surface"] == "plane"]
    if plane:
        u, v = plane[0]["U panels"], plane[0]["V panels"]
        mine = [p for p in panels if p["surface"] == "plane"]
        bad = [p for p in mine if not (
            close(p["size along i (m)"], 20 / u, rel=1e-9) and
            close(p["size across i (m)"], 15 / v, rel=1e-9))]
        check("panels: the plane's %d panels are %g m x %g m" %
              (len(mine), 20 / u, 15 / v), mine and not bad,
              [(p["size along i (m)"], p["size across i (m)"])
               for p in bad[:3]])

# The SP bending radius, where a panel is built on a fitted cylinder or
# cone: as many as the option's fitted SP panels, the least of them the
# option's sp_min_radius (the fits are made again for the schedule: the
# same to sp_fit.h's precision).
radii = [p["SP bending radius (m)"] for p in panels
         if p["SP bending radius (m)"] is not None]
check("panels: a bending radius for each of the %s SP panels built on a "
      "fit" % row["sp_fitted"], len(radii) == row["sp_fitted"] and
      all(p["type as built"] == "SP" for p in panels
          if p["SP bending radius (m)"] is not None), len(radii))
if radii:
    check("panels: the least bending radius is sp_min_radius (%s m)" %
          row["sp_min_radius"], close(min(radii), row["sp_min_radius"],
                                      rel=1e-9),
          (min(radii), row["sp_min_radius"]))
if len(sys.argv) > 5:
    # A cylinder of known radius: every panel bent to it, within the
    # facets' sag (under 1 %).
    r = float(sys.argv[5])
    check("panels: every bending radius within 1 %% of the cylinder's %g m"
          % r, radii and all(abs(x - r) <= 0.01 * r for x in radii),
          radii[:5])

moulds = table(wb["moulds"])
check("moulds: one row per family (%s)" % row["moulds"],
      len(moulds) == row["moulds"], len(moulds))
by_id = {p["id"]: p for p in panels}
members = {}
for p in panels:
    if p["mould family"] is not None:
        members.setdefault(p["mould family"], []).append(p["id"])
bad = [m for m in moulds if members.get(m["mould family"]) is None or
       m["members"] != len(members[m["mould family"]]) or
       m["representative panel id"] != members[m["mould family"]][0] or
       not m["type"].startswith(by_id[m["representative panel id"]]
                                ["type as built"])]
check("moulds: members and representative as the panels name them",
      not bad and len(members) == len(moulds), bad[:3])
check("moulds: their costs add up to the mould cost to the cent",
      close(sum(m["cost (USD)"] for m in moulds), row["mould_cost"],
            cent=True), (sum(m["cost (USD)"] for m in moulds),
                         row["mould_cost"]))

totals = table(wb["totals"])
# Stored in m, shown in mm (docs/store.md); the rest are stored as shown
# (the seams' gap in mm and angles in degrees since schema v16, as the
# option's own gaps and kinks).
SCALE = {"max_deviation": 1000, "min_panel_width": 1000}
bad = []
for t in totals:
    name = t["quantity"]
    stored = row[name]
    shown = t["value"]
    value = None if shown is None else shown / SCALE.get(name, 1)
    cent = t["unit"] == "USD"
    if not close(value, stored, rel=1e-12, cent=cent):
        bad.append((name, value, stored))
check("totals: %d quantities, each as the options row holds it (USD to "
      "the cent)" % len(totals), len(totals) >= 40 and not bad, bad[:5])
for name in ("cost", "area", "panels", "dp_area", "mould_cost"):
    check("totals: %s is there" % name,
          any(t["quantity"] == name for t in totals))
sys.exit(1 if failed else 0)
