#!/usr/bin/env bash
# End-to-end: facet tui driven in tmux (send-keys, capture-pane) at 80x24
# and 200x60: open a database made by facet optimize, sort, filter (and a
# bad filter), toggle Pareto, jump to the knee, help, scatter, parallel
# coordinates brushed from the keyboard (the table's count follows), the
# column chooser, panel map, compare with panel maps, resize, delete
# (answering no), resuming a run interrupted by SIGINT, a New run with Tab
# completion watched to the end, ASCII fallback, SIGTERM and quit, the
# terminal given back every time.
# Every step polls the captured screen (no fixed sleeps); every tmux
# server this script starts is killed on exit.
# layers: tui
. "$(dirname "$0")/lib.sh"

. "$(dirname "$0")/tui_lib.sh"

fixture roof40.obj "$WORK/roof.obj" || exit 1
# Typed by class alone (the figures below are that run's; as built, this
# coarse roof's SP panels are misfits: docs/method.md, "Panels as built").
"$FACET" optimize "$WORK/roof.obj" --db "$WORK/t.db" --u 4:8 --v 4:8 \
    --threshold 2:4:1 --sp-fit no >/dev/null 2>&1 || exit 1

# count WHERE: how many options of run 1 of t.db pass the filter WHERE.
count() {
    "$FACET" options "$WORK/t.db" --run 1 --where "$1" --csv | tail -n +2 | wc -l
}
# check_slow NAME PATTERN: check, waiting up to four times longer (a run).
check_slow() {
    local polls=$POLLS
    POLLS=$((POLLS * 4))
    check "$@"
    POLLS=$polls
}
# --- 80x24: the whole tour ---
start 80 24 -- t.db
check "runs screen lists the run" '^ +1 done +exhaustive +75 +3 .*roof\.obj'
check "runs screen has the function-key bar" 'F1Help.*F10Quit'
keys Enter
check "Enter opens the options table" '^ Run 1 roof\.obj \| exhaustive \| done \| 75 options, 3 Pareto, knee 73'
check "header with units" 'No\. P planarity +DP area +cost +FP area +SP area +U +V +t +ok rank'
check "sorted by cost, cheapest first" '^ row [0-9,]+ of 75  +sort feasible first, cost asc +filter none'
check "first row is the cheapest option" '^ +70 .* 2\.686 +809\.4 +1,538,690 +296\.7 +133\.2 +8 +7 +2\.00 +no +3$'
check "detail pane names the limit the selected option breaks" 'No\. 70: 8 x 7, (t 2\.00 mm, )?rank 3, infeasible: panel 23\.70 m\^2 > 7\.06 m\^2 limit'
keys h h s g
check "s sorts by the cursor's column; the old key becomes second" 'sort (feasible first, )?planarity asc, then cost asc '
check "planarity ascending puts a 0.000 first" '^ +[0-9]+ (✗|x) +0\.000 '
keys s g
check "s again reverses it" 'sort (feasible first, )?planarity desc, then cost asc '
check "descending starts at the largest planarity" '^ +7[345] .* 2\.522 '
keys l S
check "S sets the secondary key" 'sort (feasible first, )?planarity desc, then dp_area asc'
keys l s
check "the old primary becomes the secondary" 'sort (feasible first, )?cost asc, then planarity desc'
keys / 'cost < 1.56M' Enter
check "filter line filters" '^ row [0-9,]+ of 6  .* filter cost < 1560000'
keys / C-u 'cost < 2M and dp_aera > 1' Enter
check "a bad filter names the column in the status line" "filter: column 15: unknown column 'dp_aera' \(did you mean dp_area\?\)"
check "a bad filter keeps the old one" '^ row [0-9,]+ of 6  .* filter cost < 1560000'
keys / C-u Enter
check "an empty filter shows every option" '^ row [0-9,]+ of 75  .* filter none'
keys p
check "p shows Pareto-optimal options only" '^ row [0-9,]+ of 3  .*Pareto only'
keys p G
check "p again shows them all" '^ row [0-9,]+ of 75  .*filter none *$'
keys K
check "K jumps to the knee" 'knee option 73'
keys '?'
check "? lists the screen's keys" 'Help: Options keys'
check "help names the sort key" 's, F6 +sort by the cursor'
keys q
check "any key closes help" '^ row [0-9,]+ of 75 '
keys x
check "x opens the scatter (planarity vs cost)" '^ Scatter: cost vs planarity, size dp_area \| 75 points'
check "scatter cursor starts on the table's selection" '^ No\. 73 +planarity 2\.5217 +cost 1,551,317'
keys Left
check "the scatter cursor moves point to point" '^ No\. 34 +planarity 2\.1804'
keys x
check "x changes the x metric" '^ Scatter: cost vs dp_area'
keys q
check "the table follows the scatter's cursor" 'No\. 34: 6 x 5'
keys '|'
check "| opens parallel coordinates over every option" '^ Parallel coordinates: run 1 \| 75 of 75 options shown'
check "one axis per variable and metric, the cursor on cost" ' U +V +t +planarity +DP area +\[cost\] +FP area +SP area'
check "axes are labelled with their ranges" '1,687,314 .*'
check "the selected option is described" '^ No\. 34: 6 x 5'
keys ']' ']' ']' ']' ']' ']' ']' ']' ']' ']'
want=$(count 'cost <= 1617000')
check "] brushes cost from above; the brush is the filter" '^ filter cost <= 1617000'
check "the brushed count is the filter's ($want)" "^ Parallel coordinates: run 1 \| $want of 75 options shown"
check "the axis title marks the brush" '\[cost\*\]'
check "the brush line shows the range" 'cost USD: brush 1,538,690 \.\. 1,617,000 USD'
keys h h e C-u :1.5 Enter
want2=$(count 'cost <= 1617000 and planarity <= 1.5')
check "e types a range on planarity, added to the filter" '^ filter \(planarity <= 1\.5\) and \(cost <= 1617000\)'
check "the typed range narrows the set ($want2)" "run 1 \| $want2 of 75 options shown"
keys x
check "x clears the axis's brush" "^ Parallel coordinates: run 1 \| $want of 75 options shown"
keys '?'
check "help lists the parallel coordinates' keys" 'Help: Parallel coordinates keys'
check "help names the brush keys" '\[ / \{ +raise / lower the low edge'
keys q q
check "q goes back to the table, filtered by the brush" "^ row [0-9,]+ of $want  .* filter cost <= 1617000"
keys x
check "the scatter shows the brushed set too" "^ Scatter: .*\| $want points"
keys q a X
check "X clears every brush" '^ Parallel coordinates: run 1 \| 75 of 75 options shown'
keys p
check "p shows Pareto options only here too" '3 of 75 options shown \| Pareto only'
keys p q
check "back in the table every option shows" '^ row [0-9,]+ of 75  .*filter none *$'
keys C
check "C opens the column chooser" 'Columns: 12 of 30 shown, 80 characters'
keys j j Space
check "Space hides planarity" '\[ \] planarity'
keys G Space K K K K K K K K K K K K K K K K K K K K K K K K K K K K Enter
check "hidden planarity, gen shown second" '^ +No\. +gen P +DP area +cost '
keys q Enter
check "the chosen columns stay for the session" '^ +No\. +gen P +DP area +cost '
keys F2 r Enter
check "r brings the default columns back" 'No\. P planarity +DP area +cost +FP area +SP area +U +V +t +ok rank'
keys K Enter
check "Enter opens the panel map" '^ Panel map: option 73 of run 1 \| grid 8 x 8 \| t 2\.00 mm \| by type'
check "legend by type with counts and areas" 'FP +16 +296\.7'
check "the cursor's panel is described" 'class flat +type FP +area [0-9.]+ m\^2'
keys l l j
check "the cursor moves over panels" 'Panel \(2, 6\)'
check "a panel shows k1, k2, K, H and deviation" 'k1 [-0-9.e]+ +k2 [-0-9.e]+ 1/m +K [-0-9.e]+ 1/m\^2 +H [-0-9.e]+ 1/m +deviation'
keys c
check "c colours by class" 'by class'
concave=$(sqlite3 "$WORK/t.db" "SELECT count(*) FROM panels WHERE run = 1 AND option = 73 AND class = 'concave_feature_curve'")
check "class legend, its count sqlite3's ($concave)" "concave feature +$concave "
keys q g Space Space c
check "Space marks and c compares" '^ Compare 2 options of run 1'
check "compare shows differences to the first" 'cost +USD +min +1,538,690 +1,538,690'
check "compare shows the panel maps under the metrics" '^ panel maps, one scale +8 x 7 +8 x 7'
maps=$(screen | grep -E '^ F FP +[FSD]+ +[FSD]+ *$' | awk '{print length($3), length($4)}')
if [ -n "$maps" ] && [ "$(echo $maps | tr ' ' '\n' | sort -u | wc -l)" = 1 ]; then
    pass "the maps are drawn at one size ($maps)"
