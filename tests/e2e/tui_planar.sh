#!/usr/bin/env bash
# End-to-end: the workbench's panel map colours a planarized option by how
# far each corner moved (issue 33, item 3), in tmux at 100x30: the levels
# count the panels sqlite3 counts by corner_moved against the legend's
# bounds; a classified option has no such colouring, and c says "not a
# planarized option" and goes on to the next. A small surface of
# revolution (planarize_check.py vase), 10 x 8 panels.
# layers: tui
. "$(dirname "$0")/lib.sh"

. "$(dirname "$0")/tui_lib.sh"

if ! command -v sqlite3 >/dev/null; then
    echo "skip - every corner move check (sqlite3 is not installed)"
    exit 0
fi
HERE=$(cd "$(dirname "$0")" && pwd)
/usr/bin/python3 "$HERE/planarize_check.py" vase "$WORK/vase.obj" || exit 1
"$FACET" optimize "$WORK/vase.obj" --db "$WORK/p.db" --u 10:10 --v 8:8 \
    --threshold 3 --planarize 0.1 >/dev/null 2>&1 ||
    { echo "not ok - optimize --planarize makes the run"; exit 1; }
q() { sqlite3 "$WORK/p.db" "$1"; }
planar=$(q "select number from options where planarized = 1")
classified=$(q "select number from options where planarized = 0")

start 100 30 -- p.db
check "the runs list the run" '^ +1 done +exhaustive'
keys g Enter
# sorted by cost: the planarized option (all FP) is the cheaper, first
check "run 1 opens, the planarized option first" "^ +$planar .* 10 +8 "
keys m
check "its map opens" "^ Panel map: option $planar of run 1"
keys c c c c c
check "c reaches the corner move colouring" "by corner move"
check "the legend states the budget and that it is planar" \
    "budget 0.1 mm: planar within it"
# the levels' panels, as sqlite3 counts them under the legend's bounds
bounds=$(screen | grep -oE '[0-3] [<>]=? [0-9.]+ mm +[0-9]+' | head -4)
want=$(q "select count(*) from panels where option = $planar and corner_moved is not null")
got=$(echo "$bounds" | awk '{s += $NF} END {print s}')
same "the levels hold every moved panel ($want)" "$got" "$want"
check "its far corner is stated in mm" "moved at most [0-9.]+ mm"
keys q
check "back to the options" "^ No\. $planar: "
keys Down
check "the classified option selected" "^ No\. $classified: "
keys m
check "the classified option's map opens" "^ Panel map: option $classified of run 1"
keys c c c c c
check "c skips corner move on a classified option, and says why" \
    "corner move: not a planarized option"
check_not "no corner move colouring on a classified option" "by corner move"
exit 0
