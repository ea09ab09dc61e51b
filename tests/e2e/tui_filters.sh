#!/usr/bin/env bash
# End-to-end: the workbench's filter line and the parallel coordinates
# (issue 32 items 10 and 11), in tmux under TERM=vt100, NO_COLOR and the C
# locale (ASCII glyphs, no colour, no dim shown):
#   - after a mistyped filter, / opens on the mistyped text, to be mended;
#     Up and Down go through the filters entered before, as a shell does,
#     and past the newest back to what was being typed; the scatter's /
#     shares them;
#   - a filter typed with / shows on the parallel coordinates as brushes
#     (the axis marked *, its brushed stretch #, the brush's range with
#     its strict edge said), and without colours the options it hides are
#     dotted, so that the picture changes with the filter.
# layers: tui
. "$(dirname "$0")/lib.sh"

. "$(dirname "$0")/tui_lib.sh"

fixture roof40.obj "$WORK/roof.obj" || exit 1
"$FACET" optimize "$WORK/roof.obj" --db "$WORK/t.db" --u 4:8 --v 4:8 \
    --threshold 2:4:1 --sp-fit no >/dev/null 2>&1 || exit 1

# --- item 10: the filter line keeps its text and its history ---
start 100 30 TERM=vt100 NO_COLOR=1 LANG=C LC_ALL=C -- t.db
keys Enter
check "the table opens" '^ Run 1 '
keys / 'cost < 2M and dp_aera > 1' Enter
check "a mistyped filter is refused" "filter: column 15: unknown column 'dp_aera'"
keys /
check "/ opens on the mistyped text, to be mended" '^Filter: cost < 2M and dp_aera > 1 *$'
keys C-u 'cost < 1.6M' Enter
check "a good filter is taken" 'filter cost < 1600000'
keys / C-u 'dp' Up
check "Up brings back the last filter" '^Filter: cost < 1\.6M *$'
keys Up
check "Up again, the one before (the mistyped one)" '^Filter: cost < 2M and dp_aera > 1 *$'
keys Up
check "Up at the oldest keeps it" '^Filter: cost < 2M and dp_aera > 1 *$'
keys Down
check "Down, the newer one" '^Filter: cost < 1\.6M *$'
keys Down
check "Down past the newest: what was being typed" '^Filter: dp *$'
keys Escape
keys x
check "the scatter opens" 'cost'
keys / C-u Up
check "the scatter's / shares the history" '^Filter: cost < 1\.6M *$'
keys Escape q

# --- item 11: a typed filter is brushes; without colours it shows ---
# The plot's rows: between the axes' top labels (line 4) and the bottom
# labels, before the brush line.
plot() { screen | sed -n '5,/^ [A-Za-z]* .*: \(no \)\?brush/p' | sed '$d' | head -n -1; }
keys / C-u Enter
check "no filter" 'filter none'
keys '|'
check "parallel coordinates, unfiltered" '^ Parallel coordinates: run 1 \| 75 of 75 options shown'
plot >"$WORK/plain"
if grep -q '[#.]' "$WORK/plain"; then
    fail "unfiltered: no brush (#) and nothing dotted (.)"
    sed 's/^/  plot: /' "$WORK/plain"
else
    pass "unfiltered: no brush (#) and nothing dotted (.)"
fi
keys q / C-u 'cost < 1.6M and dp_area <= 1000' Enter
check "the filter is taken" 'filter \(cost < 1600000\) and \(dp_area <= 1000\)'
keys '|'
shown=$("$FACET" options "$WORK/t.db" --run 1 --where 'cost < 1.6M and dp_area <= 1000' --csv | tail -n +2 | wc -l)
check "parallel coordinates, filtered" "^ Parallel coordinates: run 1 \\| $shown of 75 options shown"
check "the filtered axes are marked brushed" 'DP area\*.*cost\*'
check "the cost brush: its strict edge said" ' cost USD: brush .* \.\. under 1,600,000 USD'
plot >"$WORK/filtered"
if grep -q '#' "$WORK/filtered"; then pass "the brushes show on their axes (#)"
else fail "the brushes show on their axes (#)"; sed 's/^/  plot: /' "$WORK/filtered"; fi
if grep -q '\.' "$WORK/filtered"; then pass "the options the filter hides are dotted"
else fail "the options the filter hides are dotted"; sed 's/^/  plot: /' "$WORK/filtered"; fi
if cmp -s "$WORK/plain" "$WORK/filtered"; then
    fail "without colours the filtered plot differs from the unfiltered one"
else
    pass "without colours the filtered plot differs from the unfiltered one"
fi
keys q q q y
