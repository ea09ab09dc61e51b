#!/usr/bin/env bash
# End-to-end: a run measures what it needs (issue 27, item 3). The truth
# is the same run with --measure all (every option in full, as every run
# was before), compared by SQLite: every number the run measured equals
# it to the bit, every number it did not is NULL (never 0), its Pareto
# options are measured in full, runs.measured says what it took, and an
# option opened later (facet show) is measured in full without touching
# what the run measured.
# layers: cli core store study
. "$(dirname "$0")/lib.sh"
HERE=$(cd "$(dirname "$0")" && pwd)

cd "$WORK" || exit 1
"$FACET" example roof --res 30 -o roof.obj >/dev/null || exit 1
SPACE=(--u 8:14 --v 9:15 --threshold 2:4:1 --max-panel-area 30)
# The columns of each measure.
FITS="sp_misfits, sp_fitted"
JOINTS="max_gap, mean_gap, max_kink, mean_kink, gaps_over, kinks_over"
MOULDS="moulds, sp_moulds, dp_moulds, largest_family, single_moulds"
LENGTH="joint_length"
WIDTHS="min_panel_width, slivers"

# run_pair NAME ARGS...: the run with ARGS into NAME.db and with
# --measure all into NAME-all.db.
run_pair() {
    local name=$1
    shift
    "$FACET" optimize roof.obj --db "$name.db" "${SPACE[@]}" "$@" --table 0 >/dev/null 2>"$name.err" ||
        { echo "not ok - $name runs"; cat "$name.err"; }
    "$FACET" optimize roof.obj --db "$name-all.db" "${SPACE[@]}" "$@" --measure all --table 0 >/dev/null 2>&1 ||
        echo "not ok - $name --measure all runs"
}

# differ A B COLUMNS [WHERE]: how many rows of A's options differ from B's
# over COLUMNS (EXCEPT both ways), by number.
differ() {
    sqlite3 -batch "$1" "ATTACH '$2' AS b;
        SELECT (SELECT count(*) FROM (SELECT number, $3 FROM main.options ${4:-} EXCEPT SELECT number, $3 FROM b.options ${4:-}))
             + (SELECT count(*) FROM (SELECT number, $3 FROM b.options ${4:-} EXCEPT SELECT number, $3 FROM main.options ${4:-}))"
}

# nulls DB COLUMNS WHERE: rows matching WHERE with every COLUMN NULL.
nulls() {
    local cond
    cond=$(echo "$2" | sed 's/, */ IS NULL AND /g; s/$/ IS NULL/')
    sqlite3 -batch "$1" "SELECT count(*) FROM options WHERE $3 AND $cond"
}

ALWAYS="nu, nv, threshold_mm, panels, fp_count, sp_count, dp_count, fp_area, sp_area, dp_area, area, fp_cost, sp_cost, dp_cost, cost, planarity, max_deviation, max_panel_area, min_panel_area, p_dist, feasible, flat_count, flat_area, saddle_count, saddle_area, rank, crowding, knee, area_cost, panel_cost, joint_cost, mould_cost"
ALL="$ALWAYS, $FITS, $JOINTS, $MOULDS, $LENGTH, $WIDTHS"

# 1. The paper's typing, objectives and prices: nothing beyond the panels.
run_pair paper --sp-fit no --sp-as-fp
same "paper: runs.measured is empty, --measure all every measure" \
    "$(sqlite3 paper.db 'SELECT quote(measured) FROM runs')|$(sqlite3 paper-all.db 'SELECT measured FROM runs')" \
    "''|fits,joints,moulds,joint_length,widths"
same "paper: every number it measured = --measure all's, to the bit (rank, crowding, knee too)" \
    "$(differ paper.db paper-all.db "$ALWAYS")" 0
same "paper: its Pareto options in full = --measure all's" \
    "$(differ paper.db paper-all.db "$ALL" "WHERE rank = 1")" 0
others=$(sqlite3 paper.db 'SELECT count(*) FROM options WHERE rank > 1')
same "paper: every other option's fits, joints, moulds, joint length, widths NULL" \
    "$(nulls paper.db "$FITS, $JOINTS, $MOULDS, $LENGTH, $WIDTHS" 'rank > 1')" "$others"
same "paper: --measure all leaves nothing NULL" \
    "$(sqlite3 paper-all.db "SELECT count(*) FROM options WHERE sp_fitted IS NULL OR gaps_over IS NULL OR moulds IS NULL OR joint_length IS NULL OR slivers IS NULL")" 0
if [ "$others" -gt 0 ]; then pass "paper: the space has options off the front ($others)"; else fail "paper: the space has options off the front"; fi

# 2. Typing by fit (the default): the fits, nothing else.
run_pair fit
same "fit: runs.measured" "$(sqlite3 fit.db 'SELECT measured FROM runs')" fits
same "fit: its numbers and fits = --measure all's" "$(differ fit.db fit-all.db "$ALWAYS, $FITS")" 0
same "fit: the others' joints, moulds, joint length NULL" \
    "$(nulls fit.db "$JOINTS, $MOULDS, $LENGTH" 'rank > 1')" \
    "$(sqlite3 fit.db 'SELECT count(*) FROM options WHERE rank > 1')"

