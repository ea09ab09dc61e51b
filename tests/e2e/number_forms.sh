#!/usr/bin/env bash
# End-to-end: the numbers of facet options --csv and --json carry their
# units and their kind as a script reads them (issue 32 item 4). The CSV
# header names each column with its unit, as the panel schedule's totals
# CSV does (cost_usd, max_deviation_m), the two headers one convention;
# sqlite3 itself imports the CSV (.import) and finds every value equal to
# the store's, column by column; JSON's booleans are true/false, as
# classify --json's; the tables people read (the final table, facet
# show) group thousands in counts and areas as they do in cost.
# layers: cli core
. "$(dirname "$0")/lib.sh"

"$FACET" example roof -o "$WORK/roof.obj" >/dev/null || exit 1
DB=$WORK/r.db
expect "a run of grids of thousands of panels" 0 "$FACET" optimize "$WORK/roof.obj" --db "$DB" \
    --u 60:61 --v 60:61 --threshold 2:3:1 --objectives cost,panels --table 0
cp "$OUT" "$WORK/final.table"

# --- the CSV's header: the column and its unit (csv_names.py, from the
# units docs/store.md gives), never the bare name of a quantity with one
run "$FACET" options "$DB" --csv
head -n 1 "$OUT" >"$WORK/header"
same "options --csv: a header of the store's columns, each with its unit" \
    "$(cat "$WORK/header")" \
    "$(sqlite3 "$DB" "SELECT name FROM pragma_table_info('options') ORDER BY name = 'run' DESC, cid" |
        PYTHONPATH=$(dirname "$0") python3 -c 'import sys, csv_names; print(",".join(csv_names.csv_name(c) for c in sys.stdin.read().split()))')"
for name in cost_usd fp_area_m2 max_deviation_m p_dist_m4 max_gap_mm max_kink_deg threshold_mm panels feasible; do
    same "options --csv: the header has $name" "$(tr ',' '\n' <"$WORK/header" | grep -cx "$name")" "1"
done

# sqlite3 imports it, and every value is the store's (the CSV's empty
# field is SQL's NULL: crowding at a front's end).
sqlite3 "$WORK/import.db" ".mode csv" ".import $OUT imported" 2>"$ERR"
same "sqlite3 .import takes the CSV without a word" "$(cat "$ERR")" ""
pairs=$(sqlite3 "$DB" "SELECT name FROM pragma_table_info('options')" |
    PYTHONPATH=$(dirname "$0") python3 -c 'import sys, csv_names
for c in sys.stdin.read().split(): print(c, csv_names.csv_name(c))')
bad=""
while read -r column header; do
    differ=$(sqlite3 "$WORK/import.db" "ATTACH '$DB' AS s;
        SELECT count(*) FROM imported i JOIN s.options o
          ON o.run = CAST(i.run AS INTEGER) AND o.number = CAST(i.number AS INTEGER)
        WHERE NOT ((o.\"$column\" IS NULL AND i.\"$header\" = '')
                   OR CAST(i.\"$header\" AS REAL) = o.\"$column\");")
    [ "$differ" = 0 ] || bad="$bad $header:$differ"
done <<<"$pairs"
same "sqlite3: every column of every imported row is the store's value" "${bad# }" ""
same "sqlite3: as many rows as the store" \
    "$(sqlite3 "$WORK/import.db" 'SELECT count(*) FROM imported')" "$(sqlite3 "$DB" 'SELECT count(*) FROM options')"

# The export's totals CSV: the same names for the same quantities (after
# the import: an export measures its option in full and stores it).
"$FACET" export "$DB" --run 1 --option 1 --csv "$WORK/knee.csv" >/dev/null 2>&1
same "export's totals CSV: each of its columns named as options --csv names it" \
    "$(tr ',' '\n' <<<"$(head -n 1 "$WORK/knee-totals.csv")" | grep -cvxFf <(tr ',' '\n' <"$WORK/header"))" "0"

# --- JSON: booleans true/false, as classify --json's
run "$FACET" options "$DB" --json
json_check "options --json: feasible and knee are JSON booleans" \
    "all(type(o['feasible']) is bool and type(o['knee']) is bool for o in j)"
json_check "options --json: keys are the bare column names (cost, not cost_usd)" \
    "'cost' in j[0] and 'cost_usd' not in j[0]"
run "$FACET" classify "$WORK/roof.obj" --grid 10x10 --json
json_check "classify --json: feasible is a JSON boolean too" \
    "type(j['totals']['feasible']) is bool"

# --- thousands grouped in counts and areas as in cost, in what people
# read: the final table (panels an objective here) and facet show's
# totals; the truth is SQLite's values, grouped by Python's format.
grouped() { python3 -c 'import sys; print(format(float(sys.argv[1]), ",.%sf" % sys.argv[2]))' "$1" "$2"; }
row=$(sqlite3 -separator ' ' "$DB" "SELECT number, panels, area, area_cost, fp_count FROM options WHERE number = 1")
read -r number panels area area_cost fp_count <<<"$row"
same "final table: the panels column grouped as cost is ($(grouped "$panels" 0))" \
    "$(awk -v n="$number" '$1 == n' "$WORK/final.table" | grep -cw -- "$(grouped "$panels" 0)")" "1"
run "$FACET" show "$DB" --run 1 --option "$number"
same "show: the totals row groups panels, area and cost" \
    "$(grep '^total ' "$OUT" | awk '{print $2, $3, $5}')" \
    "$(grouped "$panels" 0) $(grouped "$area" 3) $(grouped "$area_cost" 2)"
same "show: the FP row groups its count" "$(grep '^FP ' "$OUT" | awk '{print $2}')" "$(grouped "$fp_count" 0)"
stdout_has "show: the grid line groups its panels" "^grid +[0-9]+ x [0-9]+ \\($(grouped "$panels" 0) panels\\)$"