else
    echo "not ok - the maps are drawn at one size ($maps)"
    screen | sed 's/^/  screen: /'
fi
keys m
check "m hides the maps: the metrics take the room (down to rank, the hint below)" '^ rank '
check_not "m hides the maps" '^ panel maps'
keys m
keys q
"${TMUX_CMD[@]}" resize-window -x 200 -y 60
check "resize to 200x60 shows the side pane" 'Selected option.*'
check "the side pane lists every metric" 'max panel area +23\.70 m\^2'
"${TMUX_CMD[@]}" resize-window -x 80 -y 24
check "back at 80x24 the bottom pane returns" '^ No\. [0-9]+: '
keys q
check "q goes back to the runs" '^ Facet runs'
keys d
check "d asks before deleting" 'Delete run 1 with its options and panels\? \(y/n\)'
keys n
check "n keeps the run" 'run 1 kept'
keys F10
check_exit "F10 quits with status 0 and the terminal restored"

# --- 200x60 from the start, ended by SIGTERM ---
start 200 60 -- t.db
check "200x60: runs screen shows the start time" 'started'
keys Enter
check "200x60: options table with the side pane" '^ +73 .* 1,551,317 .* Selected option|Selected option'
check "200x60: every row fits" '^ +1 (✗|x) +0\.000 +942\.6 +1,638,833'
keys '|'
check "200x60: parallel coordinates with every axis" ' U +V +t +planarity +DP area +\[cost\] +FP area +SP area'
keys '[' '[' '['
check "200x60: [ raises the low edge of cost" '^ filter cost >= 1[0-9]{6}$'
keys q C G Space Enter
check "200x60: a chosen column shows beside the default ones" 'rank +gen'
keys g Space j Space c
check "200x60: compare shows every metric and the maps" '^ panel maps, one scale +[0-9]+ x [0-9]+ +[0-9]+ x [0-9]+'
i=0; while [ ! -s "$WORK/pid" ] && [ $i -lt $POLLS ]; do sleep 0.05; i=$((i + 1)); done
kill -TERM "$(cat "$WORK/pid")"
check_exit "SIGTERM ends it with the terminal restored"

