#!/usr/bin/env python3
"""ties_check.py: checks of tests/e2e/ties.sh against the SQLite file
itself (read with Python's sqlite3, which hands doubles over bit for bit)
and a brute force written here. Exits 0 when the check holds; otherwise
prints what is wrong on stderr and exits 1.

  order DB RUN SORT DESC FILE FORMAT
        the rows of `facet options --run RUN --sort SORT [--desc]`
        (FORMAT json or csv, in FILE) come in the order of the sort keys
        with ties as ties (docs/decisions.md, Ties): a key's values within a
        billionth of its range over the run (or of its largest magnitude)
        are one tie class (single linkage), and a tie falls to the next
        key, then to the option's number; every double is the stored one
  table DB RUN FILE
        the Table 2 that `facet optimize` printed (FILE) lists its options
        cheapest first, a cost tie falling to planarity, DP area, then No.
  exact-show DB RUN OPTION FILE
        every panel double of `facet show --json` (FILE) is the stored one
  exact-runs DB FILE
        every double of `facet runs --json` (FILE) is the stored one
  exact-schedule DB RUN OPTION FILE
        every panel double of `facet export --csv` (FILE) is the stored
        one (deviation_mm: the stored deviation times 1000), and the totals
        row's area and cost are the options row's
"""
import csv
import json
import math
import re
import sqlite3
import sys

from csv_names import column_of

TIE = 1e-9


def problem(text):
    print(text, file=sys.stderr)
    sys.exit(1)


def connect(path):
    db = sqlite3.connect("file:%s?mode=ro" % path, uri=True)
    db.row_factory = sqlite3.Row
    return db


def same_double(a, b):
    if a is None or b is None:
        return a is None and b is None
    return float(a) == float(b) and \
        math.copysign(1, float(a)) == math.copysign(1, float(b))


def tie_classes(values):
    """Tie class of each value: sorted, a gap over the tolerance starts a
    new class."""
    finite = [v for v in values if v is not None and math.isfinite(v)]
    if not finite:
        return list(range(len(values)))
    tol = TIE * max(max(finite) - min(finite), max(abs(v) for v in finite))
    order = sorted(range(len(values)), key=lambda i: values[i])
    cls, k, prev = [0] * len(values), 0, None
    for i in order:
        v = values[i]
        if prev is not None and not (v == prev or (
                math.isfinite(v) and math.isfinite(prev) and
                v - prev <= tol)):
            k += 1
        cls[i] = k
        prev = v
    return cls


def run_rows(db, run):
    rows = [dict(r) for r in db.execute(
        "SELECT * FROM options WHERE run = ? ORDER BY number", (run,))]
    for r in rows:  # NULL crowding of a ranked option is infinite
        if r["crowding"] is None:
            r["crowding"] = math.inf if (r["rank"] or 0) > 0 else 0.0
    return rows


def keyed_order(rows, keys, descending):
    classes = [tie_classes([r[k] for r in rows]) for k in keys]
    key = lambda i: tuple(c[i] for c in classes) + (rows[i]["number"],)
    order = sorted(range(len(rows)), key=key, reverse=descending)
    # every feasible option first, whatever the direction (issue 32 item
    # 19): a stable sort keeps each part's order
    order = sorted(order, key=lambda i: 0 if rows[i]["feasible"] == 1 else 1)
    return [rows[i]["number"] for i in order]


def check_order(path, run, sort, descending, listing, form):
    db = connect(path)
    rows = run_rows(db, run)
    want = keyed_order(rows, sort.split(","), descending == "1")
    if form == "json":
        got = json.load(open(listing))
    else:
        with open(listing, newline="") as f:
            reader = csv.reader(f)
            header = next(reader)
            # An empty field is NULL: crowding's infinity, or a column the
            # option has no value in (a single surface's module).
            # a header names its column with its unit (csv_names.py)
            got = [{column_of(k): (None if v == "" else float(v))
                    for k, v in zip(header, row)} for row in reader]
    numbers = [int(g["number"]) for g in got]
    if numbers != want[:len(numbers)] or not numbers:
        first = next((k for k, (a, b) in enumerate(zip(numbers, want))
                      if a != b), None)
        problem("order differs from the brute force at row %s: %s, want %s"
                % (first, numbers[:40], want[:40]))
    by_number = {r["number"]: r for r in rows}
    for g in got:
        r = by_number[int(g["number"])]
        for c, v in g.items():
            if c == "run" or (c == "crowding" and (v is None or
                                                   math.isinf(v))):
                continue
            if v is None and r[c] is None:
                continue
            if not same_double(v, r[c]):
                problem("option %s %s: printed %r, stored %r"
                        % (g["number"], c, v, r[c]))


