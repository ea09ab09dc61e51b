#!/usr/bin/env bash
# End-to-end: a building's seams (issue 31 item 1), found once per run at
# --weld MM, measured with its joints and stored, against closed forms.
# Buildings written from their formulas (seams_faces.py) and read back
# through SQLite, never through Facet:
#   - two planes hinged at 30 degrees, grid lines along the seam aligned
#     (both faces 4 x 3) and not (the bent face 4 x 5): one seam of 3 m,
#     crease pi/6; flat panels are their planes, so no gap and no kink
#     added at the seam (closed form 0, whatever the grids), and a
#     --max-kink of 10 deg, below the crease, leaves the option feasible;
#   - a box corner, three planes at 90 degrees: three seams of 2 m, crease
#     pi/2, no gap, nothing added, feasible under --max-kink 10;
#   - a cylinder (R 3 m, facets of 15 degrees) cut along three rulings,
#     one flat panel a face: three seams of 4 m, no crease, each panel's
#     plane (its normal at its middle, through its area centroid, at
#     d = R cos 7.5 x the mean cosine of its facets' offsets) places a
#     ruling point x at x - (x.n - d) n, so the seam gap is the distance of
#     the two placements and the kink added the angle between the normals
#     (120 deg): a --max-kink of 100 deg makes the option infeasible (3
#     seam kinks over), one of 130 deg does not; grids not aligned (faces
#     of 1, 2 and 4 columns) give each seam its own closed form;
#   - the hinge with its faces 2 mm apart: no seam within 1 mm, one within
#     3 mm whose gap is the design's 2 mm; the run keeps its tolerance;
#   - a single surface: every seam column NULL, the run's weld NULL;
#   - facet runs: the weld column and note, sqlite3's weld_mm, or "-" and
#     "not a building" for a single surface;
#   - a bad --weld: one line, status 2, no database;
#   - show's seams line and options --csv's columns; export --csv's seams
#     schedule, each ruling's row against its closed form, and its totals
#     CSV's seam columns against sqlite3's (empty for a single surface);
#   - shards at one tolerance merged into a run that keeps it, shards of
#     two refused.
# layers: cli core store study
. "$(dirname "$0")/lib.sh"
HERE=$(cd "$(dirname "$0")" && pwd)
cd "$WORK" || exit 1
/usr/bin/python3 "$HERE/seams_faces.py" "$WORK" || exit 1
q() { sqlite3 -batch "$1" "$2"; }
# near NAME DB SQL WANT TOL: the one number SQL gives is within TOL of WANT.
near() {
    local got
    got=$(q "$2" "$3")
    if /usr/bin/python3 -c "import sys; sys.exit(0 if abs(float(sys.argv[1]) - float(sys.argv[2])) <= float(sys.argv[3]) else 1)" "$got" "$4" "$5" 2>/dev/null; then
        pass "$1"
    else
        echo "not ok - $1"
        echo "  got:  $got"
        echo "  want: $4 (within $5)"
    fi
}
# The closed form of the cylinder's seams: the gap and the kink added at
# the three rulings when faces 0, 1, 2 have COLS0 COLS1 COLS2 columns of
# flat panels; prints "GAP KINK OVER" (m, rad), the largest of the three,
# and how many of the three gaps exceed 0.5 m; with a fourth argument, a
# CSV file, checks its rows (facet export's seams schedule) against each
# ruling's closed form instead and prints "same" or what differs.
thirds() {
    /usr/bin/python3 - "$@" <<'PY'
import math, sys
R = 3.0
cols = [int(c) for c in sys.argv[1:4]]
def panel(centre, facets):
    offsets = [15 * (k + 0.5) - 7.5 * facets for k in range(facets)]
    d = R * math.cos(math.radians(7.5)) * sum(
        math.cos(math.radians(o)) for o in offsets) / facets
    c = math.radians(centre)
    return (math.cos(c), math.sin(c)), d
def place(phi, n, d):
    x = (R * math.cos(math.radians(phi)), R * math.sin(math.radians(phi)))
    xn = x[0] * n[0] + x[1] * n[1]
    return (x[0] - (xn - d) * n[0], x[1] - (xn - d) * n[1])
def edge(k, first):
    w = 120 / cols[k]
    centre = 120 * k + (w / 2 if first else 120 - w / 2)
    return panel(centre, 8 // cols[k])
gap = kink = 0
over = 0
for k in range(3):
    ruling = 120 * (k + 1)
    a, b = edge(k, False), edge((k + 1) % 3, True)
    g = math.dist(place(ruling, *a), place(ruling, *b))
    gap = max(gap, g)
    over += g > 0.5
    kink = max(kink, math.acos(max(-1, min(1, a[0][0] * b[0][0] +
                                            a[0][1] * b[0][1]))))
if len(sys.argv) > 4:
    import csv
    rows = list(csv.DictReader(open(sys.argv[4])))
    # each ruling between faces k and k + 1: (surface_a, surface_b) as the
    # seam is seen from the first in project order, with its truth
    want = {}
    for k in range(3):
        ruling = 120 * (k + 1)
        a, b = edge(k, False), edge((k + 1) % 3, True)
        pair = tuple(sorted(("third%d" % k, "third%d" % ((k + 1) % 3))))
        kink_deg = math.degrees(math.acos(max(-1, min(1, a[0][0] * b[0][0] +
                                                      a[0][1] * b[0][1]))))
        want[pair] = (1000 * math.dist(place(ruling, *a), place(ruling, *b)),
                      kink_deg)
    bad = []
    for r in rows:
        g, k = want[(r["surface_a"], r["surface_b"])]
        if not (abs(float(r["gap_mm"]) - g) < 1e-6 and
                abs(float(r["added_kink_deg"]) - k) < 1e-5 and
                abs(float(r["crease_deg"])) < 1e-5):
            bad.append(r)
    print("same" if len(rows) == 3 and not bad else "rows %d, wrong %s" %
          (len(rows), bad))
    sys.exit(0)
print("%.17g %.17g %d" % (gap, kink, over))
PY
}

# 1. The hinge, grids aligned: one option, 4 x 3 panels a face.
expect "optimize the hinge (1 m modules) with --max-kink 10, below its crease" 0 \
    "$FACET" optimize hinge.obj --db hinge.db --module 1:1x1:1 --threshold 3 --max-kink 10 --table 0
same "the run keeps the default welding tolerance, 1 mm" "$(q hinge.db 'SELECT weld_mm FROM runs')" "1.0"
same "one seam between the two faces" "$(q hinge.db 'SELECT seams FROM options')" "1"
near "the seam is the hinge line, 3 m" hinge.db "SELECT seam_length FROM options" 3 1e-9
near "the crease is the design's 30 degrees (pi/6 rad)" hinge.db "SELECT seam_max_crease FROM options" 30 1e-7
near "no gap at the seam with aligned grid lines (flat panels are their planes)" hinge.db "SELECT seam_max_gap FROM options" 0 1e-6
near "no kink added to the crease" hinge.db "SELECT seam_max_kink FROM options" 0 1e-7
near "the building's max kink is not the crease: ~0 deg" hinge.db "SELECT max_kink FROM options" 0 1e-6
same "a --max-kink below the crease: no kink over, feasible" \
    "$(q hinge.db 'SELECT seam_kinks_over, kinks_over, feasible FROM options')" "0|0|1"

# 2. The hinge, grids not aligned along the seam: the bent face 4 x 5.
expect "optimize the hinge with the bent face's own 4 x 5 grid" 0 \
    "$FACET" optimize hinge.obj --db skew.db --module 1:1x1:1 --grid B=4x5 --threshold 3 --max-kink 10 --table 0
same "4 x 3 + 4 x 5 panels, one seam, feasible" "$(q skew.db 'SELECT panels, seams, feasible FROM options')" "32|1|1"
near "grid lines not aligned: still no gap (closed form 0 for planes)" skew.db "SELECT seam_max_gap FROM options" 0 1e-6
near "the crease is still pi/6 (30 degrees)" skew.db "SELECT seam_max_crease FROM options" 30 1e-7

# 3. A box corner: three planes at 90 degrees.
expect "optimize the box corner with --max-kink 10" 0 \
    "$FACET" optimize box.obj --db box.db --module 1:1x1:1 --threshold 3 --max-kink 10 --table 0
same "three seams, 12 panels, feasible (a 90 degree corner is not a defect)" \
    "$(q box.db 'SELECT seams, panels, seam_kinks_over, feasible FROM options')" "3|12|0|1"
near "three seams of 2 m" box.db "SELECT seam_length FROM options" 6 1e-9
near "the crease is 90 degrees (pi/2 rad)" box.db "SELECT seam_max_crease FROM options" 90 1e-7
near "no gap at the corner's seams" box.db "SELECT seam_max_gap FROM options" 0 1e-6
near "no kink added" box.db "SELECT seam_max_kink FROM options" 0 1e-7

# 4. The cylinder in three faces, one flat panel each (t = 5 m keeps a
#    120 degree panel flat, a panel limit of 100 m^2 lets its 25 m^2
#    through): only seam joints.
read -r gap kink over <<<"$(thirds 1 1 1)"
expect "optimize the cylinder's thirds, one flat panel a face, --max-kink 100" 0 \
    "$FACET" optimize thirds.obj --db thirds.db --module 7:7x4:4 --max-panel-area 100 --threshold 5000 --max-kink 100 --table 0
same "three panels, all FP, three seams" "$(q thirds.db 'SELECT panels, fp_count, seams FROM options')" "3|3|3"
near "three rulings of 4 m" thirds.db "SELECT seam_length FROM options" 12 1e-9
near "no crease where a cylinder is cut along a ruling" thirds.db "SELECT seam_max_crease FROM options" 0 1e-4
near "the seam gap is the closed form's ($gap m, in mm as max_gap)" thirds.db "SELECT seam_max_gap FROM options" "$(/usr/bin/python3 -c "print($gap * 1000)")" 1e-6
near "the kink added is the panels' 120 degrees ($kink rad, in degrees as max_kink)" thirds.db "SELECT seam_max_kink FROM options" 120 1e-4
near "the building's max gap is the seams' (mm: no joint inside a face)" thirds.db "SELECT max_gap FROM options" "$(/usr/bin/python3 -c "print($gap * 1000)")" 1e-6
near "its mean gap too: every joint is at a seam, each the same" thirds.db "SELECT mean_gap FROM options" "$(/usr/bin/python3 -c "print($gap * 1000)")" 1e-6
near "the building's max kink is the added 120 degrees" thirds.db "SELECT max_kink FROM options" 120 1e-5
# One unit per family of columns (schema v16): the option's gap and kink
# and its seams' in the same units, so that comparing them in SQL is
# right. Every joint here is at a seam: the same numbers, to the bit.
same "max_gap and seam_max_gap, max_kink and seam_max_kink are one number in one unit" \
    "$(q thirds.db 'SELECT max_gap = seam_max_gap, max_kink = seam_max_kink, max_gap > 100 FROM options')" "1|1|1"
same "the columns users query are SQLite's own mm and degrees of the m and rad Facet keeps (option_held)" \
    "$(q thirds.db 'SELECT o.seam_max_gap = h.seam_max_gap * 1000, o.seam_max_kink = h.seam_max_kink * 180 / pi(), o.seam_max_crease IS h.seam_max_crease * 180 / pi(), o.max_gap = h.max_gap * 1000, o.max_kink = h.max_kink * 180 / pi() FROM options o JOIN option_held h ON h.run = o.run AND h.option = o.number')" "1|1|1|1|1"
# Held rows deleted in sqlite3's shell (its foreign keys are off): Facet
# reads each gap and kink back from the column, sqlite3's own mm and
# degrees of it (within 1e-12), never a 'not measured' beside a number
# the column has; per surface too, as show's table prints them.
# (two of the thirds cut further, so that their own joints have gaps)
expect "optimize the thirds, two of them cut in 2 and 4" 0 \
    "$FACET" optimize thirds.obj --db noheld.db --module 7:7x4:4 --grid third1=2x1,third2=4x1 --max-panel-area 100 --threshold 5000 --table 0
sqlite3 noheld.db "DELETE FROM option_held; DELETE FROM option_surface_held"
json=$("$FACET" options noheld.db --json 2>&1)
cols=$(q noheld.db "SELECT max_gap, mean_gap, max_kink, mean_kink, seam_max_gap, seam_max_kink FROM options")
if /usr/bin/python3 - "$json" "$cols" <<'PY'
import json, sys
o = json.loads(sys.argv[1])[0]
want = [float(x) for x in sys.argv[2].split("|")]
names = ["max_gap", "mean_gap", "max_kink", "mean_kink", "seam_max_gap", "seam_max_kink"]
bad = [(n, o[n], w) for n, w in zip(names, want)
       if o[n] is None or abs(o[n] - w) > 1e-12 * max(1, abs(w))]
if bad:
    sys.exit("off: %r" % bad)
PY
then
    pass "without held rows, options --json has each gap and kink the column has"
else
    echo "not ok - without held rows, options --json has each gap and kink the column has"
fi
surface_gaps=$(q noheld.db "SELECT group_concat(printf('%.2f', max_gap), ' ') FROM option_surfaces WHERE max_gap > 0")
shown=$("$FACET" show noheld.db --run 1 --option 1 2>&1 | awk '$1 ~ /^third[12]$/ { printf "%s%s", sep, $(NF-1); sep = " " }')
same "... and show's surfaces their max gap as the column has it ($surface_gaps mm)" "$shown" "$surface_gaps"

# A v15 file (the seams in m and rad) migrated by facet migrate: the seams'
# columns are sqlite3's own mm and degrees of the old file's, the options'
# own mm and degrees as they were, and Facet shows the same seams as the
# file it made at v16.
cp thirds.db v15.db
sqlite3 v15.db "DROP TABLE option_surface_held; DROP TABLE option_held;
    UPDATE options SET seam_max_gap = seam_max_gap / 1000,
    seam_max_kink = seam_max_kink * pi() / 180,
    seam_max_crease = seam_max_crease * pi() / 180; PRAGMA user_version = 15;"
cp v15.db v15.old
expect "facet migrate migrates a v15 building" 0 "$FACET" migrate v15.db
same "sqlite3: the seams in mm and degrees from the v15 m and rad, an option's own as it was, the held m and rad" \
    "$(q v15.db "ATTACH 'v15.old' AS old; SELECT (SELECT user_version FROM pragma_user_version), o.seam_max_gap = p.seam_max_gap * 1000, o.seam_max_kink = p.seam_max_kink * 180 / pi(), o.seam_max_crease IS p.seam_max_crease * 180 / pi(), o.max_gap = p.max_gap AND o.max_kink = p.max_kink, h.seam_max_gap = p.seam_max_gap AND h.seam_max_kink = p.seam_max_kink, h.max_gap = p.max_gap / 1000 AND h.max_kink = p.max_kink * pi() / 180 FROM options o JOIN old.options p USING (run, number) JOIN option_held h ON h.run = o.run AND h.option = o.number")" \
    "16|1|1|1|1|1|1"
run "$FACET" show v15.db --run 1 --option 1
stdout_has "... and facet show says its seams as before: 120 deg added" \
    '^seams +3, 12\.0 m long: max gap [0-9.]+ mm, max kink added 120\.00 deg'
same "a --max-kink below the added kink: three seam kinks over, infeasible" \
    "$(q thirds.db 'SELECT seam_kinks_over, kinks_over, feasible FROM options')" "3|3|0"
expect "the same with --max-kink 130, above it" 0 \
    "$FACET" optimize thirds.obj --db thirds130.db --module 7:7x4:4 --max-panel-area 100 --threshold 5000 --max-kink 130 --table 0
same "no kink over, feasible" "$(q thirds130.db 'SELECT seam_kinks_over, kinks_over, feasible FROM options')" "0|0|1"
read -r gap kink over <<<"$(thirds 1 2 4)"
expect "the thirds with 1, 2 and 4 columns: grids not aligned at the seams" 0 \
    "$FACET" optimize thirds.obj --db uneven.db --module 7:7x4:4 --grid third1=2x1,third2=4x1 --threshold 5000 --max-gap 500 --table 0
near "the largest seam gap is the closed form's ($gap m, in mm)" uneven.db "SELECT seam_max_gap FROM options" "$(/usr/bin/python3 -c "print($gap * 1000)")" 1e-6
near "the largest kink added is the closed form's ($kink rad, in degrees)" uneven.db "SELECT seam_max_kink FROM options" "$(/usr/bin/python3 -c "import math; print(math.degrees($kink))")" 1e-4
same "seam gaps over --max-gap 500: the closed form's $over" "$(q uneven.db 'SELECT seam_gaps_over FROM options')" "$over"
expect "facet export --csv of it writes the seams schedule beside" 0 \
    "$FACET" export uneven.db --run 1 --option 1 --csv uneven.csv
stdout_has "... and says so" '^wrote uneven-seams\.csv$'
same "the seams schedule: one row a ruling, its gap (mm) and added kink (deg) the closed form's, no crease" \
    "$(thirds 1 2 4 uneven-seams.csv)" same
same "its panels are the panel schedule's ids: third0's 1 meets third1's 2, third2's 7 and third1's 3 its 4" \
    "$(/usr/bin/python3 -c "import csv,sys; print(' '.join(r['panel_a'] + '-' + r['panel_b'] for r in csv.DictReader(open(sys.argv[1]))))" uneven-seams.csv)" \
    "1-2 1-7 3-4"
# The totals beside the schedule carry the seam quantities (issue 31),
# named with the units they are stored in (m, rad), each the value
# sqlite3 reads from the options row, to the bit.
seam_totals() {
    /usr/bin/python3 - "$1" "$2" <<'PY'
import csv, sqlite3, sys
t = list(csv.DictReader(open(sys.argv[1], newline="")))
row = sqlite3.connect(sys.argv[2]).execute(
    "SELECT seams, seam_length, seam_max_gap, seam_max_kink, seam_max_crease,"
    " seam_gaps_over, seam_kinks_over FROM options WHERE run = 1 AND number = 1"
).fetchone()
names = ["seams", "seam_length_m", "seam_max_gap_mm", "seam_max_kink_deg",
         "seam_max_crease_deg", "seam_gaps_over", "seam_kinks_over"]
if len(t) != 1 or any(n not in t[0] for n in names):
    print("columns %s" % (list(t[0].keys()) if t else "none"))
    sys.exit()
got = [None if t[0][n] == "" else float(t[0][n]) for n in names]
want = [None if v is None else float(v) for v in row]
print("same" if got == want else "%s against %s" % (got, want))
PY
}
same "the totals CSV's seam columns (seams .. seam_kinks_over; gaps in mm, angles in degrees, as stored) are sqlite3's" \
    "$(seam_totals uneven-totals.csv uneven.db)" same
# The workbook's seams sheet, read with openpyxl into the CSV's columns,
# against the same closed forms and panel ids.
expect "facet export --xlsx of it" 0 \
    "$FACET" export uneven.db --run 1 --option 1 --xlsx uneven.xlsx
/usr/bin/python3 - uneven.xlsx uneven-xlsx-seams.csv <<'PY'
import csv, sys
import openpyxl
names = {"seam": "seam", "surface a": "surface_a", "panel a": "panel_a",
         "surface b": "surface_b", "panel b": "panel_b", "gap (mm)": "gap_mm",
         "kink (deg)": "kink_deg", "crease (deg)": "crease_deg",
         "added kink (deg)": "added_kink_deg"}
rows = list(openpyxl.load_workbook(sys.argv[1], read_only=True)["seams"]
            .iter_rows(values_only=True))
with open(sys.argv[2], "w", newline="") as f:
    w = csv.writer(f)
    w.writerow([names[h] for h in rows[0]])
    w.writerows(rows[1:])
PY
same "the workbook's seams sheet: one row a ruling, the closed form's gap and added kink" \
    "$(thirds 1 2 4 uneven-xlsx-seams.csv)" same
same "... its panels the panels sheet's ids" \
    "$(/usr/bin/python3 -c "import csv,sys; print(' '.join(r['panel_a'] + '-' + r['panel_b'] for r in csv.DictReader(open(sys.argv[1]))))" uneven-xlsx-seams.csv)" \
    "1-2 1-7 3-4"
same "... and the same rows as the seams CSV" \
    "$(/usr/bin/python3 -c "
import csv, sys
a = list(csv.DictReader(open(sys.argv[1])))
b = list(csv.DictReader(open(sys.argv[2])))
same = len(a) == len(b) and all(
    x['surface_a'] == y['surface_a'] and x['surface_b'] == y['surface_b'] and
    all(abs(float(x[k]) - float(y[k])) <= 1e-9 * max(1, abs(float(x[k])))
        for k in ('seam', 'panel_a', 'panel_b', 'gap_mm', 'kink_deg',
                  'crease_deg', 'added_kink_deg'))
    for x, y in zip(a, b))
print('same' if same else 'differ')" uneven-seams.csv uneven-xlsx-seams.csv)" same

# 5. The welding tolerance: the hinge's faces 2 mm apart.
expect "optimize the faces 2 mm apart at the default 1 mm" 0 \
    "$FACET" optimize hinge_apart.obj --db apart1.db --module 1:1x1:1 --threshold 3 --table 0
same "no seam within 1 mm: none, of no length, no gap (NULL, not 0)" \
    "$(q apart1.db 'SELECT seams, seam_length, quote(seam_max_gap) FROM options')" "0|0.0|NULL"
expect "the same at --weld 3" 0 \
    "$FACET" optimize hinge_apart.obj --db apart3.db --module 1:1x1:1 --weld 3 --threshold 3 --table 0
same "the run keeps --weld 3 (mm)" "$(q apart3.db 'SELECT weld_mm FROM runs')" "3.0"
run "$FACET" runs apart3.db --json
json_check "facet runs --json: weld_mm 3" "[r['weld_mm'] for r in j] == [3]"
weld=$(/usr/bin/python3 -c "import sys; print('%g' % float(sys.argv[1]))" "$(q apart3.db 'SELECT weld_mm FROM runs')")
run "$FACET" runs apart3.db --wide
stdout_has "facet runs: the weld column, sqlite3's weld_mm ($weld mm), before the start" \
    "^ +1 done .* $weld 20[0-9-]+T"
stdout_has "facet runs: the run's note says --weld $weld mm" "^run 1: .*, --weld $weld mm\$"
same "one seam within 3 mm" "$(q apart3.db 'SELECT seams FROM options')" "1"
near "its gap is the design's own 2 mm" apart3.db "SELECT seam_max_gap FROM options" 2 1e-6

# 6. A single surface has no seams: NULL, never 0.
expect "optimize the floor alone" 0 \
    "$FACET" optimize box.obj --object floor --db floor.db --u 2 --v 2 --threshold 3 --measure all --table 0
same "its joints measured, every seam column NULL" \
    "$(q floor.db 'SELECT max_gap IS NOT NULL, seams IS NULL AND seam_length IS NULL AND seam_max_gap IS NULL AND seam_max_kink IS NULL AND seam_max_crease IS NULL AND seam_gaps_over IS NULL AND seam_kinks_over IS NULL FROM options')" "1|1"
same "its run has no welding tolerance" "$(q floor.db 'SELECT quote(weld_mm) FROM runs')" "NULL"
run "$FACET" runs floor.db --json
json_check "facet runs --json: weld_mm null" "[r['weld_mm'] for r in j] == [None]"
expect "export --csv of the floor alone" 0 \
    "$FACET" export floor.db --run 1 --option 1 --csv floor.csv
same "its totals CSV has the seam columns, empty (NULL), as sqlite3's" \
    "$(seam_totals floor-totals.csv floor.db)" same
run "$FACET" runs floor.db --wide
stdout_has "facet runs: a single surface's weld is -, never 0" "^ +1 done .* - 20[0-9-]+T"
stdout_has "facet runs: ... its note says it is not a building" "^run 1: .*, no weld: not a building\$"

# 7. Bad tolerances: one line, status 2, nothing created.
expect_error "--weld -1 refused" '^facet: --weld: -1 is out of range' \
    "$FACET" optimize hinge.obj --db bad.db --module 1:1x1:1 --weld -1
expect_error "--weld nan refused" "^facet: --weld: 'nan' is not a number" \
    "$FACET" optimize hinge.obj --db bad.db --module 1:1x1:1 --weld nan
expect_error "--weld 1e9 refused" '^facet: --weld: 1e9 is out of range' \
    "$FACET" optimize hinge.obj --db bad.db --module 1:1x1:1 --weld 1e9
expect_error "--weld without --module refused" 'needs --module' \
    "$FACET" optimize hinge.obj --db bad.db --weld 1
if [ ! -e bad.db ]; then pass "no database made by a bad --weld"; else echo "not ok - no database made by a bad --weld"; fi

# 8. What facet shows, from the same stored numbers: the seams line of
#    show, and the columns of --csv (SI, named with their units).
expect "facet show the thirds' option" 0 "$FACET" show thirds.db --run 1 --option 1
stdout_has "show: three seams of 12 m, the gap in mm, 120 deg added over no crease, 3 kinks over" \
    '^seams +3, 12\.0 m long: max gap [0-9.]+ mm, max kink added 120\.00 deg to a crease of up to 0\.0 deg \(0 gaps, 3 kinks over the limits\)$'
run "$FACET" options thirds.db --csv
same "options --csv: seams, seam_length_m, seam_max_kink_deg, seam_kinks_over" \
    "$(/usr/bin/python3 -c "import csv,sys; r=list(csv.DictReader(open(sys.argv[1])))[0]; print(r['seams'], round(float(r['seam_length_m']), 9), round(float(r['seam_max_kink_deg']), 4), r['seam_kinks_over'])" "$OUT")" \
    "3 12.0 120.0 3"

# 9. Shards and their merge: each shard finds the seams at the run's
#    tolerance, the merge keeps it, and shards of two tolerances are not
#    one run.
for i in 1 2; do
    expect "shard $i/2 of the hinge over two module widths, --weld 2" 0 \
        "$FACET" optimize hinge.obj --db shard$i.db --module 0.5:1:0.5x1:1 --weld 2 --shard $i/2 --threshold 3 --table 0
done
expect "facet merge joins them" 0 "$FACET" merge merged.db shard1.db shard2.db
same "the merged run keeps --weld 2; each of its 2 options has the hinge's seam" \
    "$(q merged.db 'SELECT (SELECT weld_mm FROM runs), count(*), sum(seams) FROM options')" "2.0|2|2"
near "... at the crease pi/6 (30 degrees) in both" merged.db "SELECT max(abs(seam_max_crease - 30)) FROM options" 0 1e-7
expect "a shard 2/2 at --weld 3" 0 \
    "$FACET" optimize hinge.obj --db shard3.db --module 0.5:1:0.5x1:1 --weld 3 --shard 2/2 --threshold 3 --table 0
expect_error "shards of two welding tolerances are refused in one line" \
    'differs from .*shard1\.db in its welding tolerance of the seams \(mm\): 3, not 2' \
    "$FACET" merge merged2.db shard1.db shard3.db
