#!/usr/bin/env bash
# End-to-end: a sorted listing puts every feasible option before every
# infeasible one, each part in the order asked for, unless asked
# otherwise (issue 32 item 19). The run's cheapest options are infeasible
# (their largest panel is over the limit). The orders expected are made
# here from the rows as sqlite3 reads them, sorted in Python.
# layers: store cli
. "$(dirname "$0")/lib.sh"

fixture roof40.obj "$WORK/roof.obj" || exit 1
"$FACET" optimize "$WORK/roof.obj" --db "$WORK/f.db" --u 36:40 --v 16:20 \
    --threshold 3 --sp-as-fp --max-panel-area 1.92 --panel-cost 150 \
    --joint-cost 60 --mould-cost 1500,6000 --objectives cost,moulds \
    >/dev/null 2>&1 || exit 1
sqlite3 -csv "$WORK/f.db" \
    "SELECT number, feasible, printf('%.17g', cost) FROM options WHERE run = 1" \
    >"$WORK/rows.csv"
same "the cheapest option is infeasible, and some are feasible" \
    "$(sqlite3 "$WORK/f.db" "SELECT (SELECT feasible FROM options ORDER BY cost LIMIT 1), max(feasible) FROM options")" \
    "0|1"

# expected ORDER: the numbers of rows.csv in the order python sorts them
expected() {
    python3 - "$WORK/rows.csv" "$1" <<'PY'
import csv, sys
rows = [(int(n), int(f), float(c)) for n, f, c in csv.reader(open(sys.argv[1]))]
key = {"first": lambda r: (-r[1], r[2]),
       "first-desc": lambda r: (-r[1], -r[2]),
       "mixed": lambda r: (r[2],)}[sys.argv[2]]
print(",".join(str(r[0]) for r in sorted(rows, key=key)))
PY
}
# listed ARGS...: the numbers facet options lists, in its order
listed() {
    "$FACET" options "$WORK/f.db" --run 1 --csv "$@" |
        python3 -c 'import csv, sys; r = list(csv.DictReader(sys.stdin)); print(",".join(x["number"] for x in r))'
}

same "options --sort cost: the feasible first, each part by cost" \
    "$(listed --sort cost)" "$(expected first)"
same "options --sort cost --desc: the feasible still first, each part by cost down" \
    "$(listed --sort cost --desc)" "$(expected first-desc)"
same "options --sort cost --infeasible-mixed: by cost alone" \
    "$(listed --sort cost --infeasible-mixed)" "$(expected mixed)"
same "options --sort cost --limit 3: the three cheapest feasible" \
    "$(listed --sort cost --limit 3)" "$(expected first | cut -d, -f1-3)"
same "options without --sort: by number, as stored" \
    "$(listed)" "$(sqlite3 "$WORK/f.db" "SELECT number FROM options WHERE run = 1 ORDER BY number" | paste -sd, -)"
run "$FACET" options --help
stdout_has "options --help says how to mix them" '--infeasible-mixed'