# 3. A limit, a price, an objective: each brings its measure.
run_pair gap --max-gap 5
same "gap limit: runs.measured" "$(sqlite3 gap.db 'SELECT measured FROM runs')" fits,joints
same "gap limit: = --measure all's over what it measured (feasibility too)" \
    "$(differ gap.db gap-all.db "$ALWAYS, $FITS, $JOINTS")" 0
run_pair width --min-panel-width 2.2
same "width limit: runs.measured" "$(sqlite3 width.db 'SELECT measured FROM runs')" fits,widths
same "width limit: = --measure all's over what it measured (feasibility too)" \
    "$(differ width.db width-all.db "$ALWAYS, $FITS, $WIDTHS")" 0
run_pair priced --joint-cost 40 --mould-cost 1000,5000 --sp-fit no
same "joint and mould prices: runs.measured" "$(sqlite3 priced.db 'SELECT measured FROM runs')" moulds,joint_length
same "joint and mould prices: = --measure all's over what it measured" \
    "$(differ priced.db priced-all.db "$ALWAYS, $MOULDS, $LENGTH")" 0
run_pair objective --objectives cost,max_kink --sp-fit no
same "objective max_kink: runs.measured" "$(sqlite3 objective.db 'SELECT measured FROM runs')" fits,joints
same "objective max_kink: = --measure all's over what it measured" \
    "$(differ objective.db objective-all.db "$ALWAYS, $FITS, $JOINTS")" 0

# 4. An option opened later is measured in full; what the run measured
# stays to the bit.
opt=$(sqlite3 paper.db 'SELECT min(number) FROM options WHERE rank > 1')
before=$(sqlite3 paper.db "SELECT $ALWAYS FROM options WHERE number = $opt")
expect "show an option off the front" 0 "$FACET" show paper.db --run 1 --option "$opt"
stdout_has "show: its moulds measured" '^moulds +[0-9]+ \(SP'
stdout_has "show: its gaps measured" '^gap +max [0-9.]+ mm'
same "show: its row now holds every measure" \
    "$(sqlite3 paper.db "SELECT sp_fitted IS NOT NULL AND gaps_over IS NOT NULL AND moulds IS NOT NULL AND joint_length IS NOT NULL FROM options WHERE number = $opt")" 1
same "show: what the run measured is as it was, to the bit" \
    "$(sqlite3 paper.db "SELECT $ALWAYS FROM options WHERE number = $opt")" "$before"
same "show: the counts it measured = --measure all's" \
    "$(differ paper.db paper-all.db "moulds, sp_moulds, dp_moulds, sp_misfits, sp_fitted, gaps_over, kinks_over" "WHERE number = $opt")" 0

# 5. Resumed, a run measures as it recorded. A space of 4,400 options on
# one thread, so that the stop lands mid-run however fast the build; the
# truth is the same space uninterrupted.
LONG=(--u 8:29 --v 9:28 --threshold 1:10:1 --max-panel-area 30 --sp-fit no --sp-as-fp --jobs 1 --table 0)
"$FACET" optimize roof.obj --db long.db "${LONG[@]}" >/dev/null 2>&1 ||
    echo "not ok - the uninterrupted long run"
"$FACET" optimize roof.obj --db res.db "${LONG[@]}" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 400); do
    n=$(sqlite3 res.db 'SELECT count(*) FROM options' 2>/dev/null || echo 0)
    [ "${n:-0}" -ge 20 ] && break
    sleep 0.05
done
kill -INT "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
same "stopped mid-run" "$(sqlite3 res.db "SELECT status, options < 4400 FROM runs")" "interrupted|1"
expect "resume" 0 "$FACET" optimize --db res.db --resume 1 --table 0
same "resumed: = the uninterrupted run, every column" "$(differ res.db long.db "$ALL")" 0
same "resumed: measured as recorded (nothing beyond the panels)" \
    "$(sqlite3 res.db "SELECT quote(measured) FROM runs")" "''"

expect_error "--measure takes all or needed" "measure: 'some' is neither all nor needed" \
    "$FACET" optimize roof.obj --db bad.db --measure some

# 6. The workbench says so too: its selected-option pane (wide terminal)
# reads "not measured" for a NULL, a number for what was measured.
. "$HERE/tui_lib.sh"
cp fit.db tui.db
start 200 60 -- tui.db
check "workbench: the runs list the run" '^ +1 done +exhaustive'
keys g Enter
check "workbench: the run opens" '^ Run 1 '
# An option off the front whose SP panels are all misfits (SP fitted 0,
# as sqlite3 picks it out): no panel is bent, and the pane says none, not
# "not measured" (the fits ran).
same "workbench: the run has options off the front with no SP panel fitted" \
    "$(sqlite3 tui.db 'SELECT count(*) > 0 FROM options WHERE rank > 1 AND sp_fitted = 0')" 1
keys / && sleep 0.3 && keys "rank > 1 and sp_fitted = 0" Enter
check "workbench: an option off the front, moulds not measured" 'moulds +not measured'
check "workbench: its SP fits measured (a number)" 'SP fitted +[0-9]+'
# (the option the filter opens has no SP panel fitted)
check "workbench: SP fitted 0 here" 'SP fitted +0 *$'
check "workbench: its smallest SP bending radius: none, measured with the fits" 'smallest SP bending radius +none *$'
check_not "workbench: no NULL shown as 0 or '-' for moulds" 'moulds +(0|-) *$'
