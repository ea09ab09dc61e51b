#!/usr/bin/env bash
# End-to-end: the cost model in the workbench's New-run form (issue 15),
# and its panels-as-built settings (issue 16: SP fit, gap and kink limits),
# in tmux at 80x24 on a small example torus (its options have DP moulds;
# its SP-classed panels fit no cylinder or cone, so the SP term is priced
# at 0 moulds here: e2e/cost.sh prices SP moulds from the CLI, and the
# same run from the CLI below ties the form to it). The form shows the five cost fields with their hints and
# the paper's zero costs; a run started from it records the costs in its
# run row, and every option's cost is its terms summed again in SQL from
# the option's own columns; the same run from `facet optimize` with the
# flags gives the same options; "like this" fills the five fields from
# the run (an empty mould tolerance for a run without one); a bad value
# is refused by the field's label and starts nothing; on a short screen
# the form scrolls. Truths come from sqlite3 and the CLI, never from the
# form's own earlier screens. Every step polls the captured screen.
# layers: tui
. "$(dirname "$0")/lib.sh"

. "$(dirname "$0")/tui_lib.sh"

if ! command -v sqlite3 >/dev/null; then
    echo "skip - every cost form check (sqlite3 is not installed)"
    exit 0
fi
"$FACET" example torus --res 24 -o "$WORK/torus.obj" >/dev/null || exit 1
# a second surface, so that Tab on an empty path lists the two
"$FACET" example plane --res 2 -o "$WORK/plane.obj" >/dev/null || exit 1
q() { sqlite3 "$WORK/costs.db" "$1"; }
# The cost model the form is given, odd amounts so that none is a default.
PANEL=37.5 JOINT=12.25 SP=1999.5 DP=15000.25 TOL=4.5
# Panels as built: the paper's typing (no SP fit), odd limits on gaps and
# kinks; a kink limit whose degrees are no whole number of radians' worth.
GAP=6.75 KINK=1.3

# wait_run ID: polls the database until run ID is done (up to 4 x POLLS).
wait_run() {
    local i=0
    while [ $i -lt $((POLLS * 4)) ]; do
        [ "$(q "SELECT status FROM runs WHERE id = $1" 2>/dev/null)" = done ] && return 0
        sleep 0.05
        i=$((i + 1))
    done
    return 1
}
# down N: N fields on (the focus wraps, so each step is counted).
down() { local k; for ((k = 0; k < $1; k++)); do keys Down; done; }
# set_field HINT VALUE: once the focused field's hint (the line under the
# form) matches HINT, replaces the field's text with VALUE.
set_field() {
    if ! wait_for "^ $1"; then
        echo "not ok - the focus is on the field of '$1'"
        screen | sed 's/^/  screen: /'
    fi
    keys C-u
    [ -z "$2" ] || keys -l -- "$2"
}
H_PANEL='USD per panel, whatever its type'
H_JOINT='USD per metre of joint'
H_MOULD='USD per mould: a bending jig for SP'
H_TOL='curved panels within it share a mould'
H_MIRROR='yes or no: a panel and its mirror image'
H_AREA='the largest panel that can be made'
H_FIT='yes: an SP panel no cylinder or cone fits'
H_GAP="feasible only when no joint's gap exceeds it"
H_KINK="feasible only when no joint's kink exceeds it"
H_NAME='optional'

# --- the form at 80x24: every field, its hint, the paper's zero costs ---
start 80 24 -- costs.db
check "(a new database is asked about)" 'costs\.db does not exist'
keys y
check "(the runs of the new database)" '^ Facet runs +costs\.db +\(0 runs\)'
keys a
check "(the New run form)" '^ New run into costs\.db'
check "the panel cost field, 0 by default (the paper's model)" '^ Panel cost USD/panel +0 *$'
check "the joint cost field, 0 by default" '^ Joint cost USD/m +0 *$'
check "the mould cost field, 0,0 by default" '^ Mould cost SP,DP USD +0,0 *$'
check "the mould tolerance field, empty by default (the threshold)" '^ Mould tolerance \(mm\) *$'
check "the mirror field, no by default" '^ Mirrors share moulds +no *$'
check "the SP fit field, yes by default (panels as built)" '^ SP panels fitted +yes *$'
if [ "$(screen | grep -nE '^ Max panel m\^2 ' | cut -d: -f1)" = 12 ] &&
    [ "$(screen | grep -nE '^ Panel cost USD/panel ' | cut -d: -f1)" = 13 ] &&
    [ "$(screen | grep -nE '^ Mirrors share moulds ' | cut -d: -f1)" = 17 ] &&
    screen | sed -n 19p | grep -q '^vMax gap'; then
    pass "the five cost fields sit under Max panel m^2, the fields below them marked as more"
