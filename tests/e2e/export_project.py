"""export_project.py DB RUN OPTION SCHEDULE.csv TOTALS.csv: a building's
option exported as a schedule, read back against the store with Python's
csv and sqlite3 modules (not Facet). Prints one "ok - ..." or "not ok -
..." line per check."""
import csv
import sqlite3
import sys

db, run, option, schedule, totals_path = sys.argv[1:6]
run, option = int(run), int(option)
con = sqlite3.connect(db)
names = [r[0] for r in con.execute(
    "SELECT name FROM surfaces WHERE run=? ORDER BY surface", (run,))]
stored = {}
for r in con.execute(
        "SELECT surface, panels, fp_count, sp_count, dp_count, area, "
        "area_cost FROM option_surfaces WHERE run=? AND option=? "
        "ORDER BY surface", (run, option)):
    stored[names[r[0]]] = r[1:]
row = con.execute("SELECT panels, cost, area FROM options WHERE run=? AND "
                  "number=?", (run, option)).fetchone()

def check(name, ok, detail=""):
    print(("ok - " if ok else "not ok - ") + name +
          ("" if ok else "  (" + detail + ")"))

rows = list(csv.DictReader(open(schedule, newline="")))
check("the schedule lists every panel of the building",
      len(rows) == row[0], "%d rows, the option has %d panels" %
      (len(rows), row[0]))
check("a surface column", rows and "surface" in rows[0], "no surface column")
ids = [int(r["id"]) for r in rows]
check("panel IDs unique across the building, 1..N",
      ids == list(range(1, len(rows) + 1)), "ids %s..." % ids[:5])
keys = {(r["surface"], r["i"], r["j"]) for r in rows}
check("(surface, i, j) names one panel", len(keys) == len(rows),
      "%d distinct of %d" % (len(keys), len(rows)))
for name in names:
    mine = [r for r in rows if r.get("surface") == name]
    want = stored[name]
    counts = [sum(1 for r in mine if r["type"] == t)
              for t in ("FP", "SP", "DP")]
    area = sum(float(r["area_m2"]) for r in mine)
    cost = sum(float(r["cost_usd"]) for r in mine)
    check("surface %s: %d panels, FP/SP/DP %s as stored" % (name, want[0],
                                                          list(want[1:4])),
          len(mine) == want[0] and counts == list(want[1:4]),
          "%d panels, FP/SP/DP %s" % (len(mine), counts))
    check("surface %s: area %.6f m^2 as stored" % (name, want[4]),
          abs(area - want[4]) <= 1e-9 * max(1, want[4]), "%.12f" % area)
    check("surface %s: area cost %.2f USD as stored, to the cent" %
          (name, want[5]), abs(cost - want[5]) < 0.005, "%.6f" % cost)
t = list(csv.DictReader(open(totals_path, newline="")))
check("the totals: one row, the option's panels and cost to the cent",
      len(t) == 1 and int(t[0]["panels"]) == row[0] and
      abs(float(t[0]["cost_usd"]) - row[1]) < 0.005,
      "%s vs %s" % (t[:1], row))
