#!/usr/bin/env python3
"""optimize_check.py: independent checks of a Facet result store, for
tests/e2e/optimize.sh. Each subcommand reads the database with Python's
sqlite3 (read-only) and exits 0 when the check holds; otherwise it prints
what is wrong on stderr and exits 1.

  ranks DB RUN              ranks, knee, pareto view, hypervolume, summary
                            and stored panels against brute force
  same DB1 RUN1 DB2 RUN2    the option rows (every column but run) are equal
  differ DB1 RUN1 DB2 RUN2  they are not
  summary DB1 RUN1 DB2 RUN2 the runs' results (options, pareto_options,
                            knee, best_cost, hypervolume) are equal
  listing DB FORMAT FILE SQL  the rows of `facet options` (FORMAT json or
                            csv, in FILE) are the rows of SQL, in order,
                            every column the same double as stored
  show DB RUN OPTION SHOW.json CLASSIFY.json
                            `facet show --json` of one option has the keys
                            of classify --json, its totals are the options
                            row and classify's, its panels classify's (to
                            1e-9 of each panel's scale)
  show-surface SHOW.json CLASSIFY.json
                            and its surface is classify's
"""
import csv
import json
import math
import sqlite3
import sys

from csv_names import column_of, csv_name

# Every column of the options table but run (which comes first), in the
# table's order: what --json and --csv must carry (docs/store.md).
COLUMNS = ["number", "generation", "nu", "nv", "threshold_mm", "panels",
           "fp_count", "sp_count", "dp_count", "fp_area", "sp_area",
           "dp_area", "area", "fp_cost", "sp_cost", "dp_cost", "cost",
           "planarity", "max_deviation", "max_panel_area", "p_dist",
           "feasible"] + [c + s for c in (
               "convex_feature_curve", "saddle", "concave_feature_curve",
               "ruled_convex", "flat", "ruled_concave", "convex_round",
               "concave_round") for s in ("_count", "_area")] + [
           "rank", "crowding", "knee", "joint_length", "moulds", "sp_moulds",
           "dp_moulds", "largest_family", "single_moulds", "area_cost",
           "panel_cost", "joint_cost", "mould_cost", "max_gap", "mean_gap",
           "max_kink", "mean_kink", "gaps_over", "kinks_over", "sp_misfits",
           "sp_fitted", "module_w", "module_h", "modules",
           "sp_min_radius", "min_panel_area", "min_panel_width", "slivers",
           "planarized", "closeness_reached", "closeness_mean",
           "planarity_reached", "planar_over", "seams", "seam_length",
           "seam_max_gap", "seam_max_kink", "seam_max_crease",
           "seam_gaps_over", "seam_kinks_over"]


def connect(path):
    db = sqlite3.connect("file:%s?mode=ro" % path, uri=True)
    db.row_factory = sqlite3.Row
    return db


def problem(text):
    print(text, file=sys.stderr)
    sys.exit(1)


def exact(a, b):
    """The same double (Facet prints every double so that it reads back
    exactly), or both null."""
    if a is None or b is None:
        return a is None and b is None
    return a == b and math.copysign(1, a) == math.copysign(1, b)


def options_of(db, run):
    rows = [dict(r) for r in db.execute(
        "SELECT * FROM options WHERE run = ? ORDER BY number", (run,))]
    if not rows:
        problem("run %s has no options" % run)
    return rows


# --- ranks -----------------------------------------------------------------

def objective_values(row, objectives):
    values = []
    for name in objectives:
        if name.startswith("max:"):
            values.append(-row[name[4:]])
        else:
            values.append(row[name[4:] if name.startswith("min:") else name])
    return values


TIE = 1e-9


def tolerances(points):
    """Values of an objective within a billionth of its range over the
    run's options, or of its largest magnitude, are equal (docs/decisions.md,
    Ties)."""
    tol = []
    for j in range(len(points[0]) if points else 0):
        v = [p[j] for p in points]
        tol.append(TIE * max(max(v) - min(v), max(abs(x) for x in v)))
    return tol


