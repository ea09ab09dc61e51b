#!/usr/bin/env bash
# End-to-end: ties are ties. Runs on surfaces with exact symmetries (a
# torus section, a barrel vault), whose mirror-image grids have totals
# equal in exact arithmetic and different by rounding, checked against the
# SQLite file and a brute force with the same tolerance (docs/decisions.md,
# Ties): ranks, knee and hypervolume; the order of `facet options
# --sort` and of Table 2 (a tie falls to the next key, then to the
# number); and every double of --json and --csv, read back, is the stored
# one bit for bit.
# layers: core study cli
. "$(dirname "$0")/lib.sh"

HERE=$(cd "$(dirname "$0")" && pwd)
RANKS=(/usr/bin/python3 "$HERE/optimize_check.py" ranks)
CHECK=(/usr/bin/python3 "$HERE/ties_check.py")

check() {
    local name=$1
    shift
    run "$@"
    if [ "$STATUS" -eq 0 ]; then pass "$name"; else fail "$name"; fi
}

DB=$WORK/ties.db
"$FACET" example torus -o "$WORK/torus.obj" || exit 1
"$FACET" example cylinder --res 80 -o "$WORK/cylinder.obj" || exit 1

# 1. The issue's case: the torus over the paper's grids at 3 mm.
expect "torus: exhaustive u 20:40 x v 35:50 at 3 mm" 0 \
    "$FACET" optimize "$WORK/torus.obj" --db "$DB" --u 20:40 --v 35:50 \
    --threshold 3 --table 0
cp "$OUT" "$WORK/table1"
check "torus: ranks, knee and hypervolume = brute force with ties" \
    "${RANKS[@]}" "$DB" 1
check "torus: Table 2 cheapest first, a cost tie by planarity, DP area, No." \
    "${CHECK[@]}" table "$DB" 1 "$WORK/table1"

expect "cylinder: exhaustive, stepped thresholds" 0 \
    "$FACET" optimize "$WORK/cylinder.obj" --db "$DB" --u 10:24 --v 10:24 \
    --threshold 1:3:1
check "cylinder: ranks, knee and hypervolume = brute force with ties" \
    "${RANKS[@]}" "$DB" 2

# 2. facet options --sort: ties fall to the next key, then the number.
# order NAME RUN SORT DESC FORMAT [ARGS...]
order() {
    local name=$1 run=$2 sort=$3 desc=$4 format=$5
    shift 5
    local flags=(--run "$run" --sort "$sort" "--$format" "$@")
    [ "$desc" = 1 ] && flags+=(--desc)
    run "$FACET" options "$DB" "${flags[@]}"
    if [ "$STATUS" -ne 0 ]; then fail "$name"; return; fi
    cp "$OUT" "$WORK/listing"
    check "$name" "${CHECK[@]}" order "$DB" "$run" "$sort" "$desc" \
        "$WORK/listing" "$format"
}
order "options --sort cost: tied costs by No., doubles as stored (json)" \
    1 cost 0 json
order "options --sort cost,planarity: tied costs by planarity (csv)" \
    1 cost,planarity 0 csv
order "options --sort dp_area,cost --desc --limit 25 (json)" \
    1 dp_area,cost 1 json --limit 25
order "options --sort cost,planarity on the cylinder (csv)" \
    2 cost,planarity 0 csv
order "options --sort crowding,cost (json)" 1 crowding,cost 0 json

# 3. Every double printed reads back as the stored one.
KNEE=$(sqlite3 -batch "$DB" 'SELECT knee FROM runs WHERE id = 1')
run "$FACET" show "$DB" --run 1 --option "$KNEE" --json
cp "$OUT" "$WORK/show.json"
check "show --json: every panel double is the stored one" \
    "${CHECK[@]}" exact-show "$DB" 1 "$KNEE" "$WORK/show.json"
run "$FACET" runs "$DB" --json
cp "$OUT" "$WORK/runs.json"
check "runs --json: hypervolume, best cost, elapsed as stored" \
    "${CHECK[@]}" exact-runs "$DB" "$WORK/runs.json"
expect "export --csv of the knee" 0 \
    "$FACET" export "$DB" --run 1 --option "$KNEE" --csv "$WORK/knee.csv"
check "export --csv: every panel double is the stored one" \
    "${CHECK[@]}" exact-schedule "$DB" 1 "$KNEE" "$WORK/knee.csv"
