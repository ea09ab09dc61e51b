#!/usr/bin/env bash
# End-to-end: slivers at face boundaries (issue 31, item 2). Planes written
# from their formulas (slivers_planes.py): an L, a rectangle 10.3 m x 6 m
# with a strip 11 m x 1 m along its foot, on 11 x 6 cells of 1 m. The
# outline cuts the last column at 10.3 m, leaving five panels 0.3 m x 1 m:
# the closed form is a smallest width of 0.3 m, a smallest area of 0.3 m^2
# and five slivers under 0.5 m. A plain 10 m x 6 m beside it on 1 m cells
# has none. Checked through SQLite: the stored columns, the width limit
# making the option infeasible and named, a building's rows per surface
# and its totals (least area and width, slivers added), and a count not
# measured staying NULL for the building.
# layers: cli core store study
. "$(dirname "$0")/lib.sh"
HERE=$(cd "$(dirname "$0")" && pwd)
cd "$WORK" || exit 1
/usr/bin/python3 "$HERE/slivers_planes.py" "$WORK" || exit 1
q() { sqlite3 -batch "$1" "$2"; }
# near DB SQL WANT: the one number SQL gives is within 1e-9 of WANT.
near() {
    local got
    got=$(q "$2" "$3")
    if /usr/bin/python3 -c "import sys; sys.exit(0 if abs(float(sys.argv[1]) - float(sys.argv[2])) <= 1e-9 else 1)" "$got" "$4" 2>/dev/null; then
        pass "$1"
    else
        echo "not ok - $1"
        echo "  got:  $got"
        echo "  want: $4"
    fi
}

# 1. One surface, the width limit 0.5 m: the option's columns.
expect "optimize the L at 11 x 6 with --min-panel-width 0.5" 0 \
    "$FACET" optimize l.obj --db l.db --u 11 --v 6 --threshold 3 --min-panel-width 0.5 --table 5
near "the smallest width is the sliver's, 10.3 - 10 = 0.3 m" l.db "SELECT min_panel_width FROM options" 0.3
near "the smallest area is 0.3 m x 1 m" l.db "SELECT min_panel_area FROM options" 0.3
same "five slivers under 0.5 m (rows 1 to 5 of the last column), of 66 panels; infeasible" \
    "$(q l.db 'SELECT slivers, panels, feasible FROM options')" "5|66|0"
same "the run keeps its width limit and measured widths" \
    "$(q l.db 'SELECT min_panel_width, measured FROM runs')" "0.5|fits,widths"
stdout_has "the run's table names the width limit the option breaks" \
    '^infeasible: 1 listed; 1 with slivers under the width limit \(--min-panel-width 0.5 m\)$'
expect "facet show names the limit" 0 "$FACET" show l.db --run 1 --option 1
stdout_has "show: the width and the slivers against the limit" \
    '^min panel width +300\.0 mm \(5 slivers narrower than the 500 mm width limit: NOT within\)$'
stdout_has "show: infeasible" '^feasible +NO$'
run "$FACET" options l.db --csv
same "options --csv: the three columns, width in m" \
    "$(/usr/bin/python3 -c "import csv,sys; r=list(csv.DictReader(open(sys.argv[1])))[0]; print(round(float(r['min_panel_area_m2']),9), round(float(r['min_panel_width_m']),9), r['slivers'])" "$OUT")" \
    "0.3 0.3 5"
run "$FACET" options l.db --json
json_check "options --json: the three columns" \
    'abs(j[0]["min_panel_width"]-0.3)<1e-9 and abs(j[0]["min_panel_area"]-0.3)<1e-9 and j[0]["slivers"]==5'
run "$FACET" options l.db --where "slivers > 0 and min_panel_width < 0.31" --csv
same "--where takes the columns" "$(tail -n +2 "$OUT" | wc -l)" 1
# A limit of the slivers' own width: they meet it (rounding allowed).
expect "optimize with --min-panel-width 0.3" 0 \
    "$FACET" optimize l.obj --db at.db --u 11 --v 6 --threshold 3 --min-panel-width 0.3 --table 0
same "at the slivers' own width: none under it, feasible" \
    "$(q at.db 'SELECT slivers, feasible FROM options')" "0|1"