def merge_ties(points):
    """Each value replaced by the lowest of its tie class: the values of
    an objective sorted, a gap over its tolerance starts a new class."""
    tol = tolerances(points)
    merged = [list(p) for p in points]
    for j, t in enumerate(tol):
        order = sorted(range(len(points)), key=lambda i: points[i][j])
        low = None
        for k, i in enumerate(order):
            v = points[i][j]
            if k == 0 or not v - points[order[k - 1]][j] <= t:
                low = v
            merged[i][j] = low
    return merged


def dominates(a, b, tol):
    return all(x <= y + t for x, y, t in zip(a, b, tol)) and \
        any(x < y - t for x, y, t in zip(a, b, tol))


def brute_ranks(points, violation):
    """Non-dominated fronts by peeling, with Deb's constraint-domination:
    feasible before infeasible, infeasible by smaller violation; feasible
    ones by dominance with ties as ties (the pairwise rule)."""
    n = len(points)
    tol = tolerances(points)

    def beats(i, j):
        if violation[i] == 0 and violation[j] > 0:
            return True
        if violation[i] > 0 and violation[j] > 0:
            return violation[i] < violation[j]
        if violation[i] == 0 and violation[j] == 0:
            return dominates(points[i], points[j], tol)
        return False

    beaten_by = [[j for j in range(n) if j != i and beats(j, i)]
                 for i in range(n)]
    rank = [0] * n
    remaining = set(range(n))
    front = 0
    while remaining:
        front += 1
        current = [i for i in remaining
                   if not any(j in remaining for j in beaten_by[i])]
        if not current:
            problem("domination has a cycle")
        for i in current:
            rank[i] = front
        remaining -= set(current)
    return rank


def hypervolume_slices(points, reference):
    """Exact hypervolume by slicing: along the last axis, between
    consecutive values, the (m-1)-dimensional volume of the points at or
    below the slice, down to lengths on one axis."""
    points = [p for p in points if all(x < r for x, r in zip(p, reference))]
    if not points:
        return 0.0
    if len(reference) == 1:
        return reference[0] - min(p[0] for p in points)
    levels = sorted(set(p[-1] for p in points)) + [reference[-1]]
    volume = 0.0
    for low, high in zip(levels, levels[1:]):
        below = [p[:-1] for p in points if p[-1] <= low]
        volume += (high - low) * hypervolume_slices(below, reference[:-1])
    return volume