else
    echo "not ok - the five cost fields sit under Max panel m^2, the fields below them marked as more"
    screen | sed 's/^/  screen: /'
fi
check "(the estimate)" 'Not ready: name the surface'
if screen | sed -n 21p | grep -q '^ path of the OBJ file; Tab completes it' &&
    screen | sed -n 22p | grep -q '^ Not ready: name the surface'; then
    pass "the hint and the estimate fit under the fields shown (lines 21, 22)"
else
    echo "not ok - the hint and the estimate fit under the fields shown (lines 21, 22)"
    screen | sed 's/^/  screen: /'
fi
keys Tab
# no room under the estimate at 80x24: the choices cover the fields below
# the surface's while a path is chosen
check_line "Tab lists the surface's choices at 80x24, under its field" 4 '^  2 choices'
check_line "  ... naming the two surfaces" 5 '^ plane\.obj +torus\.obj'

# --- a run with costs, from the form ---
keys torus.obj
keys Down Down
set_field 'A:B, panels along u' 4:6
keys Down
set_field 'A:B, panels along v' 4:6
keys Down
set_field 'MM, A:B or A:B:STEP' 3:9:3
down 6
set_field "$H_PANEL" "$PANEL"
check "the panel cost field's hint" "^ $H_PANEL \(0: area alone"
keys Down
set_field "$H_JOINT" "$JOINT"
keys Down
set_field "$H_MOULD" "$SP,$DP"
keys Down
set_field "$H_TOL" "$TOL"
check "the mould tolerance's hint says what empty means" "^ $H_TOL; empty: the flatness threshold"
keys Down
set_field "$H_MIRROR" yes
keys Down
set_field "$H_FIT" no
check "the SP fit field's hint" "^ $H_FIT within t is built DP"
keys Down
set_field "$H_GAP" "$GAP"
check "the gap limit's hint says what empty means" "^ $H_GAP; empty: no limit"
keys Down
set_field "$H_KINK" "$KINK"
check "  ... and the fields scrolled with the focus, one up" '^\^Units'
check "  ... the more below marked" '^vMax kink \(deg\) +1\.3'

down 5  # the weld, the module, the surface grids and the objectives on the way
set_field "$H_NAME" 'costs from the form'
check "the form counts the run (3 x 3 x 3 = 27)" 'F5 starts: 27 options \(exhaustive\)'
keys F5
check "the run starts and its table opens" '^ Run 1 '
if wait_run 1; then pass "the run is done"; else fail "the run is done"; fi
same "the run row keeps the form's costs" \
    "$(q 'SELECT price_panel, price_joint, price_sp_mould, price_dp_mould, mould_tol_mm, mould_mirror FROM runs WHERE id = 1')" \
    "$PANEL|$JOINT|$SP|$DP|$TOL|1"
same "the run row keeps the form's panels as built (no SP fit, the limits)" \
    "$(q 'SELECT sp_fit, max_gap_mm, max_kink_deg FROM runs WHERE id = 1')" \
    "0|$GAP|$KINK"
# The limits judge feasibility: an option is feasible only with no joint
# over them and no panel over the size limit, judged again in SQL.
same "an option is feasible just when no joint is over the limits and no panel over the size" \
    "$(q "SELECT count(*) FROM options WHERE run = 1 AND
          feasible = (gaps_over = 0 AND kinks_over = 0 AND max_panel_area <=
            (SELECT max_panel_area_limit FROM runs WHERE id = 1) * (1 + 1e-9))")" 27
same "27 options" "$(q 'SELECT count(*) FROM options WHERE run = 1')" 27
# Each option's cost, its terms summed again from its own columns (to 1e-9
# of the cost: Facet sums the terms in its own order).
SUM="o.area_cost + o.panels * r.price_panel + o.joint_length * r.price_joint
     + o.sp_moulds * r.price_sp_mould + o.dp_moulds * r.price_dp_mould"
same "every option's cost is area + panels + joints + moulds, summed in SQL" \
    "$(q "SELECT count(*) FROM options o JOIN runs r ON r.id = o.run
          WHERE o.run = 1 AND abs(o.cost - ($SUM)) <= 1e-9 * o.cost")" 27