def check_table(path, run, printed):
    db = connect(path)
    rows = run_rows(db, run)
    numbers = []
    for line in open(printed):
        m = re.match(r"^\s*(\d+) [* ] +[0-9.]+ ", line)
        if m:
            numbers.append(int(m.group(1)))
    if not numbers:
        problem("no table rows in %s" % printed)
    listed = [r for r in rows if r["number"] in set(numbers)]
    want = keyed_order(listed, ["cost", "planarity", "dp_area"], False)
    if numbers != want:
        problem("Table 2 order %s, want %s" % (numbers, want))


def check_show(path, run, option, show_file):
    db = connect(path)
    show = json.load(open(show_file))
    stored = {(r["i"], r["j"]): dict(r) for r in db.execute(
        "SELECT * FROM panels WHERE run = ? AND option = ?", (run, option))}
    if len(stored) != len(show["panels"]):
        problem("%d panels shown, %d stored" % (len(show["panels"]),
                                                len(stored)))
    column = {"eps": "eps", "area": "area", "deviation": "deviation",
              "k1": "k1", "k2": "k2", "K": "K", "H": "H",
              "p_dist": "p_dist", "diameter": "diameter", "cost": "cost",
              "corner_planarity": "corner_planarity"}
    checked = 0
    for p in show["panels"]:
        s = stored[(p["i"], p["j"])]
        for key, col in column.items():
            if key in p and not same_double(p[key], s[col]):
                problem("panel (%s, %s) %s: shown %r, stored %r"
                        % (p["i"], p["j"], key, p[key], s[col]))
            checked += key in p
    if checked == 0:
        problem("no panel value compared")


def check_runs(path, listing):
    db = connect(path)
    for r in json.load(open(listing)):
        s = dict(db.execute("SELECT * FROM runs WHERE id = ?",
                            (r["id"],)).fetchone())
        for key in ("hypervolume", "best_cost", "elapsed"):
            if not same_double(r[key], s[key]):
                problem("run %s %s: printed %r, stored %r"
                        % (r["id"], key, r[key], s[key]))


def check_schedule(path, run, option, schedule):
    db = connect(path)
    stored = {(r["i"], r["j"]): dict(r) for r in db.execute(
        "SELECT * FROM panels WHERE run = ? AND option = ?", (run, option))}
    row = dict(db.execute("SELECT * FROM options WHERE run = ? AND "
                          "number = ?", (run, option)).fetchone())
    columns = {"area_m2": "area", "k1": "k1", "k2": "k2", "K": "K",
               "H": "H", "price_usd_m2": "price", "cost_usd": "cost",
               "deviation_m": "deviation", "eps": "eps",
               "p_dist_m4": "p_dist", "diameter_m": "diameter"}
    with open(schedule, newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
    panels = rows
    if len(panels) != len(stored):
        problem("%d panels in the schedule, %d stored"
                % (len(panels), len(stored)))
    for p in panels:
        s = stored[(int(p["i"]), int(p["j"]))]
        for key, col in columns.items():
            if not same_double(float(p[key]), s[col]):
                problem("panel (%s, %s) %s: written %r, stored %r"
                        % (p["i"], p["j"], key, p[key], s[col]))
    with open(schedule[:-4] + "-totals.csv", newline="") as f:
        total = list(csv.DictReader(f))[0]
    for key, col in (("area_m2", "area"), ("cost_usd", "cost")):
        if not same_double(float(total[key]), row[col]):
            problem("totals %s %s, options row %r" % (key, total[key],
                                                      row[col]))


def main(argv):
    command, args = argv[1], argv[2:]
    if command == "order":
        check_order(args[0], int(args[1]), args[2], args[3], args[4], args[5])
    elif command == "table":
        check_table(args[0], int(args[1]), args[2])
    elif command == "exact-show":
        check_show(args[0], int(args[1]), int(args[2]), args[3])
    elif command == "exact-runs":
        check_runs(args[0], args[1])
    elif command == "exact-schedule":
        check_schedule(args[0], int(args[1]), int(args[2]), args[3])
    else:
        problem("unknown check %s" % command)


if __name__ == "__main__":
    main(sys.argv)
