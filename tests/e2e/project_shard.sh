#!/usr/bin/env bash
# End-to-end: a project run (a building of many surfaces, searched over
# panel modules) cut into shards with --shard I/N and joined with facet
# merge (issue 17). The truth is the unsharded run, compared by SQLite
# itself (EXCEPT both ways over every column but the run id) in all three
# tables a project run fills: options, option_surfaces (each surface's
# part of every option) and surfaces. Exhaustive and random shards
# partition the run's distinct options (modules that give every surface the
# same grid are one option, in one shard only); NSGA-II islands merge into
# one ranked run with each island's surface rows; shards of another module
# range, of other files or of other per-surface grids are refused naming
# the difference; merging twice changes nothing; a missing shard is named.
# layers: study store cli
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/shard_lib.sh"
sql() { sqlite3 -batch "$1" "$2"; }

four_surfaces || exit 1
# The fixture's own file: the unsharded run (the fixture four.db) names it.
P=$(fixture_path four.obj) || exit 1
# 13 x 13 modules x 3 thresholds = 507 points; far fewer distinct options.
SPACE=(--module 1:4:0.25x1:4:0.25 --threshold 2:6:2 --method exhaustive)

# make_shards N PREFIX FILES... -- OPTIONS...: shard I of N of a project
# run into PREFIX I.db, for every I.
make_shards() {
    local n=$1 prefix=$2 i
    shift 2
    local files=()
    while [ "$1" != "--" ]; do files+=("$1"); shift; done
    shift
    for i in $(seq 1 "$n"); do
        "$FACET" optimize "${files[@]}" --db "$prefix$i.db" "$@" --shard "$i/$n" \
            --table 1 >/dev/null 2>"$WORK/shard.err" ||
            { echo "not ok - project shard $i/$n ran"; sed 's/^/  /' "$WORK/shard.err"; }
    done
}

