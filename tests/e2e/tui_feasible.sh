#!/usr/bin/env bash
# End-to-end: the workbench's options table sorts the feasible options
# first, each part by the keys, unless F asks otherwise; an infeasible row
# is dim and marked x in the P column (seen under TERM=vt100 and NO_COLOR,
# where dim is not shown), and the detail pane names the limit it breaks;
# a front's end reads "crowding boundary", not "inf" (issue 32 item 19), and
# "boundary" in the crowding column (issue 32).
# Figures come from sqlite3, the orders from its rows sorted in Python.
# layers: store tui
. "$(dirname "$0")/lib.sh"

. "$(dirname "$0")/tui_lib.sh"

if ! command -v sqlite3 >/dev/null; then
    echo "skip - every check (sqlite3 is not installed)"
    exit 0
fi
fixture roof40.obj "$WORK/roof.obj" || exit 1
"$FACET" optimize "$WORK/roof.obj" --db "$WORK/f.db" --u 36:40 --v 16:20 \
    --threshold 3 --sp-as-fp --max-panel-area 1.92 --panel-cost 150 \
    --joint-cost 60 --mould-cost 1500,6000 --objectives cost,moulds \
    >/dev/null 2>&1 || exit 1
q() { sqlite3 "$WORK/f.db" "$1"; }
q "SELECT number, feasible, printf('%.17g', cost) FROM options WHERE run = 1" \
    | tr '|' ',' >"$WORK/rows.csv"
# order KEY: the option numbers in the order KEY sorts them
order() {
    python3 - "$WORK/rows.csv" "$1" <<'PY'
import csv, sys
rows = [(int(n), int(f), float(c)) for n, f, c in csv.reader(open(sys.argv[1]))]
key = {"first": lambda r: (-r[1], r[2], r[0]),
       "mixed": lambda r: (r[2], r[0])}[sys.argv[2]]
print(" ".join(str(r[0]) for r in sorted(rows, key=key)))
PY
}
read -ra first <<<"$(order first)"
read -ra mixed <<<"$(order mixed)"
n=${#first[@]}
same "the cheapest option is infeasible" "$(q "SELECT feasible FROM options WHERE number = ${mixed[0]}")" 0
last=${first[$((n - 1))]}
same "the last in feasible-first order is infeasible" "$(q "SELECT feasible FROM options WHERE number = $last")" 0
area=$(q "SELECT printf('%.2f', max_panel_area) FROM options WHERE number = $last")

start 100 30 TERM=vt100 NO_COLOR=1 LANG=C LC_ALL=C -- f.db
keys Enter
check "the table opens sorted by cost, the feasible first" "^ row 1 of $n  sort feasible first, cost asc"
check_line "its first row is the cheapest feasible option" 5 "^ +${first[0]} [^x] "
check "an infeasible row is marked x in the P column" "^ +${mixed[0]} x "
check_not "a feasible row is not" "^ +${first[0]} x "
keys G
check "the last row is the dearest infeasible option" "^ row $n of $n"
check "the detail pane names the limit it breaks" \
    "No\. $last: .*infeasible: panel $area m\^2 > 1\.92 m\^2 limit"
check_not "no crowding reads inf" "crowding inf"
keys g
check "a front's end reads as a boundary" "crowding boundary"
keys F
check "F sorts by the keys alone" "^ row [0-9]+ of $n  sort cost asc  filter none"
check_line "the first row is then the cheapest option, infeasible" 5 "^ +${mixed[0]} x "
keys F
check "F again puts the feasible first" "sort feasible first, cost asc"
keys '?'
check "help names F" "^ *F +sorted, the feasible options first"
keys q q q y

# Dim, where the terminal shows it: the infeasible rows, not the feasible.
start 100 30 NO_COLOR=1 -- f.db
keys Enter
check "opens in colour-less xterm" "sort feasible first, cost asc"
dim=$("${TMUX_CMD[@]}" capture-pane -p -e | grep -c $'\e\\[2m *'"${mixed[0]}"$'\e')
same "an infeasible row is drawn dim (SGR 2)" "$dim" 1
dim=$("${TMUX_CMD[@]}" capture-pane -p -e | grep -c $'\e\\[2m *'"${first[1]}"$'\e')
same "a feasible row is not" "$dim" 0

# Issue 32: the table's crowding cell of a front's end read "inf"; it reads
# "boundary", as the detail pane does, and an inner option of the front its
# crowding distance. A front of many options (cost and planarity); the
# truth: sqlite3, where a front's end is a ranked option whose crowding is
# NULL.
"$FACET" optimize "$WORK/roof.obj" --db "$WORK/c.db" --u 36:40 --v 16:20 \
    --threshold 1:6:1 >/dev/null 2>&1 || exit 1
qc() { sqlite3 "$WORK/c.db" "$1"; }
ends=$(qc "SELECT number FROM options WHERE run = 1 AND rank = 1 AND crowding IS NULL ORDER BY number")
inner=$(qc "SELECT number || ' ' || printf('%.3f', crowding) FROM options WHERE run = 1 AND rank = 1 AND crowding IS NOT NULL ORDER BY number")
same "the front has two ends and inner options" "$(echo "$ends" | wc -l) $([ "$(echo "$inner" | wc -l)" -gt 2 ] && echo many)" "2 many"
start 120 40 LANG=C.UTF-8 -- c.db
keys Enter
check "the table opens" "sort feasible first, cost asc"
# the column chooser: crowding is the 29th column (tui_option_columns)
keys F2
check "the column chooser opens" "Columns: 12 of"
for _ in $(seq 28); do keys Down; done
keys Space Enter
check "the crowding column is shown" "^ +No\. .* crowd *$"
keys F4
front=$(qc "SELECT count(*) FROM options WHERE run = 1 AND rank = 1")
check "F4: the front alone, $front options (sqlite3)" "^ row 1 of $front "
for e in $ends; do
    check "front's end No. $e: its crowding cell reads boundary" "^ +$e .* boundary *$"
done
while read -r number crowding; do
    check "inner No. $number: its crowding $crowding" "^ +$number .* $crowding *$"
done <<<"$inner"
check_not "no crowding cell reads inf" " inf *$"
keys q q y