# 2. classify says the same.
expect "classify the L with --min-panel-width 0.5" 0 \
    "$FACET" classify l.obj --grid 11x6 --min-panel-width 0.5
stdout_has "classify: min panel area" '^min panel area +0\.300 m\^2$'
stdout_has "classify: the width limit broken" \
    '^min panel width +300\.0 mm \(5 slivers narrower than the 500 mm width limit: NOT within\)$'
stdout_has "classify: infeasible" '^feasible +NO$'
run "$FACET" classify l.obj --grid 11x6 --min-panel-width 0.5 --json
json_check "classify --json: the limit and the three totals" \
    'j["min_panel_width_limit"]==0.5 and abs(j["totals"]["min_panel_width"]-0.3)<1e-9 and abs(j["totals"]["min_panel_area"]-0.3)<1e-9 and j["totals"]["slivers"]==5 and j["totals"]["feasible"] is False'
expect_error "--min-panel-width must be a width" "min-panel-width" \
    "$FACET" classify l.obj --grid 11x6 --min-panel-width -1

# 3. A building of the L and the plain, module 1 m x 1 m (the L's grid
# given: 11 x 6; the plain's is 10 x 6 by the module).
expect "optimize the building with --min-panel-width 0.5" 0 \
    "$FACET" optimize two.obj --db two.db --module 1x1 --grid L=11x6 --min-panel-width 0.5 --table 0
same "per surface: the L's 0.3 m slivers, five; the plain's 1 m panels, none" \
    "$(q two.db 'SELECT s.name, o.nu, o.nv, round(o.min_panel_area, 9), round(o.min_panel_width, 9), o.slivers FROM option_surfaces o JOIN surfaces s ON s.run = o.run AND s.surface = o.surface ORDER BY o.surface')" \
    "$(printf 'L|11|6|0.3|0.3|5\nplain|10|6|1.0|1.0|0')"
same "the building: least area and width of its surfaces', slivers added (sqlite3 over option_surfaces)" \
    "$(q two.db 'SELECT (SELECT min(min_panel_area) FROM option_surfaces s WHERE s.option = o.number) = o.min_panel_area, (SELECT min(min_panel_width) FROM option_surfaces s WHERE s.option = o.number) = o.min_panel_width, (SELECT sum(slivers) FROM option_surfaces s WHERE s.option = o.number) = o.slivers FROM options o')" \
    "1|1|1"
same "the building: infeasible, 5 slivers" "$(q two.db 'SELECT slivers, feasible FROM options')" "5|0"

# 4. Without a limit, a building's run leaves widths unmeasured (they cost
# ten evaluations and more): NULL on each surface and for the building,
# never the surfaces' unknowns added (which wrapped round to -2 for two
# surfaces); the smallest area is classifying's, always stored.
expect "optimize the building over five modules, no width limit" 0 \
    "$FACET" optimize two.obj --db many.db --module 0.8:1.2x1 --table 0
same "runs.measured: everything but widths" "$(q many.db 'SELECT measured FROM runs')" \
    "fits,joints,moulds,joint_length"
same "every option's and surface's smallest area stored, no width or sliver count" \
    "$(q many.db 'SELECT count(*), count(min_panel_area), count(min_panel_width), count(slivers) FROM options')|$(q many.db 'SELECT count(*), count(min_panel_area), count(min_panel_width), count(slivers) FROM option_surfaces')" \
    "5|5|0|0|10|10|0|0"

# 5. The workbench's selected-option pane (a wide terminal) shows them:
# the width in mm, the slivers, and "not measured" where a run did not
# measure them.
. "$HERE/tui_lib.sh"
start 200 60 -- l.db
check "workbench: the runs list the run" '^ +1 done +exhaustive'
keys g Enter
check "workbench: the run opens" '^ Run 1 '
check "workbench: the smallest panel width, 300 mm" 'smallest panel width +300 mm'
check "workbench: the slivers, 5" 'slivers \(panels under the width limit\) +5 *$'
check "workbench: the smallest panel area, 0.300 m^2" 'smallest panel area +0\.300 m\^2'