# and the area's own cost from the areas and the run's prices
same "every option's area cost is its areas times the run's prices" \
    "$(q "SELECT count(*) FROM options o JOIN runs r ON r.id = o.run
          WHERE o.run = 1 AND abs(o.area_cost - (o.fp_area * r.price_fp
            + o.sp_area * r.price_sp + o.dp_area * r.price_dp))
            <= 1e-9 * o.area_cost")" 27
# the check above prices panels, joints and DP moulds (the torus's SP
# panels are misfits, built DP)
same "the options have panels, joints and DP moulds to price" \
    "$(q 'SELECT min(panels) > 0, min(joint_length) > 0, max(dp_moulds) > 0, max(sp_misfits) > 0 FROM options WHERE run = 1')" \
    "1|1|1|1"
# Issue 32 item 1: at 80 columns the detail pane's cost is a sum that
# adds up: its terms, as a reader adds them, are its total, and the total
# is the option's cost as sqlite3 reads it, rounded to the dollar.
# The run is done in the database before the table repaints: wait for the
# pane (a sanitizer build paints late; CI read it blank once).
wait_for '^ +No\. [0-9]+:' && wait_for '^ +cost [0-9,]+ USD'
line=$(screen | grep -E '^ +cost [0-9,]+ USD' | head -n 1)
selected=$(screen | grep -oE '^ +No\. [0-9]+:' | grep -oE '[0-9]+' | head -n 1)
if [ -n "$line" ] && [ -n "$selected" ] && python3 - "$line" \
    "$(q "SELECT cost FROM options WHERE run = 1 AND number = $selected")" <<'PY'
import re, sys
line, cost = sys.argv[1], float(sys.argv[2])
total, _, terms = line.partition(" = ")
number = lambda s: int(s.replace(",", ""))
shown = number(re.search(r"cost ([0-9,]+) USD", total).group(1))
parts = [number(n) for n in re.findall(r"[A-Za-z]+ ([0-9,]+)", terms)]
ok = shown == round(cost) and (not parts or sum(parts) == shown)
if not parts:
    print("no terms:", line, file=sys.stderr)
sys.exit(0 if ok and parts else 1)
PY
then
    pass "80 columns: the detail pane's cost adds up ($line)"
else
    echo "not ok - 80 columns: the detail pane's cost adds up (No. '$selected': '$line')"
fi
# The same run from the command line: the same options, to the bit.
"$FACET" optimize "$WORK/torus.obj" --db "$WORK/cli.db" --u 4:6 --v 4:6 \
    --threshold 3:9:3 --panel-cost "$PANEL" --joint-cost "$JOINT" \
    --mould-cost "$SP,$DP" --mould-tol "$TOL" --mould-mirror --sp-fit no \
    --max-gap "$GAP" --max-kink "$KINK" >/dev/null 2>&1
OPTS='SELECT number, nu, nv, threshold_mm, sp_moulds, dp_moulds, joint_length, cost, max_gap, max_kink, gaps_over, kinks_over, feasible, sp_misfits FROM options ORDER BY number'
same "facet optimize with the same flags gives the same options" \
    "$(q "$OPTS")" "$(sqlite3 "$WORK/cli.db" "$OPTS")"

# --- like this: the five fields from the run ---
keys L
check "(L opens a New run like the option)" '^ New run into costs\.db'
check "like this: the panel cost" "^ Panel cost USD/panel +$PANEL *\$"
check "like this: the joint cost" "^ Joint cost USD/m +$JOINT *\$"
check "like this: the mould costs" "^ Mould cost SP,DP USD +$SP,$DP *\$"
check "like this: the mould tolerance" "^ Mould tolerance \(mm\) +$TOL *\$"
check "like this: mirrors share moulds" '^ Mirrors share moulds +yes *$'
check "like this: no SP fit" '^ SP panels fitted +no *$'
keys Down Down Down Down Down Down Down Down Down Down Down Down Down Down Down
check "like this: the gap limit as the run has it" "^ Max gap \(mm\) +$GAP *\$"
check "like this: the kink limit as the run has it (degrees, not radians back)" "^[ v]Max kink \(deg\) +$KINK *\$"