def check_ranks(path, run):
    db = connect(path)
    info = db.execute("SELECT * FROM runs WHERE id = ?", (run,)).fetchone()
    if info is None:
        problem("no run %s" % run)
    objectives = info["objectives"].split(",")
    limit = info["max_panel_area_limit"]
    rows = options_of(db, run)
    points = [objective_values(r, objectives) for r in rows]
    violation = [max(0.0, r["max_panel_area"] - limit) for r in rows]
    bad = [r["number"] for r, v in zip(rows, violation)
           if bool(r["feasible"]) != (v == 0)]
    if bad:
        problem("feasible disagrees with max_panel_area <= %g for options %s"
                % (limit, bad[:10]))

    want = brute_ranks(points, violation)
    wrong = [(r["number"], r["rank"], w) for r, w in zip(rows, want)
             if r["rank"] != w]
    if wrong:
        problem("%d of %d ranks differ from brute force (number, stored, "
                "brute): %s" % (len(wrong), len(rows), wrong[:10]))

    # The knee: one option, rank 1, closest to the ideal point of the
    # first front normalised by its own range (ties, to 1e-9 in normalised
    # units: the lowest number). It and the hypervolume see values equal
    # but for rounding as equal: an objective whose values all tie has no
    # range.
    first = [i for i, r in enumerate(rows) if r["rank"] == 1]
    m = len(objectives)
    points = merge_ties(points)
    low = [min(points[i][j] for i in first) for j in range(m)]
    high = [max(points[i][j] for i in first) for j in range(m)]

    def distance(i):
        return sum(((points[i][j] - low[j]) / (high[j] - low[j])
                    if high[j] > low[j] else 0.0) ** 2 for j in range(m))
    knees = [r["number"] for r in rows if r["knee"]]
    best = min(distance(i) for i in first)
    closest = [rows[i]["number"] for i in first if distance(i) <= best + TIE]
    if knees != [closest[0]] or info["knee"] != closest[0]:
        problem("knee: options marked %s, runs.knee %s; brute force %s "
                "(distance %g)" % (knees, info["knee"], closest[0], best))

    view = sorted(r[0] for r in db.execute(
        "SELECT number FROM pareto WHERE run = ?", (run,)))
    if view != sorted(rows[i]["number"] for i in first):
        problem("the pareto view is not the rank 1 options")
    if info["pareto_options"] != len(first):
        problem("runs.pareto_options %s, rank 1 options %d"
                % (info["pareto_options"], len(first)))
    feasible = [r["cost"] for r in rows if r["feasible"]]
    if (info["best_cost"] is None) != (not feasible) or (
            feasible and info["best_cost"] != min(feasible)):
        problem("runs.best_cost %s, cheapest feasible %s"
                % (info["best_cost"], min(feasible) if feasible else None))

    # Hypervolume of the feasible first front, normalised by the feasible
    # options' ideal and nadir, reference 1.1 on every axis.
    if feasible:
        fi = [i for i, v in enumerate(violation) if v == 0]
        ideal = [min(points[i][j] for i in fi) for j in range(m)]
        nadir = [max(points[i][j] for i in fi) for j in range(m)]
        front = [[(points[i][j] - ideal[j]) / (nadir[j] - ideal[j])
                  if nadir[j] > ideal[j] else 0.0 for j in range(m)]
                 for i in first if violation[i] == 0]
        hv = hypervolume_slices(front, [1.1] * m)
        if info["hypervolume"] is None or not math.isclose(
                info["hypervolume"], hv, rel_tol=1e-9, abs_tol=1e-12):
            problem("hypervolume %s, brute force %r" % (info["hypervolume"], hv))
    elif info["hypervolume"] is not None:
        problem("hypervolume %s with no feasible option" % info["hypervolume"])

    # The panels of the Pareto options are stored, one row per panel: all
    # of them up to the run's budget, max(16, options / 40); of a larger
    # front the knee first, then the largest crowding distance (the ends,
    # at infinity, stored as NULL, first), then the lowest number.
    budget = max(16, len(rows) // 40)
    order = sorted(first, key=lambda i: (
        -rows[i]["knee"], rows[i]["crowding"] is not None,
        -(rows[i]["crowding"] or 0), rows[i]["number"]))
    kept = order[:budget]
    stored = sorted(o for (o,) in db.execute(
        "SELECT option FROM panel_sets s JOIN options o ON o.run = s.run "
        "AND o.number = s.option WHERE s.run = ? AND o.rank = 1", (run,)))
    if stored != sorted(rows[i]["number"] for i in kept):
        problem("Pareto options with panels %s, want %s (budget %d of %d)"
                % (stored, sorted(rows[i]["number"] for i in kept), budget,
                   len(first)))
    for i in kept:
        r = rows[i]
        sets = db.execute("SELECT nu, nv FROM panel_sets WHERE run = ? AND "
                          "option = ?", (run, r["number"])).fetchall()
        count = db.execute("SELECT count(*) FROM panels WHERE run = ? AND "
                           "option = ?", (run, r["number"])).fetchone()[0]
        if [tuple(s) for s in sets] != [(r["nu"], r["nv"])] or \
                count != r["panels"]:
            problem("Pareto option %d: panel_sets %s, %d panels stored of %d"
                    % (r["number"], [tuple(s) for s in sets], count,
                       r["panels"]))


# --- comparing runs --------------------------------------------------------

def rows_without_run(path, run):
    db = connect(path)
    return [tuple(r[c] for c in COLUMNS) for r in options_of(db, run)]


def check_same(a, ra, b, rb, want_same):
    x, y = rows_without_run(a, ra), rows_without_run(b, rb)
    same = x == y
    if same != want_same:
        if want_same:
            diff = [(p, q) for p, q in zip(x, y) if p != q]
            problem("%d and %d options; %d rows differ, first: %s"
                    % (len(x), len(y), len(diff), diff[:1]))
        problem("the options are identical (%d rows)" % len(x))


def check_summary(a, ra, b, rb):
    keys = ["options", "pareto_options", "knee", "best_cost", "hypervolume",
            "status"]
    x = connect(a).execute("SELECT * FROM runs WHERE id = ?", (ra,)).fetchone()
    y = connect(b).execute("SELECT * FROM runs WHERE id = ?", (rb,)).fetchone()
    diff = [(k, x[k], y[k]) for k in keys if x[k] != y[k]]
    if diff:
        problem("the runs differ: %s" % diff)


# --- facet options against SQL --------------------------------------------

def check_listing(path, form, listing, sql):
    db = connect(path)
    want = [dict(r) for r in db.execute(sql)]
    if form == "json":
        got = json.load(open(listing))
    else:
        with open(listing, newline="") as f:
            reader = csv.reader(f)
            header = next(reader)
            # the columns with their units (csv_names.py)
            if header != ["run"] + [csv_name(c) for c in COLUMNS]:
                problem("csv header %s" % header)
            got = [{column_of(k): (None if v == "" else float(v))
                    for k, v in zip(header, row)} for row in reader]
    if len(got) != len(want):
        problem("facet options gave %d rows, SQL %d" % (len(got), len(want)))
    for k, (g, w) in enumerate(zip(got, want)):
        if (g.get("run"), g.get("number")) != (w["run"], w["number"]):
            problem("row %d is run %s option %s, SQL says run %s option %s"
                    % (k, g.get("run"), g.get("number"), w["run"],
                       w["number"]))
        if set(g) != set(["run"] + COLUMNS):
            problem("row %d has the keys %s" % (k, sorted(g)))
        for c in ["run"] + COLUMNS:
            if c == "crowding" and w[c] is None:
                continue  # NULL (a front's end): optimize.sh checks it apart
            if not exact(g[c], w[c]):
                problem("row %d (option %s) %s: %r, SQL %r"
                        % (k, w["number"], c, g[c], w[c]))


# --- facet show --json -------------------------------------------------------

def keys_of(j):
    return {
        "top": sorted(j),
        "surface": sorted(j["surface"]),
        "grid": sorted(j["grid"]),
        "prices": sorted(j["prices"]),
        "totals": sorted(j["totals"]),
        "classes": sorted(j["totals"]["classes"]),
        "class": sorted(next(iter(j["totals"]["classes"].values()))),
        "panel": sorted(j["panels"][0]),
    }


def check_show(path, run, number, show_file, classify_file):
    show, classify = json.load(open(show_file)), json.load(open(classify_file))
    ks, kc = keys_of(show), keys_of(classify)
    if ks != kc:
        problem("keys differ from classify --json: %s"
                % {k: (ks[k], kc[k]) for k in ks if ks[k] != kc[k]})
    row = dict(connect(path).execute(
        "SELECT * FROM options WHERE run = ? AND number = ?",
        (run, number)).fetchone())
    t = show["totals"]
    if len(show["panels"]) != t["panels"] or t["panels"] != row["panels"]:
        problem("%d panels listed, totals.panels %d, options row %d"
                % (len(show["panels"]), t["panels"], row["panels"]))
    if show["grid"] != {"nu": row["nu"], "nv": row["nv"]} or \
            show["threshold_mm"] != row["threshold_mm"]:
        problem("grid %s threshold %s, options row %dx%d %s"
                % (show["grid"], show["threshold_mm"], row["nu"], row["nv"],
                   row["threshold_mm"]))
    # The options row may come from the run's lattice and show's panels
    # from the option's own grid: equal to 1e-9 (see below).
    for c in ["panels", "fp_count", "sp_count", "dp_count", "fp_area",
              "sp_area", "dp_area", "area", "cost", "planarity",
              "max_deviation", "max_panel_area", "p_dist", "feasible"]:
        if not near(float(t[c]), float(row[c]), TOTAL_SCALE.get(c, 0)):
            problem("totals.%s %r, options row %r" % (c, t[c], row[c]))
    for name, v in t["classes"].items():
        if v["count"] != row[name + "_count"] or \
                not near(v["area"], row[name + "_area"], t["area"]):
            problem("class %s: %s, options row %s, %s" % (
                name, v, row[name + "_count"], row[name + "_area"]))
    # A run takes its panels from the lattice of its space's lines,
    # classify from its one grid: the same panels, each measure to 1e-9 of
    # its panel's scale (a flat panel deviates by 0 or by 1e-18 m), the
    # same types and classes.
    if len(show["panels"]) != len(classify["panels"]):
        problem("%d panels, classify %d"
                % (len(show["panels"]), len(classify["panels"])))
    for a, b in zip(show["panels"], classify["panels"]):
        for k in a:
            if isinstance(a[k], float) or isinstance(b[k], float):
                same = near(a[k], b[k], panel_scale(k, b))
            else:
                same = a[k] == b[k]
            if not same:
                problem("panel (%s, %s) %s: %r, classify %r"
                        % (a["i"], a["j"], k, a[k], b[k]))
    ts, tc = show["totals"], classify["totals"]
    for k in tc:
        if k == "classes":
            same = all(ts[k][c]["count"] == v["count"] and
                       near(ts[k][c]["area"], v["area"], tc["area"])
                       for c, v in tc[k].items())
        elif isinstance(tc[k], float) or isinstance(ts[k], float):
            same = near(ts[k], tc[k], TOTAL_SCALE.get(k, 0))
        else:
            same = ts[k] == tc[k]
        if not same:
            problem("totals.%s %r, classify --json of the same grid %r"
                    % (k, ts[k], tc[k]))


# What a total is judged against when it is near zero: a millimetre of
# deviation (m), a millimetre squared over a square metre of P_dist (m^4),
# a metre of gap (in mm: panels equal to 1e-9 of their metres have gaps
# equal to a micrometre's thousandth), a radian of kink (in degrees).
TOTAL_SCALE = {"planarity": 1e-3, "max_deviation": 1e-3, "p_dist": 1e-6,
               "max_gap": 1e3, "mean_gap": 1e3, "max_kink": 57.3,
               "mean_kink": 57.3}


def near(a, b, scale):
    """Equal to 1e-9 of the larger of the two or of scale."""
    return abs(a - b) <= 1e-9 * max(abs(a), abs(b), scale) + 1e-300


def panel_scale(key, panel):
    """What a panel's measure is judged against: its size for lengths, its
    area for areas, its largest principal curvature for curvatures."""
    size, area = panel["diameter"], panel["area"]
    k = max(abs(panel["k1"]), abs(panel["k2"]))
    return {"deviation": size, "diameter": size, "corner_planarity": size,
            "area": area, "p_dist": area * size * size,
            "cost": panel["cost"], "k1": k, "k2": k, "H": k, "K": k * k,
            "eps": k, "sp_deviation": size, "worst_gap": 1e3 * size,
            "worst_kink": 57.3}.get(key, 0)


def check_show_surface(show_file, classify_file):
    show, classify = json.load(open(show_file)), json.load(open(classify_file))
    if show["surface"] != classify["surface"]:
        problem("surface %s, classify --json says %s"
                % (show["surface"], classify["surface"]))


def main(argv):
    command, args = argv[1], argv[2:]
    if command == "ranks":
        check_ranks(args[0], int(args[1]))
    elif command in ("same", "differ"):
        check_same(args[0], int(args[1]), args[2], int(args[3]),
                   command == "same")
    elif command == "summary":
        check_summary(args[0], int(args[1]), args[2], int(args[3]))
    elif command == "listing":
        check_listing(args[0], args[1], args[2], args[3])
    elif command == "show":
        check_show(args[0], int(args[1]), int(args[2]), args[3], args[4])
    elif command == "show-surface":
        check_show_surface(args[0], args[1])
    else:
        problem("unknown check %s" % command)


if __name__ == "__main__":
    main(sys.argv)
