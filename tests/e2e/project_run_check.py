#!/usr/bin/env python3
"""project_run_check.py: checks of a project run against the module rule
and SQLite's own sums, independent of Facet's search (tests/e2e/project_run.sh).

  vectors DB RUN WMIN WMAX WSTEP HMIN HMAX HSTEP NTHRESHOLDS
      every module of the range mapped, from the surfaces' u and v lengths
      as stored, through nu = max(1, floor(L / w + 1/2)): the run holds one
      option per distinct grid vector and threshold, each option's surface
      rows hold its module's vector, and its modules count is how many
      modules give that vector.
  distinct DB RUN
      no two options of the run have the same grid vector and threshold
      (random and NSGA-II runs meet modules in any order).
  sums DB RUN
      the surface rows of every option add up to its building totals.
  same DB1 DB2
      the two files hold the same options and surface rows (run 1 each).
Prints one line per failure and exits 1 on any.
"""
import math
import sqlite3
import sys
from collections import Counter, defaultdict

failures = []


def fail(text):
    failures.append(text)
    print(text)


def values(lo, hi, step):
    n = int(math.floor((hi - lo) / step + 1e-9)) + 1
    return [round((lo + k * step) * 1e9) / 1e9 for k in range(n)]


def count_along(length, module):
    return max(1, int(math.floor(length / module + 0.5)))


def surface_rows(db, run):
    return db.execute("SELECT u_length, v_length FROM surfaces WHERE run=?"
                      " ORDER BY surface", (run,)).fetchall()


def option_vectors(db, run):
    vec = defaultdict(list)
    for option, nu, nv in db.execute(
            "SELECT option, nu, nv FROM option_surfaces WHERE run=?"
            " ORDER BY option, surface", (run,)):
        vec[option].append((nu, nv))
    return {k: tuple(v) for k, v in vec.items()}


def vectors(db, run, wmin, wmax, wstep, hmin, hmax, hstep, nthresholds):
    lengths = surface_rows(db, run)
    if not lengths:
        fail("run %d has no surfaces" % run)
        return
    modules = Counter()
    of_module = {}
    for w in values(wmin, wmax, wstep):
        for h in values(hmin, hmax, hstep):
            v = tuple((count_along(lu, w), count_along(lv, h))
                      for lu, lv in lengths)
            modules[v] += 1
            of_module[(w, h)] = v
    options = db.execute("SELECT number, module_w, module_h, modules,"
                         " threshold_mm FROM options WHERE run=?",
                         (run,)).fetchall()
    want = len(modules) * nthresholds
    if len(options) != want:
        fail("%d options, want %d distinct grid vectors x %d thresholds"
             % (len(options), len(modules), nthresholds))
    stored = option_vectors(db, run)
    seen = set()
    for number, w, h, count, t in options:
        key = min(of_module, key=lambda m: abs(m[0] - w) + abs(m[1] - h))
        if abs(key[0] - w) > 1e-9 or abs(key[1] - h) > 1e-9:
            fail("option %d: module %r x %r is not in the range" % (number, w, h))
            continue
        v = of_module[key]
        if stored.get(number) != v:
            fail("option %d (module %g x %g): surface grids %r, want %r"
                 % (number, w, h, stored.get(number), v))
        if count != modules[v]:
            fail("option %d: modules %r, want %d" % (number, count, modules[v]))
        first = min(m for m in of_module if of_module[m] == v)
        if key != first:
            fail("option %d: met as module %r, the first of its grid is %r"
                 % (number, key, first))
        seen.add((v, round(t, 6)))
    if len(seen) != len(options):
        fail("%d options but %d distinct (grids, threshold)" % (len(options), len(seen)))


def distinct(db, run):
    stored = option_vectors(db, run)
    keys = Counter()
    for number, t in db.execute("SELECT number, threshold_mm FROM options"
                                " WHERE run=?", (run,)):
        if number not in stored:
            fail("option %d has no surface rows" % number)
        keys[(stored.get(number), round(t, 6))] += 1
    for k, n in keys.items():
        if n > 1:
            fail("%d options share grids and threshold %r" % (n, k))


SUMMED = ["panels", "fp_count", "sp_count", "dp_count", "moulds", "sp_moulds",
          "dp_moulds", "gaps_over", "kinks_over", "sp_misfits"]
SUMMED_REAL = ["fp_area", "sp_area", "dp_area", "area", "planarity",
               "p_dist", "joint_length", "cost", "area_cost", "panel_cost",
               "joint_cost", "mould_cost"]
MAXED = ["max_deviation", "max_panel_area", "max_gap", "max_kink"]


def sums(db, run):
    n = db.execute("SELECT count(*) FROM options WHERE run=?", (run,)).fetchone()[0]
    if n == 0:
        fail("run %d has no options" % run)
    for c in SUMMED:
        bad = db.execute(
            "SELECT count(*) FROM options o WHERE run=?1 AND o.%s IS NOT"
            " (SELECT sum(s.%s) FROM option_surfaces s WHERE s.run=?1"
            " AND s.option=o.number)" % (c, c), (run,)).fetchone()[0]
        if bad:
            fail("%s: %d options whose surfaces do not add up" % (c, bad))
    for c in SUMMED_REAL:
        bad = db.execute(
            "SELECT count(*) FROM options o WHERE run=?1 AND abs(o.%s -"
            " (SELECT sum(s.%s) FROM option_surfaces s WHERE s.run=?1"
            " AND s.option=o.number)) > 1e-9 * max(1, abs(o.%s))"
            % (c, c, c), (run,)).fetchone()[0]
        if bad:
            fail("%s: %d options whose surfaces do not add up" % (c, bad))
    for c in MAXED:
        bad = db.execute(
            "SELECT count(*) FROM options o WHERE run=?1 AND o.%s IS NOT"
            " (SELECT max(s.%s) FROM option_surfaces s WHERE s.run=?1"
            " AND s.option=o.number)" % (c, c), (run,)).fetchone()[0]
        if bad:
            fail("%s: %d options whose largest surface value is not theirs"
                 % (c, bad))
    bad = db.execute(
        "SELECT count(*) FROM options o WHERE run=?1 AND o.moulds >"
        " (SELECT sum(s.moulds_used) FROM option_surfaces s WHERE s.run=?1"
        " AND s.option=o.number)", (run,)).fetchone()[0]
    if bad:
        fail("%d options with more moulds than their surfaces use" % bad)


def dump(path):
    db = sqlite3.connect(path)
    options = db.execute("SELECT * FROM options WHERE run=1 ORDER BY number").fetchall()
    surfaces = db.execute("SELECT * FROM option_surfaces WHERE run=1"
                          " ORDER BY option, surface").fetchall()
    return options, surfaces


def same(a, b):
    oa, sa = dump(a)
    ob, sb = dump(b)
    if oa != ob:
        fail("options differ: %d and %d rows, first difference %r"
             % (len(oa), len(ob), next(((x, y) for x, y in zip(oa, ob) if x != y), None)))
    if sa != sb:
        fail("option_surfaces differ: %d and %d rows" % (len(sa), len(sb)))


def main():
    what = sys.argv[1]
    if what == "same":
        same(sys.argv[2], sys.argv[3])
    else:
        db = sqlite3.connect(sys.argv[2])
        run = int(sys.argv[3])
        if what == "vectors":
            a = [float(x) for x in sys.argv[4:10]]
            vectors(db, run, *a, int(sys.argv[10]))
        elif what == "distinct":
            distinct(db, run)
        elif what == "sums":
            sums(db, run)
        else:
            fail("unknown check " + what)
    sys.exit(1 if failures else 0)


main()