# --- ASCII and monochrome ---
start 80 24 LC_ALL=C NO_COLOR=1 -- t.db
keys Enter
check "ASCII locale: plain Pareto marks" '^ +74 \* +2\.522'
check "ASCII locale: plain sort arrow" '\^USD'
keys '|'
check "ASCII locale: parallel coordinates drawn in slopes" '^ +o-{9}\|'
keys q
keys F10
check_exit "ASCII session quits cleanly"

# --- resume a run interrupted by SIGINT, watched to the end ---
# (the database is made first: two processes creating one schema at once
# is another test's matter)
"$FACET" runs "$WORK/r.db" >/dev/null 2>&1
"$FACET" optimize "$WORK/roof.obj" --db "$WORK/r.db" --u 4:40 --v 4:40 \
    --threshold 2:4:1 >/dev/null 2>&1 &
writer=$!
i=0
while [ $i -lt $((POLLS * 4)) ]; do
    "$FACET" runs "$WORK/r.db" 2>/dev/null | grep -qE '^ +1 running +[a-z0-9]+ +[1-9]' && break
    sleep 0.05
    i=$((i + 1))
done
kill -INT $writer
wait $writer
if "$FACET" runs "$WORK/r.db" | grep -qE '^ +1 interrupted'; then
    pass "SIGINT leaves the run interrupted"
else
    echo "not ok - SIGINT leaves the run interrupted"
    "$FACET" runs "$WORK/r.db" | sed 's/^/  runs: /'
fi
start 80 24 -- r.db
check "the runs screen shows the interrupted run" '^ +1 interrupted +exhaustive'
check "the bar offers Resume" 'F6Resume'
keys R
check "R resumes it with a gauge in the status line" '^run 1 .*(options \([0-9]+%\)|Ctrl-X stops)'
check_slow "the resumed run is watched to the end" '^ +1 done +exhaustive +4107 '
# The table shows the run done (from the store) a moment before the job
# that ran it ends and says so on the status line; R pressed between the
# two had its answer overwritten by that line.
check_slow "the status line says the run is done" '^run 1 done: 4107 options'
keys R
check "a done run does not resume" 'run 1 is done; only an interrupted or failed run resumes'
keys '?'
check "help names the resume key" 'R, F6 +resume a stopped'
keys q F10
check_exit "quits after a resume"

