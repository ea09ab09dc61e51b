#!/usr/bin/env bash
# End-to-end: a building prepared once and reused (issue 31 item 3). A
# second `facet optimize` of a small project beside the same database
# reads its prepared building from the cache written beside it, says so,
# and stores options identical, column by column (sqlite3), to a run of
# the same files into a database without a cache; a cache damaged or cut
# short is refused with a note and rebuilt, to the same options again.
# layers: core study cli
. "$(dirname "$0")/lib.sh"
sql() { sqlite3 -batch "$1" "$2"; }

four_surfaces || exit 1
mkdir -p "$WORK/fresh" "$WORK/cached"
ARGS=(--module 1.5:3:0.5x1.5:3:0.5 --threshold 2:6:2 --method exhaustive)

# The columns of table but run: every number an option has.
columns() {
    sql "$WORK/fresh/runs.db" "SELECT group_concat(name, ', ') FROM pragma_table_info('$1') WHERE name <> 'run'"
}

# identical NAME RUN: run RUN of cached.db has the options and surface
# rows of fresh.db's run 1, every column.
identical() {
    local name=$1 r=$2 t cols diff
    for t in options option_surfaces; do
        cols=$(columns "$t")
        diff=$(sqlite3 -batch "$WORK/cached/runs.db" "ATTACH '$WORK/fresh/runs.db' AS f;
            SELECT count(*) FROM (SELECT $cols FROM $t WHERE run = $r
                                  EXCEPT SELECT $cols FROM f.$t WHERE run = 1);
            SELECT count(*) FROM (SELECT $cols FROM f.$t WHERE run = 1
                                  EXCEPT SELECT $cols FROM $t WHERE run = $r);
            SELECT (SELECT count(*) FROM $t WHERE run = $r) = (SELECT count(*) FROM f.$t WHERE run = 1)
                   AND (SELECT count(*) FROM $t WHERE run = $r) > 0;" | tr '\n' ' ')
        if [ "$diff" = "0 0 1 " ]; then
            pass "$name: $t identical to a run without a cache"
        else
            echo "not ok - $name: $t differs from a run without a cache (rows only here, only there, same count: $diff)"
        fi
    done
}

# 1. A run without a cache, the reference (a folder of its own: a cache
# is shared by the databases of its folder); it leaves one there.
expect "a first run" 0 "$FACET" optimize "$WORK/four.obj" --db "$WORK/fresh/runs.db" "${ARGS[@]}"
if grep -q "reused the prepared building" "$ERR"; then
    fail "a first run reuses nothing"
else
    pass "a first run reuses nothing"
fi
same "a first run keeps its prepared building in its database's folder" \
    "$(ls "$WORK"/fresh/facet-prepared-* 2>/dev/null | wc -l)" 1

# 2. Twice into cached.db: the second reuses the first's preparation.
expect "a run into cached.db" 0 "$FACET" optimize "$WORK/four.obj" --db "$WORK/cached/runs.db" "${ARGS[@]}"
expect "a second run into cached.db" 0 "$FACET" optimize "$WORK/four.obj" --db "$WORK/cached/runs.db" "${ARGS[@]}"
if grep -qE "^facet: note: reused the prepared building .*cached/facet-prepared-[0-9a-f]{16}$" "$ERR"; then
    pass "the second run says it reused the prepared building"
else
    fail "the second run says it reused the prepared building"
fi
identical "the run that reused it" 2
CACHE=$(ls "$WORK"/cached/facet-prepared-*)

# 3. A byte flipped in the middle of the cache: refused, rebuilt, the
# same options; the cache made whole again.
python3 - "$CACHE" <<'PY'
import sys
p = sys.argv[1]
b = bytearray(open(p, "rb").read())
b[len(b) // 2] ^= 0x10
open(p, "wb").write(b)
PY
expect "a run over a damaged cache" 0 "$FACET" optimize "$WORK/four.obj" --db "$WORK/cached/runs.db" "${ARGS[@]}"
if [ "$(grep -c "note: .*prepared building not used: damaged.*; preparing it again" "$ERR")" -eq 1 ]; then
    pass "a damaged cache: one note saying so"
else
    fail "a damaged cache: one note saying so"
fi
identical "the run over a damaged cache" 3

# 4. Cut short: the same.
truncate -s -100 "$CACHE"
expect "a run over a truncated cache" 0 "$FACET" optimize "$WORK/four.obj" --db "$WORK/cached/runs.db" "${ARGS[@]}"
if grep -q "note: .*prepared building not used: truncated" "$ERR"; then
    pass "a truncated cache: a note saying so"
else
    fail "a truncated cache: a note saying so"
fi
identical "the run over a truncated cache" 4
expect "a run after the rebuild" 0 "$FACET" optimize "$WORK/four.obj" --db "$WORK/cached/runs.db" "${ARGS[@]}"
if grep -q "reused the prepared building" "$ERR"; then
    pass "the rebuilt cache is reused"
else
    fail "the rebuilt cache is reused"
fi
identical "the run after the rebuild" 5