# --- a bad value names the field and starts nothing ---
# bad FIELDS HINT VALUE MESSAGE: FIELDS on from Panel cost, VALUE refused
# with MESSAGE (after the field's label) in the estimate and on F5.
bad() {
    keys Escape
    check "(back on the table)" '^ Run 1 '
    keys L
    check "(a form like the option)" "^ Panel cost USD/panel +$PANEL"
    down $((8 + $1))
    set_field "$2" "$3"
    check "'$3' is refused before F5, naming the field" "Not ready: $4"
    keys F5
    check "F5 refuses '$3', naming the field" "new run: $4"
}
bad 0 "$H_PANEL" abc "Panel cost USD/panel: 'abc' is not a number"
bad 1 "$H_JOINT" -5 'Joint cost USD/m: -5 is out of range \(0 to 1e\+09\)'
bad 3 "$H_TOL" 1e999 'Mould tolerance \(mm\): 1e999 is out of range \(0 to 1e\+06\)'
bad 2 "$H_MOULD" 5000 "Mould cost SP,DP USD: '5000' is not SP,DP in USD per mould"
bad 4 "$H_MIRROR" maybe "Mirrors share moulds: 'maybe' is not yes or no"
bad 5 "$H_FIT" maybe "SP panels fitted: 'maybe' is not yes or no"
bad 6 "$H_GAP" 0 'Max gap \(mm\): 0 is out of range \(1e-06 to 1e\+06\)'
bad 7 "$H_KINK" 200 'Max kink \(deg\): 200 is out of range \(1e-09 to 180\)'
bad 7 "$H_KINK" nan "Max kink \(deg\): 'nan' is not a number"
bad -1 "$H_AREA" 1e999 'Max panel m\^2: 1e999 is out of range'
if screen | grep -qE 'new run: Max panel m\^2: ' &&
    ! screen | grep -E 'Not ready|new run:' | grep -qE -- '--[a-z]'; then
    pass "the form's number messages name no command-line flag"
else
    echo "not ok - the form's number messages name no command-line flag"
    screen | sed 's/^/  screen: /'
fi
same "the refused values started no run" "$(q 'SELECT count(*) FROM runs')" 1
keys F10
check_exit "(F10 quits)"

# --- like this of a run without a mould tolerance: the field is empty ---
"$FACET" optimize "$WORK/torus.obj" --db "$WORK/costs.db" --u 4:4 --v 4:4 \
    --threshold 3 --panel-cost 1000000000 --mould-cost 0.1,2e3 \
    >/dev/null 2>&1
start 80 24 -- costs.db
check "the runs" '^ +2 done'
keys j Enter
check "run 2's table" '^ Run 2 '
keys L
check "like run 2: the panel cost as stored (1e9, whole)" '^ Panel cost USD/panel +1000000000 *$'
check "like run 2: the mould costs" '^ Mould cost SP,DP USD +0\.1,2000 *$'
check "like run 2: no mould tolerance, an empty field" '^ Mould tolerance \(mm\) *$'
check "like run 2: mirrors do not share moulds" '^ Mirrors share moulds +no *$'
check "like run 2: SP panels fitted (the default)" '^ SP panels fitted +yes *$'
keys Down Down Down Down Down Down Down Down Down Down Down Down Down Down Down
check "like run 2: no gap limit, an empty field" '^ Max gap \(mm\) *$'
check "like run 2: no kink limit, an empty field" '^[ v]Max kink \(deg\) *$'
keys F10
check_exit "(F10 quits, run 2)"

# --- a screen too short for the form: it scrolls, the focus in view ---
start 80 18 -- costs.db
check "(the runs, 80x18)" '^ +1 done'
keys a
check "(the form, 80x18)" '^ New run into costs\.db'
check "(its first field)" '^ Surface \(OBJ\)'
keys Up
check "(Up from the first field goes to Name)" '^ optional'
if screen | sed -n 12p | grep -qE '^ Objectives( |$)' &&
    screen | sed -n 13p | grep -qE '^ Name *$' &&
    screen | sed -n 15p | grep -q '^ optional'; then
    pass "the fields scroll: Name on the last row of them, the objectives above, its hint under"
else
    echo "not ok - the fields scroll: Name on the last row of them, the objectives above, its hint under"
    screen | sed 's/^/  screen: /'
fi
check_not "  ... and the first fields scrolled away" '^ Surface \(OBJ\)'
check_line "  ... marked as more above" 3 '^\^Mould cost SP,DP USD'
keys F10
check_exit "(F10 quits, 80x18)"
