#!/usr/bin/env bash
# End-to-end: facet curvature, the vertex curvature a user holds against
# their CAD's analysis, against the formulas of the generated examples
# (a sphere of R = 20 m: k1 = k2 = -1/20; a cylinder of R = 10 m: -1/10
# across, 0 along), in its CSV, its JSON and its errors.
# layers: core cli
. "$(dirname "$0")/lib.sh"

"$FACET" example dome --res 40 -o "$WORK/dome.obj" || exit 1
"$FACET" example cylinder --res 40 -o "$WORK/cyl.obj" || exit 1

expect "curvature --csv" 0 "$FACET" curvature "$WORK/dome.obj" --csv "$WORK/dome.csv"
same "csv header" "$(head -n 1 "$WORK/dome.csv")" "v,x,y,z,k1,k2,K,H,normal_x,normal_y,normal_z,boundary"
same "csv: one row per vertex (41 x 41)" "$(($(wc -l <"$WORK/dome.csv") - 1))" 1681
if /usr/bin/python3 - "$WORK/dome.csv" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for r in rows:
    p = [float(r[k]) for k in "xyz"]
    n = [float(r["normal_" + k]) for k in "xyz"]
    k1, k2 = float(r["k1"]), float(r["k2"])
    # The dome is a cap of the sphere of radius 20 m centred 20 m under
    # its apex (example.c): the outward normal is (p - c) / 20.
    c = [0, 0, max(float(q["z"]) for q in rows) - 20]
    d = [p[i] - c[i] for i in range(3)]
    assert abs(math.sqrt(sum(x * x for x in d)) - 20) < 1e-6, p
    assert sum(d[i] / 20 * n[i] for i in range(3)) > 0.99999, (p, n)
    # Facet's estimate, not the estimator's accuracy (test_curvature):
    # within 2 % on the boundary of this coarse mesh, 0.2 % inside.
    tol = 2e-2 if r["boundary"] == "1" else 2e-3
    assert abs(k1 + 0.05) < tol * 0.05 and abs(k2 + 0.05) < tol * 0.05, (p, k1, k2)
    assert float(r["K"]) == k1 * k2 and float(r["H"]) == (k1 + k2) / 2
PY
then pass "csv: sphere curvature -1/R and outward normals at every vertex"; else fail "csv: sphere curvature -1/R and outward normals at every vertex"; fi

expect "curvature --json" 0 "$FACET" curvature "$WORK/cyl.obj" --json
json_check "json: documented keys" \
    'all(k in j for k in ["file","units","flip_normals","vertices"]) and all(all(k in v for k in ["v","position","k1","k2","K","H","normal","boundary"]) for v in j["vertices"])'
json_check "json: cylinder k2 = -1/R across, k1 = 0 along (interior)" \
    'all(abs(v["k2"]+0.1) < 1e-3 and abs(v["k1"]) < 1e-4 for v in j["vertices"] if not v["boundary"])'
json_check "json: v is the OBJ index, 1-based" 'sorted(v["v"] for v in j["vertices"]) == list(range(1, 41*41+1))'

expect "curvature --flip-normals" 0 "$FACET" curvature "$WORK/cyl.obj" --json --flip-normals
json_check "flipped: every sign reversed (k1 = 1/R across)" \
    'j["flip_normals"] and all(abs(v["k1"]-0.1) < 1e-3 for v in j["vertices"] if not v["boundary"])'

expect "summary without --csv or --json" 0 "$FACET" curvature "$WORK/dome.obj"
stdout_has "summary: inside and boundary ranges" '^inside +1521 vertices, k1 '

expect_error "--csv and --json together" 'not both' "$FACET" curvature "$WORK/dome.obj" --csv "$WORK/x.csv" --json
expect_error "existing --csv refused" 'exists' "$FACET" curvature "$WORK/dome.obj" --csv "$WORK/dome.csv"
expect "existing --csv with --force" 0 "$FACET" curvature "$WORK/dome.obj" --csv "$WORK/dome.csv" --force
expect_error "missing file" 'nosuch.obj' "$FACET" curvature "$WORK/nosuch.obj"
expect_error "no file named" 'name one OBJ file' "$FACET" curvature

# Issue 32 item 5: the CSV lists the vertices in the file's order, each
# row's position the file's own v line (the truth: the OBJ, read by
# Python), whatever order welding numbered them in (here the v lines are
# shuffled against the faces, and one point is written twice); and every
# number is the shortest text that reads back to the same double, as
# Python's repr writes it.
/usr/bin/python3 - "$WORK/shuffled.obj" <<'PY'
import math, random, sys
random.seed(5)
n = 8
points = [(5 * math.sin(0.6 * i / n) * math.cos(j), 5 * math.sin(0.6 * i / n) * math.sin(j),
           5 * math.cos(0.6 * i / n)) for i in range(n + 1) for j in
          [2 * math.pi * k / n for k in range(n)]]
slot = list(range(len(points)))
random.shuffle(slot)
at = {p: s for p, s in enumerate(slot)}
lines = [None] * len(points)
for p, s in at.items():
    lines[s] = "v %.17g %.17g %.17g" % points[p]
lines.append("v %.17g %.17g %.17g" % points[12])  # a point twice: welded
faces = []
for i in range(n):
    for k in range(n):
        a, b = i * n + k, i * n + (k + 1) % n
        c, d = (i + 1) * n + (k + 1) % n, (i + 1) * n + k
        faces.append("f %d %d %d %d" % tuple(at[q] + 1 for q in (a, b, c, d)))
open(sys.argv[1], "w").write("\n".join(lines + faces) + "\n")
PY
expect "curvature --csv of a shuffled file" 0 "$FACET" curvature "$WORK/shuffled.obj" --csv "$WORK/shuffled.csv"
if out=$(/usr/bin/python3 - "$WORK/shuffled.obj" "$WORK/shuffled.csv" <<'PY' 2>&1
import csv, sys
v = [tuple(float(x) for x in l.split()[1:4]) for l in open(sys.argv[1]) if l.startswith("v ")]
rows = list(csv.DictReader(open(sys.argv[2])))
order = [int(r["v"]) for r in rows]
assert order == sorted(order) and len(set(order)) == len(order), "rows not in the file's order: %s" % order[:12]
for r in rows:
    assert tuple(float(r[k]) for k in "xyz") == v[int(r["v"]) - 1], r
def digits(text):  # significant digits
    return len(text.lower().split("e")[0].lstrip("+-").replace(".", "").strip("0"))
long = [(r["v"], k, r[k]) for r in rows for k in r if k not in ("v", "boundary")
        and digits(r[k]) > digits(repr(float(r[k])))]
assert not long, "not the shortest: %s" % long[:3]
print(len(rows))
PY
); then
    pass "csv: $out vertices in the file's order, their positions the file's, every number the shortest"
else
    fail "csv: the vertices in the file's order, every number the shortest ($out)"
fi