# --- exhaustive: 3 shards dealt by distinct grid vector
# The unsharded run is the fixture four.db (SPACE, --jobs 2), which
# project_run.sh checks on its own.
expect_fixture "unsharded exhaustive project run" 0 four.db "$WORK/whole.db"
make_shards 3 "$WORK/ex" "$P" -- "${SPACE[@]}" --jobs 1
whole=$(sql "$WORK/whole.db" 'SELECT count(*) FROM options')
got=$(sql "$WORK/ex1.db" "ATTACH '$WORK/ex2.db' AS b; ATTACH '$WORK/ex3.db' AS c;
    SELECT count(*), count(DISTINCT number), min(number), max(number),
           count(DISTINCT nu || ' ' || nv || ' ' || threshold_mm) FROM
    (SELECT number, nu, nv, threshold_mm FROM main.options UNION ALL
     SELECT number, nu, nv, threshold_mm FROM b.options UNION ALL
     SELECT number, nu, nv, threshold_mm FROM c.options)")
same "the shards partition the run's distinct options (no option in two shards)" \
    "$got" "$whole|$whole|1|$whole|$whole"
same "each shard holds a third of the grid vectors, all thresholds of each" \
    "$(for i in 1 2 3; do sql "$WORK/ex$i.db" "SELECT count(*) % 3, count(DISTINCT nu || ' ' || nv) * 3 = count(*) FROM options"; done | tr '\n' ' ')" \
    "0|1 0|1 0|1 "
same "a project shard records its surfaces and I/N" \
    "$(sql "$WORK/ex2.db" "SELECT (SELECT count(*) FROM surfaces), shard_index || '/' || shard_count FROM runs")" "4|2/3"
same "a shard's options each have their four surface rows" \
    "$(sql "$WORK/ex2.db" 'SELECT (SELECT count(*) FROM option_surfaces) = 4 * (SELECT count(*) FROM options)')" "1"

expect "merge of 3 project shards" 0 "$FACET" merge "$WORK/merged.db" "$WORK/ex3.db" "$WORK/ex1.db" "$WORK/ex2.db"
stdout_has "merge says what it made" "run 1 merged from 3 of 3 shards: $whole options"
same_options "merged project run = unsharded: options, ranks, front, hypervolume, knee" "$WORK/whole.db" "$WORK/merged.db"
same_rows "merged project run = unsharded: every surface row of every option" "$WORK/whole.db" "$WORK/merged.db" option_surfaces
same_rows "merged project run = unsharded: its surfaces" "$WORK/whole.db" "$WORK/merged.db" surfaces
same "merged project run records its module range" \
    "$(sql "$WORK/merged.db" 'SELECT module_w_min, module_w_max, module_w_step, module_h_min, module_h_max, module_h_step, shards_merged FROM runs')" \
    "1.0|4.0|0.25|1.0|4.0|0.25|3"
run "$FACET" show "$WORK/merged.db" --run 1 --option "$(sql "$WORK/merged.db" 'SELECT knee FROM runs')"
stdout_has "show lists the merged knee's rows per surface" '^ *hypar +[0-9]+ x [0-9]+ '

dump() {
    { sql "$1" "SELECT $(cols "$1") FROM options ORDER BY number"
      sql "$1" 'SELECT * FROM option_surfaces ORDER BY option, surface'
      sql "$1" 'SELECT count(*) FROM runs'; } | md5sum
}
before=$(dump "$WORK/merged.db")
expect "merging the project shards again" 0 "$FACET" merge "$WORK/merged.db" "$WORK/ex1.db" "$WORK/ex2.db" "$WORK/ex3.db"
same "merging again changes nothing (options, surface rows, runs)" "$(dump "$WORK/merged.db")" "$before"

# --- a missing shard: named, the run incomplete, completed in place later
run "$FACET" merge "$WORK/part.db" "$WORK/ex1.db" "$WORK/ex3.db"
if [ "$STATUS" -eq 0 ] && grep -q "shard 2 of 3 missing" "$ERR"; then
    pass "a missing project shard is named"
else
    fail "a missing project shard is named"
fi
expect "runs --json of the incomplete project merge" 0 "$FACET" runs "$WORK/part.db" --json
json_check "the project merge is marked incomplete" 'j[0]["incomplete"] is True'
expect "merging the missing shard in" 0 "$FACET" merge "$WORK/part.db" "$WORK/ex2.db" "$WORK/ex1.db" "$WORK/ex3.db"
same_rows "completed later, its surface rows are the unsharded run's" "$WORK/whole.db" "$WORK/part.db" option_surfaces

# --- random: the unsharded run's distinct options dealt out
RAND=(--module 1:4:0.1x1:4:0.1 --threshold 1:6 --method random --evals 60 --seed 5)
expect "unsharded random project run" 0 "$FACET" optimize "$P" --db "$WORK/rand.db" "${RAND[@]}" --table 1
make_shards 4 "$WORK/rs" "$P" -- "${RAND[@]}"
expect "merge of 4 random project shards" 0 "$FACET" merge "$WORK/rand-merged.db" "$WORK"/rs{1,2,3,4}.db
same_options "merged random project run = unsharded" "$WORK/rand.db" "$WORK/rand-merged.db"
same_rows "merged random project run = unsharded: surface rows" "$WORK/rand.db" "$WORK/rand-merged.db" option_surfaces

# --- NSGA-II: islands, renumbered in shard order; each keeps its surface rows
NSGA=(--module 1:4:0.1x1:4:0.1 --threshold 1:6 --method nsga2 --pop 8 --gens 3 --seed 3)
expect "unsharded nsga2 project run" 0 "$FACET" optimize "$P" --db "$WORK/nsga.db" "${NSGA[@]}" --table 1
make_shards 2 "$WORK/ns" "$P" -- "${NSGA[@]}"
same_options "island 1 is the project run with the run's seed" "$WORK/nsga.db" "$WORK/ns1.db"
expect "merge of 2 project islands" 0 "$FACET" merge "$WORK/ns-merged.db" "$WORK/ns1.db" "$WORK/ns2.db"
same "the merged islands hold each option of either once, four surface rows each" \
    "$(sql "$WORK/ns-merged.db" 'SELECT count(*), (SELECT count(*) FROM option_surfaces) FROM options')" \
    "$(sql "$WORK/ns1.db" "ATTACH '$WORK/ns2.db' AS b; SELECT count(*), 4 * count(*) FROM (SELECT nu, nv, threshold_mm FROM main.options UNION SELECT nu, nv, threshold_mm FROM b.options)")"
# Each merged option's surface rows are those its island stored for the
# same design point, whatever number it had there.
srow="s.surface, s.nu, s.nv, s.panels, s.cost, s.area, s.planarity, s.moulds, s.mean_gap, s.feasible"
same "each merged island option's surface rows are its island's" \
    "$(sql "$WORK/ns-merged.db" "ATTACH '$WORK/ns1.db' AS a; ATTACH '$WORK/ns2.db' AS b;
        SELECT count(*) FROM (
          SELECT o.nu, o.nv, o.threshold_mm, $srow FROM main.options o
            JOIN main.option_surfaces s ON s.run = o.run AND s.option = o.number
          EXCEPT SELECT * FROM (
            SELECT o.nu, o.nv, o.threshold_mm, $srow FROM a.options o
              JOIN a.option_surfaces s ON s.run = o.run AND s.option = o.number
            UNION
            SELECT o.nu, o.nv, o.threshold_mm, $srow FROM b.options o
              JOIN b.option_surfaces s ON s.run = o.run AND s.option = o.number))")" "0"

# --- shards of different runs: refused in one line naming the difference
"$FACET" optimize "$P" --db "$WORK/other-module.db" --module 1:4:0.5x1:4:0.25 \
    --threshold 2:6:2 --method exhaustive --shard 2/3 --table 1 >/dev/null 2>&1
expect_error "a shard of another module range is refused, naming it" \
    "differs from .*ex1.db in its module range \(m\): 1:4:0.5 x 1:4:0.25, not 1:4:0.25 x 1:4:0.25" \
    "$FACET" merge "$WORK/bad.db" "$WORK/ex1.db" "$WORK/other-module.db"
mkdir -p "$WORK/a" "$WORK/b"
sed 's/^o dome$/o extra/' "$WORK/dome.obj" >"$WORK/a/extra.obj"
"$FACET" example dome --res 13 -o "$WORK/b/dome.obj" >/dev/null || exit 1
sed 's/^o dome$/o extra/' "$WORK/b/dome.obj" >"$WORK/b/extra.obj"
make_shards 2 "$WORK/pa" "$P" "$WORK/a/extra.obj" -- "${SPACE[@]}"
"$FACET" optimize "$P" "$WORK/b/extra.obj" --db "$WORK/pb2.db" "${SPACE[@]}" \
    --shard 2/2 --table 1 >/dev/null 2>&1
expect_error "a shard of a project whose second file differs is refused, naming the surface" \
    "pb2.db \(shard 2/2\) is of another project than .*pa1.db: surface 5 \('extra'\): a file of SHA-256 [0-9a-f]{12}\.\.\., not [0-9a-f]{12}\.\.\." \
    "$FACET" merge "$WORK/bad.db" "$WORK/pa1.db" "$WORK/pb2.db"
"$FACET" optimize "$P" --db "$WORK/other-grid.db" "${SPACE[@]}" --grid dome=5x5 \
    --shard 2/3 --table 1 >/dev/null 2>&1
expect_error "a shard with another surface's own grid is refused, naming it" \
    "is of another project than .*ex1.db: surface 3 \('dome'\): its own grid 5 x 5, not 0 x 0" \
    "$FACET" merge "$WORK/bad.db" "$WORK/ex1.db" "$WORK/other-grid.db"
same "a refused merge writes nothing" "$(ls "$WORK" | grep -c '^bad.db')" "0"
expect "the two shards of the second project merge" 0 "$FACET" merge "$WORK/pa-merged.db" "$WORK/pa1.db" "$WORK/pa2.db"
same "its merged run records its five surfaces" \
    "$(sql "$WORK/pa-merged.db" 'SELECT count(*), group_concat(name) FROM (SELECT name FROM surfaces ORDER BY surface)')" \
    "5|plane,cylinder,dome,hypar,extra"
expect "a second project's merge beside the first" 0 "$FACET" merge "$WORK/merged.db" "$WORK/pa1.db" "$WORK/pa2.db"
same "the first project's merged run is kept, the second's added" \
    "$(sql "$WORK/merged.db" 'SELECT group_concat(n) FROM (SELECT count(*) AS n FROM surfaces GROUP BY run ORDER BY run)')" "4,5"