# --- facet tui SURFACE.obj: the New run form, run watched to the end ---
rm -f "$WORK/facet.db"
mkdir -p "$WORK/surfaces"
cp "$WORK/roof.obj" "$WORK/surfaces/a.obj"
cp "$WORK/roof.obj" "$WORK/surfaces/b.obj"
start 80 24 -- roof.obj
check "a missing facet.db is asked about first" '^facet\.db does not exist\. Create a new result database there\? \(y/n\)'
keys y
check "SURFACE.obj opens the New run form" '^ New run into facet\.db'
check "the form holds the surface" 'Surface \(OBJ\) +roof\.obj'
check "the form has prices, SP as FP and the largest panel" 'Prices FP,SP,DP +701,766,1518'
check "SP as FP defaults to no" 'SP priced as FP +no'
check "max panel area defaults to the paper's" 'Max panel m\^2 +7\.06'
keys Up C-u su Tab
check "Tab completes a directory" 'Surface \(OBJ\) +surfaces/ *$'
keys Tab Tab
check "Tab again lists the choices" '2 choices'
check "the choices are the OBJ files" '^ a\.obj +b\.obj'
keys C-u ro Tab
check "Tab completes a file" 'Surface \(OBJ\) +roof\.obj *$'
keys Tab
check "Tab on a complete path goes to the next field" 'm, cm, mm, in or ft'
keys Down Down Down Down Down Down C-u abc F5
check "a bad price is refused, naming the field" "new run: Prices FP,SP,DP: 'abc' is not FP,SP,DP"
keys C-u 700,766,1518 Down C-u yes Down C-u 9.5 Up Up Up Up Up Up Up Up
keys Down C-u 4:5 Down C-u 4:6 F5
check "F5 starts the run and opens its table" '^ Run 1 roof\.obj \| exhaustive'
check "the run is watched to the end" '^ Run 1 roof\.obj \| exhaustive \| done \| 6 options'
check "its options fill the table" '^ row [0-9,]+ of 6 '
keys Escape Escape
check "Esc goes back to the runs" '^ Facet runs +facet\.db +\(1 run\)'
keys a
check "a opens the New run form" '^ New run into facet\.db'
keys roof.obj Down Down C-u 4:40 Down C-u 4:40 Down C-u 2:4:1 F5
check "a bigger run starts and its table opens" '^ Run 2 roof\.obj \| exhaustive \| running'
keys C-x
check "Ctrl-X stops it and says how to go on" 'run 2 stopped with [0-9]+ options stored'
keys Escape Escape
check "the stopped run is interrupted" '^ +2 interrupted +exhaustive'
keys k R
check "a run is selected with k, and a stopped one is not" "run 1 is done; only an interrupted or failed run resumes"
keys j R
check_slow "R resumes the run stopped from the UI to the end" '^ +2 done +exhaustive +4107 '
keys F10
check_exit "quits after a New run"
# the database and the surface named both, or by flag, whatever their names
cp "$WORK/roof.obj" "$WORK/roof.mesh"
start 80 24 -- two.db roof.obj
check "DB SURFACE: a missing DB is asked about" '^two\.db does not exist\. Create'
keys y
check "DB SURFACE opens the New run form into DB" '^ New run into two\.db'
check "DB SURFACE: the form holds the surface" 'Surface \(OBJ\) +roof\.obj'
keys Escape
check "DB SURFACE: Esc goes back to the runs" '^ Facet runs +two\.db'
keys F10
check_exit "quits (DB SURFACE)"
start 80 24 -- --db two.db --surface roof.mesh
check "--db and --surface: the form, whatever the surface's name" 'Surface \(OBJ\) +roof\.mesh'
check "--db and --surface: into the DB given" '^ New run into two\.db'
keys Escape
check "--db and --surface: Esc goes back to the runs" '^ Facet runs +two\.db'
keys F10
check_exit "quits (--db --surface)"
# (read after the workbench quits: see the note on store_open in the
# report: another process closing the database while the workbench runs
# a job can leave the workbench on a stale view)
got=$(sqlite3 "$WORK/facet.db" "select price_fp || ',' || price_sp || ',' || price_dp || ' ' || sp_as_fp || ' ' || max_panel_area_limit from runs where id = 1")
if [ "$got" = "700.0,766.0,1518.0 1 9.5" ]; then
    pass "the run has the form's prices, SP as FP and largest panel"
else
    echo "not ok - the run has the form's prices, SP as FP and largest panel (got '$got')"
fi

# --- without a terminal ---
expect_error "tui without a terminal is refused" 'needs a terminal' \
    "$FACET" tui "$WORK/t.db"
