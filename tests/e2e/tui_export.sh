#!/usr/bin/env bash
# End-to-end: exports from the terminal UI (issue 6): the panel map writes
# the option as OBJ + MTL, CSV schedule and SVG map, the scatter writes the
# run's plot; the files are whole and valid, an existing file is refused
# unless the name ends with '!', and the UI reports it all on its status
# line.
# layers: tui
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/tui_lib.sh"

fixture roof40.obj "$WORK/roof.obj" || exit 1
"$FACET" optimize "$WORK/roof.obj" --db "$WORK/t.db" --u 4:8 --v 4:8 \
    --threshold 2:4:1 >/dev/null 2>&1 || exit 1
KNEE=$(sqlite3 "$WORK/t.db" 'SELECT knee FROM runs WHERE id = 1')
PANELS=$(sqlite3 "$WORK/t.db" "SELECT panels FROM options WHERE run = 1 AND number = $KNEE")
PREFIX=facet-run1-option$KNEE

start 80 24 -- t.db
check "runs screen" '^ +1 done +exhaustive'
keys Enter
check "options table" '^ Run 1 roof\.obj'
keys K
keys Enter
check "the knee's panel map" "Panel map: option $KNEE of run 1"
check "the bar offers Export on F9" 'F9Export'
keys e
check "export asks for a prefix, offering one" "Export to \\(prefix\\): *$PREFIX"
keys Enter
check "export says what it wrote" "wrote $PREFIX\\.obj \\(\\+ \\.mtl\\)"
for ext in obj mtl csv svg; do
    if [ -s "$WORK/$PREFIX.$ext" ]; then pass "$PREFIX.$ext written"; else fail "$PREFIX.$ext written"; fi
done
if [ -z "$(find "$WORK" -name '*.partial')" ]; then pass "no .partial left"; else fail "no .partial left"; fi
groups=$(grep -c '^g panel_' "$WORK/$PREFIX.obj")
same "the OBJ has one group per panel" "$groups" "$PANELS"
same "the CSV has one row per panel, its totals beside it" \
    "$(($(wc -l <"$WORK/$PREFIX.csv") - 1)) $(wc -l <"$WORK/$PREFIX-totals.csv")" "$PANELS 2"
if xmllint --noout "$WORK/$PREFIX.svg" 2>/dev/null; then pass "the map SVG is valid"; else fail "the map SVG is valid"; fi
same "the map SVG has one mark per panel" "$(grep -o '<path class="panel' "$WORK/$PREFIX.svg" | wc -l)" "$PANELS"

before=$(stat -c %Y.%s "$WORK/$PREFIX.obj")
keys e Enter
check "exporting again is refused: the file exists" "export: .*$PREFIX\\.obj exists"
same "the refused export left the file alone" "$(stat -c %Y.%s "$WORK/$PREFIX.obj")" "$before"
keys e BSpace BSpace BSpace BSpace BSpace BSpace BSpace BSpace BSpace BSpace \
    BSpace BSpace BSpace BSpace BSpace BSpace BSpace BSpace BSpace BSpace \
    BSpace BSpace BSpace BSpace BSpace BSpace BSpace BSpace BSpace BSpace
keys -l "/nonexistent/x" 
keys Enter
check "an unwritable path is an error on the status line" "export: cannot write /nonexistent/x"
keys e "!" Enter
check "a name ending with ! overwrites" "wrote $PREFIX\\.obj"

keys q
check "back in the table" '^ Run 1 roof\.obj'
keys x
check "the scatter" 'planarity'
keys e
check "the scatter asks where to plot" 'Plot to: *facet-run1-plot\.svg'
keys Enter
check "the scatter says what it wrote" 'wrote facet-run1-plot\.svg'
if xmllint --noout "$WORK/facet-run1-plot.svg" 2>/dev/null; then pass "the plot SVG is valid"; else fail "the plot SVG is valid"; fi
same "the plot has one circle per option" "$(grep -o '<circle' "$WORK/facet-run1-plot.svg" | wc -l)" \
    "$(sqlite3 "$WORK/t.db" 'SELECT count(*) FROM options WHERE run = 1')"
keys F10
check_exit "quit: status 0, no stderr, terminal given back"
