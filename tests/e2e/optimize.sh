#!/usr/bin/env bash
# End-to-end: facet optimize and its result store (facet runs, options,
# show), checked against the SQLite file itself and against brute force
# computed here: the runs finish and are listed, ranks and knees are right,
# the same seed gives the same options, an interrupted or killed run resumes
# to what an uninterrupted run stores, readers are never locked out, and
# bad input is refused in one line.
# layers: study store core cli
. "$(dirname "$0")/lib.sh"

HERE=$(cd "$(dirname "$0")" && pwd)
CHECK=(/usr/bin/python3 "$HERE/optimize_check.py")

fixture roof40.obj "$WORK/roof.obj" || exit 1
ROOF=$WORK/roof.obj
# 6 x 6 grids x 4 thresholds = 144 options, feasible and infeasible ones.
SMALL=(--u 10:15 --v 12:17 --threshold 1:4:1)
# 6 x 6 grids x 77 thresholds = 2772 options, for interrupting.
BIG=(--u 10:15 --v 12:17 --threshold 1:20:0.25)
BIG_TOTAL=2772
NSGA=(--u 10:20 --v 12:24 --threshold 1:20 --method nsga2 --pop 24 --gens 40)

# sql DB QUERY: the query's rows, '|' between columns.
sql() { sqlite3 -batch "$1" "$2"; }


# check NAME CMD...: passes when CMD exits 0 (a checker prints why not).
check() {
    local name=$1
    shift
    run "$@"
    if [ "$STATUS" -eq 0 ]; then pass "$name"; else fail "$name"; fi
}

# count_options DB: the options stored so far (0 before the table exists).
count_options() {
    local n=0
    [ -s "$1" ] && n=$(sqlite3 -batch "$1" 'SELECT count(*) FROM options' 2>/dev/null)
    echo "${n:-0}"
}

# wait_for_options DB PID N: waits until DB holds N options, the writer PID
# has ended, or 300 s have passed; prints the count it saw last.
wait_for_options() {
    local n=0 tries=0
    while [ "$tries" -lt 6000 ]; do
        n=$(count_options "$1")
        [ "$n" -ge "$3" ] && break
        kill -0 "$2" 2>/dev/null || break
        sleep 0.05
        tries=$((tries + 1))
    done
    echo "$n"
}

# finish PID: waits for a background writer and sets STATUS to its exit
# status; one still running after 600 s is killed (status 137), so a hung
# writer fails the checks rather than hanging the script.
finish() {
    local tries=0
    while kill -0 "$1" 2>/dev/null && [ "$tries" -lt 12000 ]; do
        sleep 0.05
        tries=$((tries + 1))
    done
    kill -KILL "$1" 2>/dev/null
    wait "$1" 2>/dev/null
    STATUS=$?
}

# listing NAME FORMAT SQL ARGS...: `facet options DB ARGS --FORMAT` gives the
# rows of SQL over $DB, in the same order, every column equal.
listing() {
    local name=$1 format=$2 query=$3
    shift 3
    run "$FACET" options "$DB" "$@" --"$format"
    if [ "$STATUS" -ne 0 ]; then
        fail "$name (facet options failed)"
        return
    fi
    cp "$OUT" "$WORK/listing"
    check "$name" "${CHECK[@]}" listing "$DB" "$format" "$WORK/listing" "$query"
}

# ---------------------------------------------------------------------------
# 1. A run finishes. The file is a Facet database in WAL mode, whole, with
# one option per point of the space; the final table, facet runs and facet
# options show what the tables hold, and facet options sorts and filters
# exactly as the same SQL does.
DB=$WORK/small.db
expect "a small exhaustive run finishes" 0 \
    "$FACET" optimize "$ROOF" --db "$DB" "${SMALL[@]}" --jobs 2 --table 0 --name small
cp "$OUT" "$WORK/small.table"
stdout_has "final table: the run, its method and options" \
    '^run 1 \(done, small\): .*exhaustive, 144 options'
stdout_has "final table: the Pareto legend" '^\* Pareto-optimal$'
same "final table: --table 0 prints every option" \
    "$(grep -cE '^ +[0-9]+ [ *] +[0-9]+\.[0-9]{4} ' "$WORK/small.table")" 144
same "final table: the starred options are the rank 1 ones" \
    "$(grep -E '^ +[0-9]+ \* ' "$WORK/small.table" | awk '{print $1}' | sort -n | tr '\n' ' ')" \
    "$(sql "$DB" 'SELECT number FROM options WHERE rank = 1 ORDER BY number' | tr '\n' ' ')"
same "final table: the knee is marked on the run's knee" \
    "$(grep -E '^ +[0-9]+ .* knee' "$WORK/small.table" | awk '{print $1}')" \
    "$(sql "$DB" 'SELECT knee FROM runs WHERE id = 1')"
same "status done" "$(sql "$DB" 'SELECT status FROM runs WHERE id = 1')" done
same "options = 6 u x 6 v x 4 thresholds, all stored and counted" \
    "$(sql "$DB" 'SELECT count(*), (SELECT options FROM runs WHERE id = 1) FROM options WHERE run = 1')" \
    "144|144"
same "every point of the space once" \
    "$(sql "$DB" "SELECT count(DISTINCT nu || 'x' || nv || '@' || threshold_mm), min(nu), max(nu), min(nv), max(nv), min(threshold_mm), max(threshold_mm) FROM options")" \
    "144|10|15|12|17|1.0|4.0"
same "the space has feasible and infeasible options" \
    "$(sql "$DB" 'SELECT count(DISTINCT feasible) FROM options')" 2
same "integrity_check ok" "$(sql "$DB" 'PRAGMA integrity_check')" ok
same "application_id is Facet's" "$(sql "$DB" 'PRAGMA application_id')" 1178813780
same "user_version (schema) set" "$(sql "$DB" 'SELECT user_version >= 1 FROM pragma_user_version')" 1
same "journal_mode wal" "$(sql "$DB" 'PRAGMA journal_mode')" wal
same "run_summary view" "$(sql "$DB" 'SELECT id, status, u, v, options FROM run_summary')" \
    "1|done|10:15|12:17|144"

PARETO=$(sql "$DB" 'SELECT count(*) FROM options WHERE rank = 1')
KNEE=$(sql "$DB" 'SELECT knee FROM runs WHERE id = 1')
expect "facet runs" 0 "$FACET" runs "$DB"
stdout_has "facet runs lists the run: done, exhaustive, its options and Pareto count" \
    "^ +1 done +exhaustive +144 +$PARETO .* small / "
expect "facet runs --json" 0 "$FACET" runs "$DB" --json
json_check "runs --json: the run and its settings" \
    'len(j)==1 and j[0]["id"]==1 and j[0]["status"]=="done" and j[0]["name"]=="small" and j[0]["method"]=="exhaustive" and j[0]["u"]==[10,15] and j[0]["v"]==[12,17] and j[0]["threshold_mm"]==[1,4,1] and j[0]["objectives"]=="cost,planarity,dp_area" and j[0]["options"]==144'
json_check "runs --json: its results as stored" \
    "j[0][\"pareto_options\"]==$PARETO and j[0][\"knee\"]==$KNEE and j[0][\"best_cost\"] > 0 and j[0][\"finished\"] is not None"

# Sorted, every feasible option comes first, each part in the order asked
# for, --desc too (issue 32 item 19).
listing "options --json: every option, every column, as stored" json \
    'SELECT * FROM options ORDER BY run, number'
listing "options --pareto: the rank 1 options" json \
    'SELECT * FROM options WHERE rank = 1 ORDER BY run, number' --pareto
listing "options --sort cost --limit 10" json \
    'SELECT * FROM options ORDER BY feasible DESC, cost, run, number LIMIT 10' --sort cost --limit 10
# Sorted on two keys the second of which ties to rounding (planarity 0
# against 9e-16): the order of the tie rule (docs/decisions.md: Ties), by a
# brute force over the stored values, not SQL's exact ORDER BY.
run "$FACET" options "$DB" --run 1 --sort dp_area,planarity --desc --limit 15 --json
cp "$OUT" "$WORK/listing"
check "options --sort dp_area,planarity --desc --limit 15: the tie rule's order" \
    /usr/bin/python3 "$HERE/ties_check.py" order "$DB" 1 dp_area,planarity 1 "$WORK/listing" json
WHERE='cost < 1.65e6 and dp_area <= 950 or pareto'
WHERE_SQL='(cost < 1.65e6 AND dp_area <= 950) OR rank = 1'
same "the --where below selects some but not all options, not only Pareto ones" \
    "$(sql "$DB" "SELECT count(*) > $PARETO AND count(*) < 144 FROM options WHERE $WHERE_SQL")" 1
listing "options --where 'and/or/pareto' --sort cost: the SQL query's rows and order" json \
    "SELECT * FROM options WHERE $WHERE_SQL ORDER BY feasible DESC, cost, run, number" --where "$WHERE" --sort cost
listing "options --where with the aliases u and threshold, --run 1" json \
    'SELECT * FROM options WHERE run = 1 AND nu >= 14 AND threshold_mm = 2 ORDER BY run, number' \
    --run 1 --where 'u >= 14 and threshold = 2'
listing "options --where 'not feasible' --sort rank,cost" json \
    'SELECT * FROM options WHERE NOT feasible ORDER BY rank, cost, run, number' \
    --where 'not feasible' --sort rank,cost
listing "options --csv --sort threshold_mm,nu --desc" csv \
    'SELECT * FROM options ORDER BY feasible DESC, threshold_mm DESC, nu DESC, run DESC, number DESC' \
    --sort threshold_mm,nu --desc
# Crowding is stored NULL at a front's end (infinite): --json writes null
# there, --csv inf, and a finite number everywhere else.
ENDS=$(sql "$DB" 'SELECT number FROM options WHERE crowding IS NULL ORDER BY number' | paste -sd, -)
same "some options are at a front's end (crowding NULL)" "$([ -n "$ENDS" ] && echo yes)" yes
run "$FACET" options "$DB" --json
json_check "options --json: crowding null exactly where stored NULL" \
    "[o['number'] for o in j if o['crowding'] is None] == [$ENDS]"
run "$FACET" options "$DB" --csv
same "options --csv: crowding empty exactly where stored NULL (as JSON's null)" \
    "$(awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) if ($k == "crowding") c = k } NR > 1 && $c == "" { print $2 }' "$OUT" | paste -sd, -)" \
    "$ENDS"
if grep -q 'inf' "$OUT"; then fail "options --csv: no inf anywhere"; else pass "options --csv: no inf anywhere"; fi
run "$FACET" options "$DB" --csv
# each named with its unit, as the schedule's (csv_names.py, from the
# units docs/store.md gives)
same "options --csv: every column of the options table, in its order (run first), with its unit" \
    "$(head -n 1 "$OUT")" "$(sqlite3 "$DB" "SELECT name FROM pragma_table_info('options') ORDER BY name = 'run' DESC, cid" |
        PYTHONPATH=$(dirname "$0") python3 -c 'import sys, csv_names; print(",".join(csv_names.csv_name(c) for c in sys.stdin.read().split()))')"
run "$FACET" options "$DB" --json
cols=$(sqlite3 "$DB" "SELECT group_concat(name) FROM pragma_table_info('options')")
json_check "options --json: every column of the options table" \
    "sorted(j[0]) == sorted('$cols'.split(','))"
expect "options table with --where" 0 "$FACET" options "$DB" --where "$WHERE" --sort cost
stdout_has "the table's count is the SQL count" \
    "^\($(sql "$DB" "SELECT count(*) FROM options WHERE $WHERE_SQL") options where "
same "the table has one line per option" \
    "$(grep -cE '^ +1 +[0-9]+ ' "$OUT")" "$(sql "$DB" "SELECT count(*) FROM options WHERE $WHERE_SQL")"
expect_error "a bad --where names the column position" "facet: --where: column 16: unknown column 'nosuch'" \
    "$FACET" options "$DB" --where 'cost < 1e6 and nosuch > 3'
expect_error "a --where missing a number names the column position" 'facet: --where: column 8:' \
    "$FACET" options "$DB" --where 'cost < < 3'
expect_error "a bad --sort column" "facet: --sort: unknown column 'nosuch'" \
    "$FACET" options "$DB" --sort cost,nosuch
# Issue 32 item 12: a misspelt --sort column gets "did you mean", and an
# unknown one the list of columns on one line, ending whole (every name
# the options table has, as sqlite3 lists it, is in it or in its
# per-class pattern).
expect_error "a misspelt --sort column: did you mean" \
    "^facet: --sort: unknown column 'costt' \(did you mean cost\?\)\$" \
    "$FACET" options "$DB" --sort costt
expect_error "an unknown --sort column: the columns, the list whole" \
    "^facet: --sort: unknown column 'qqqqqq' \(columns: number, .*, CLASS_\{count,area\}\)\$" \
    "$FACET" options "$DB" --sort qqqqqq
missing=""
for c in $(sqlite3 "$DB" "SELECT name FROM pragma_table_info('options')"); do
    case $c in *_count|*_area|*_cost|*_moulds|*_gap|*_kink|*_over|*_reached|*_length) continue ;; esac
    grep -qE "[ (]$c[,)]" "$ERR" || missing="$missing $c"
done
if [ -z "$missing" ]; then
    pass "... every column sqlite3 lists is named in it"
else
    fail "... every column sqlite3 lists is named in it (missing:$missing)"
fi

# ---------------------------------------------------------------------------
# 2. Pareto ranks against brute force: every option's rank recomputed by
# peeling non-dominated fronts with constraint-domination (feasible first,
# infeasible by how far the largest panel exceeds the limit), the knee, the
# pareto view, hypervolume, best cost, and the panels of every Pareto
# option; for the default objectives, a subset, one to maximise, a single
# objective, and a space where nothing is feasible.
check "ranks, knee, view, hypervolume, panels = brute force (cost,planarity,dp_area)" \
    "${CHECK[@]}" ranks "$DB" 1
cp "$DB" "$WORK/wrong.db"
sql "$WORK/wrong.db" "UPDATE options SET rank = rank + 1 WHERE run = 1 AND number = (SELECT max(number) FROM options WHERE rank = 2)"
run "${CHECK[@]}" ranks "$WORK/wrong.db" 1
if [ "$STATUS" -eq 1 ] && grep -q 'differ from brute force' "$ERR"; then
    pass "the brute-force check notices one wrong rank"
else
    fail "the brute-force check notices one wrong rank"
fi
expect "a run with --objectives cost,dp_area" 0 \
    "$FACET" optimize "$ROOF" --db "$DB" "${SMALL[@]}" --objectives cost,dp_area --table 0
check "ranks = brute force (cost,dp_area)" "${CHECK[@]}" ranks "$DB" 2
expect "a run with --objectives max:fp_area,cost,planarity" 0 \
    "$FACET" optimize "$ROOF" --db "$DB" "${SMALL[@]}" --objectives max:fp_area,cost,planarity --table 0
check "ranks = brute force (max:fp_area,cost,planarity)" "${CHECK[@]}" ranks "$DB" 3
expect "a run with --objectives cost" 0 \
    "$FACET" optimize "$ROOF" --db "$DB" "${SMALL[@]}" --objectives cost --table 0
check "ranks = brute force (cost alone)" "${CHECK[@]}" ranks "$DB" 4
same "runs.objectives as given" "$(sql "$DB" 'SELECT objectives FROM runs ORDER BY id' | tr '\n' ' ')" \
    "cost,planarity,dp_area cost,dp_area max:fp_area,cost,planarity cost "
same "the objectives change the front" \
    "$(sql "$DB" 'SELECT count(DISTINCT pareto_options) > 1 FROM runs')" 1
listing "options --run 2 --pareto: only that run's front" json \
    'SELECT * FROM options WHERE run = 2 AND rank = 1 ORDER BY run, number' --run 2 --pareto
expect "a run where no option is feasible" 0 \
    "$FACET" optimize "$ROOF" --db "$DB" --u 4:6 --v 5:7 --threshold 1:3:1 --table 0
cp "$OUT" "$WORK/infeasible.table"
check "ranks = brute force (all infeasible: by violation)" "${CHECK[@]}" ranks "$DB" 5
if grep -qiw nan "$WORK/infeasible.table"; then
    fail "the final table of an all-infeasible run prints no 'nan'"
else
    pass "the final table of an all-infeasible run prints no 'nan'"
fi
expect "nsga2 run (ranks of a run with generations)" 0 \
    "$FACET" optimize "$ROOF" --db "$DB" --u 10:20 --v 12:24 --threshold 1:20 --method nsga2 --pop 12 --gens 6 --table 0
check "ranks = brute force (nsga2)" "${CHECK[@]}" ranks "$DB" 6

# ---------------------------------------------------------------------------
# 3. facet show on an option whose panels are not stored computes them and
# stores them; its --json is classify --json's, with the option's totals,
# and the same panels as classify computes for that grid and threshold,
# whether show or optimize stored them.
OPT=$(sql "$DB" 'SELECT number FROM options WHERE run = 1 AND rank > 1 AND feasible ORDER BY number LIMIT 1')
read -r NU NV T <<<"$(sql "$DB" "SELECT nu, nv, threshold_mm FROM options WHERE run = 1 AND number = $OPT" | tr '|' ' ')"
same "a non-Pareto option has no stored panels yet" \
    "$(sql "$DB" "SELECT count(*) FROM panel_sets WHERE run = 1 AND option = $OPT")" 0
expect "show a non-Pareto option" 0 "$FACET" show "$DB" --run 1 --option "$OPT"
stdout_has "show names the option" "^option +run 1 option $OPT\$"
stdout_has "show gives its grid" "^grid +$NU x $NV \\($((NU * NV)) panels\\)"
stdout_has "show draws the panel map" '^  [FSD.]+$'
same "show stored its panel set" \
    "$(sql "$DB" "SELECT count(*), nu, nv FROM panel_sets WHERE run = 1 AND option = $OPT")" "1|$NU|$NV"
same "show stored one row per panel" \
    "$(sql "$DB" "SELECT count(*) FROM panels WHERE run = 1 AND option = $OPT")" \
    "$(sql "$DB" "SELECT panels FROM options WHERE run = 1 AND number = $OPT")"
expect "classify the same grid and threshold" 0 \
    "$FACET" classify "$ROOF" --grid "${NU}x$NV" --threshold "$T" --json
cp "$OUT" "$WORK/classify.json"
expect "show --json (panels read back)" 0 "$FACET" show "$DB" --run 1 --option "$OPT" --json
cp "$OUT" "$WORK/show.json"
json_check "show --json: panels listed = totals.panels" 'len(j["panels"]) == j["totals"]["panels"]'
check "show --json: classify's keys and panels; totals = options row" \
    "${CHECK[@]}" show "$DB" 1 "$OPT" "$WORK/show.json" "$WORK/classify.json"
check "show --json: surface (triangles, uv) = classify's" \
    "${CHECK[@]}" show-surface "$WORK/show.json" "$WORK/classify.json"
OPT=$(sql "$DB" 'SELECT knee FROM runs WHERE id = 1')
read -r NU NV T <<<"$(sql "$DB" "SELECT nu, nv, threshold_mm FROM options WHERE run = 1 AND number = $OPT" | tr '|' ' ')"
run "$FACET" classify "$ROOF" --grid "${NU}x$NV" --threshold "$T" --json
cp "$OUT" "$WORK/classify.json"
expect "show --json of the knee (panels stored by optimize)" 0 \
    "$FACET" show "$DB" --run 1 --option "$OPT" --json
cp "$OUT" "$WORK/show.json"
check "the knee's stored panels = classify's" \
    "${CHECK[@]}" show "$DB" 1 "$OPT" "$WORK/show.json" "$WORK/classify.json"
expect_error "show of an option that does not exist" 'no option 9999' \
    "$FACET" show "$DB" --run 1 --option 9999
expect_error "show of a run that does not exist" 'no run 99' \
    "$FACET" show "$DB" --run 99 --option 1

# ---------------------------------------------------------------------------
# 4. Reproducibility: the same seed gives the same options (every column
# but run), with any number of threads; another seed gives others.
REP=$WORK/rep.db
for args in "--seed 7 --jobs 1" "--seed 7 --jobs 2" "--seed 8 --jobs 2"; do
    # shellcheck disable=SC2086
    expect "nsga2 $args" 0 "$FACET" optimize "$ROOF" --db "$REP" \
        --u 10:20 --v 12:24 --threshold 1:20 --method nsga2 --pop 12 --gens 4 $args --table 0
done
for args in "--seed 7 --jobs 2" "--seed 7 --jobs 1" "--seed 8 --jobs 1"; do
    # shellcheck disable=SC2086
    expect "random $args" 0 "$FACET" optimize "$ROOF" --db "$REP" \
        --u 10:20 --v 12:24 --threshold 1:20 --method random --evals 60 $args --table 0
done
check "nsga2: the same seed, the same options" "${CHECK[@]}" same "$REP" 1 "$REP" 2
check "nsga2: another seed, other options" "${CHECK[@]}" differ "$REP" 1 "$REP" 3
check "random: the same seed, the same options" "${CHECK[@]}" same "$REP" 4 "$REP" 5
check "random: another seed, other options" "${CHECK[@]}" differ "$REP" 4 "$REP" 6
same "nsga2: at most pop x gens options, generations 0 to gens-1" \
    "$(sql "$REP" 'SELECT count(*) <= 48, min(generation), max(generation) FROM options WHERE run = 1')" "1|0|3"
same "random: --evals distinct options" \
    "$(sql "$REP" "SELECT count(*), count(DISTINCT nu || 'x' || nv || '@' || threshold_mm) FROM options WHERE run = 4")" "60|60"

# ---------------------------------------------------------------------------
# 5 and 7. The reference runs, uninterrupted, while a reader queries the
# file again and again until the writer has exited: `facet options`, then
# sqlite3 with no busy timeout (as a quick script has none). WAL lets every
# read succeed while the writer commits (no "database is locked"), and the
# count a reader sees never goes down. A failed sqlite3 read is counted
# apart when the run was already done (the writer closing the file).
REF=$WORK/ref.db
"$FACET" optimize "$ROOF" --db "$REF" "${BIG[@]}" --jobs 2 --table 0 >"$WORK/ref.out" 2>"$WORK/ref.err" &
pid=$!
wait_for_options "$REF" "$pid" 1 >/dev/null
reads=0 facet_failed=0 running_failed=0 closing_failed=0 backwards=0 last=0
: >"$WORK/facet-reader.err"
: >"$WORK/sqlite-reader.err"
while kill -0 "$pid" 2>/dev/null; do
    reads=$((reads + 1))
    "$FACET" options "$REF" --run 1 --sort cost --limit 3 >/dev/null 2>>"$WORK/facet-reader.err" ||
        facet_failed=$((facet_failed + 1))
    if n=$(sqlite3 -batch "$REF" 'SELECT count(*) FROM options' 2>>"$WORK/sqlite-reader.err"); then
        [ "$n" -ge "$last" ] || backwards=$((backwards + 1))
        last=$n
    elif [ "$(sqlite3 -batch -cmd '.timeout 10000' "$REF" 'SELECT status FROM runs')" = running ]; then
        running_failed=$((running_failed + 1))
    else
        closing_failed=$((closing_failed + 1))
    fi
done
finish "$pid"
OUT=$WORK/ref.out ERR=$WORK/ref.err
if [ "$STATUS" -eq 0 ]; then pass "reference run finishes"; else fail "reference run finishes"; fi
OUT=$WORK/stdout ERR=$WORK/stderr
# reader_result NAME FAILURES LOG: passes when there were reads and none failed.
reader_result() {
    if [ "$reads" -ge 3 ] && [ "$2" -eq 0 ]; then
        pass "$1: every read succeeded"
    else
        echo "not ok - $1: $2 of $reads reads failed"
        sed 's/^/  stderr: /' "$3" | sort | uniq -c | head -n 3
    fi
}
reader_result "facet options while the writer runs" "$facet_failed" "$WORK/facet-reader.err"
reader_result "sqlite3 count(*) while the run is running" "$running_failed" "$WORK/sqlite-reader.err"
reader_result "sqlite3 count(*) after the run is done, as the writer exits" "$closing_failed" "$WORK/sqlite-reader.err"
same "the count a reader sees never goes down" "$backwards" 0
same "reference: done, every option" \
    "$(sql "$REF" 'SELECT status, options, (SELECT count(*) FROM options) FROM runs')" "done|$BIG_TOTAL|$BIG_TOTAL"

# 5. Resume after SIGINT: the writer stops between batches, exits 130, says
# how to go on, leaves the run 'interrupted' with every option it evaluated
# committed and counted; --resume finishes it to exactly the options, ranks
# and results of the uninterrupted run.
INT=$WORK/int.db
"$FACET" optimize "$ROOF" --db "$INT" "${BIG[@]}" --jobs 1 --table 3 >"$WORK/int.out" 2>"$WORK/int.err" &
pid=$!
wait_for_options "$INT" "$pid" 1 >/dev/null
kill -INT "$pid"
finish "$pid"
OUT=$WORK/int.out ERR=$WORK/int.err
if [ "$STATUS" -eq 130 ]; then pass "SIGINT: exit status 130"; else fail "SIGINT: exit status 130"; fi
if grep -q "interrupted.*--resume 1" "$ERR"; then pass "SIGINT: says how to resume"; else fail "SIGINT: says how to resume"; fi
if [ "$(tail -n 1 "$ERR")" != "facet: failed" ]; then
    pass "SIGINT: does not end by calling the run failed"
else
    fail "SIGINT: does not end by calling the run failed"
fi
stdout_has "SIGINT: the final table of what is stored" '^run 1 \(interrupted\)'
OUT=$WORK/stdout ERR=$WORK/stderr
read -r status stored rows <<<"$(sql "$INT" 'SELECT status, options, (SELECT count(*) FROM options) FROM runs' | tr '|' ' ')"
same "SIGINT: status interrupted" "$status" interrupted
same "SIGINT: options stored = rows" "$stored" "$rows"
same "SIGINT: stopped mid-run (0 < options < all)" \
    "$rows $([ "${rows:-0}" -gt 0 ] && [ "${rows:-0}" -lt "$BIG_TOTAL" ] && echo mid-run)" "$rows mid-run"
same "SIGINT: integrity ok" "$(sql "$INT" 'PRAGMA integrity_check')" ok
expect "resume the interrupted run" 0 "$FACET" optimize --db "$INT" --resume 1 --table 0
stdout_has "resume: final table says done" "^run 1 \\(done\\): .*$BIG_TOTAL options"
same "resume: done, every option" \
    "$(sql "$INT" 'SELECT status, options, (SELECT count(*) FROM options) FROM runs')" "done|$BIG_TOTAL|$BIG_TOTAL"
check "resume: the options equal the uninterrupted run's" "${CHECK[@]}" same "$INT" 1 "$REF" 1
check "resume: the run's results equal the uninterrupted run's" "${CHECK[@]}" summary "$INT" 1 "$REF" 1
same "resume: the panels of the Pareto options are stored, up to max(16, options / 40)" \
    "$(sql "$INT" 'SELECT count(*) FROM options o JOIN panel_sets s ON s.run = o.run AND s.option = o.number WHERE o.rank = 1')" \
    "$(sql "$INT" 'SELECT min(count(*) FILTER (WHERE rank = 1), max(16, count(*) / 40)) FROM options')"

# The same for nsga2: its generations continue from the stored options.
NREF=$WORK/nsga-ref.db NINT=$WORK/nsga-int.db
expect "nsga2 reference run" 0 "$FACET" optimize "$ROOF" --db "$NREF" "${NSGA[@]}" --jobs 2 --table 0
"$FACET" optimize "$ROOF" --db "$NINT" "${NSGA[@]}" --jobs 1 --table 0 >"$WORK/nint.out" 2>"$WORK/nint.err" &
pid=$!
wait_for_options "$NINT" "$pid" 1 >/dev/null
kill -INT "$pid"
finish "$pid"
OUT=$WORK/nint.out ERR=$WORK/nint.err
if [ "$STATUS" -eq 130 ]; then pass "nsga2 SIGINT: exit status 130"; else fail "nsga2 SIGINT: exit status 130"; fi
OUT=$WORK/stdout ERR=$WORK/stderr
NSGA_TOTAL=$(sql "$NREF" 'SELECT options FROM runs')
read -r status stored rows <<<"$(sql "$NINT" 'SELECT status, options, (SELECT count(*) FROM options) FROM runs' | tr '|' ' ')"
same "nsga2 SIGINT: interrupted mid-run, options stored = rows" \
    "$status $([ "${rows:-0}" -gt 0 ] && [ "${rows:-0}" -lt "$NSGA_TOTAL" ] && echo mid-run) $stored" \
    "interrupted mid-run $rows"
same "nsga2 SIGINT: integrity ok" "$(sql "$NINT" 'PRAGMA integrity_check')" ok
expect "nsga2 resume" 0 "$FACET" optimize --db "$NINT" --resume 1 --table 0
same "nsga2 resume: done" "$(sql "$NINT" 'SELECT status FROM runs')" done
check "nsga2 resume: the options equal the uninterrupted run's" "${CHECK[@]}" same "$NINT" 1 "$NREF" 1
check "nsga2 resume: the run's results equal the uninterrupted run's" "${CHECK[@]}" summary "$NINT" 1 "$NREF" 1

# ---------------------------------------------------------------------------
# 6. kill -9 mid-run: nothing can be written, so the file says 'running';
# the next Facet to open it sees the writer is gone and reports the run
# 'interrupted'; every option committed before the kill is still there and
# the file is whole; --resume finishes it as in 5.
KILL=$WORK/kill.db
"$FACET" optimize "$ROOF" --db "$KILL" "${BIG[@]}" --jobs 1 --table 0 >/dev/null 2>&1 &
pid=$!
disown "$pid"  # no "Killed" notice from bash
wait_for_options "$KILL" "$pid" 48 >/dev/null
before=$(count_options "$KILL")
kill -KILL "$pid"
finish "$pid"
same "kill -9: the file still says running" "$(sql "$KILL" 'SELECT status FROM runs')" running
after=$(count_options "$KILL")
same "kill -9: no committed option lost, and it stopped mid-run (options before, after the kill)" \
    "$before $after $([ "$before" -ge 48 ] && [ "$after" -ge "$before" ] && [ "$after" -lt "$BIG_TOTAL" ] && echo yes)" \
    "$before $after yes"
expect "kill -9: facet runs" 0 "$FACET" runs "$KILL"
stdout_has "kill -9: facet runs reports the run interrupted" '^ +1 interrupted '
same "kill -9: facet runs only reads: the file still says running" "$(sql "$KILL" 'SELECT status FROM runs')" running
expect "kill -9: a writer opens the file (facet show)" 0 "$FACET" show "$KILL" --run 1 --option 1
same "kill -9: and the writer records it" "$(sql "$KILL" 'SELECT status FROM runs')" interrupted
same "kill -9: integrity ok" "$(sql "$KILL" 'PRAGMA integrity_check')" ok
expect "kill -9: resume" 0 "$FACET" optimize --db "$KILL" --resume 1 --table 0
same "kill -9: resumed to done" \
    "$(sql "$KILL" 'SELECT status, options, (SELECT count(*) FROM options) FROM runs')" "done|$BIG_TOTAL|$BIG_TOTAL"
# The show above measured option 1 in full (what the run did not need,
# stored beside what it did): the same look at the reference.
"$FACET" show "$REF" --run 1 --option 1 >/dev/null 2>&1
check "kill -9: the options equal the uninterrupted run's" "${CHECK[@]}" same "$KILL" 1 "$REF" 1
check "kill -9: the run's results equal the uninterrupted run's" "${CHECK[@]}" summary "$KILL" 1 "$REF" 1

# ---------------------------------------------------------------------------
# 8. Bad input: one line on stderr naming what is wrong, and status 2
# (docs/manual.md: "bad usage or bad input"; a damaged database is bad
# input too).
echo "not a database" >"$WORK/text.db"
expect_error "a text file as --db" 'text.db: not an SQLite database' \
    "$FACET" optimize "$ROOF" --db "$WORK/text.db" "${SMALL[@]}"
expect_error "facet runs on a text file" 'text.db: not an SQLite database' "$FACET" runs "$WORK/text.db"
sql "$WORK/other.db" 'CREATE TABLE songs (title TEXT)'
expect_error "an SQLite file of another application" 'other.db: .*another application' \
    "$FACET" optimize "$ROOF" --db "$WORK/other.db" "${SMALL[@]}"
expect_error "facet options on another application's file" 'other.db: .*another application' \
    "$FACET" options "$WORK/other.db"
cp "$DB" "$WORK/newer.db"
sql "$WORK/newer.db" 'PRAGMA application_id = 1178813780; PRAGMA user_version = 99'
expect_error "a newer schema (user_version 99)" 'newer.db: .*newer Facet.*99' \
    "$FACET" optimize "$ROOF" --db "$WORK/newer.db" "${SMALL[@]}"
expect_error "facet runs on a newer schema" 'newer.db: .*newer Facet.*99' "$FACET" runs "$WORK/newer.db"

# Corruption, made by overwriting whole pages. First in the middle of the
# options table (pages found with dbstat): readers of the options and a new
# run into the file must refuse it, and nothing is added to a damaged file.
cp "$DB" "$WORK/bad-options.db"
page=$(sql "$DB" "SELECT pageno FROM dbstat WHERE name = 'options' AND pagetype = 'leaf' ORDER BY pageno LIMIT 1 OFFSET (SELECT count(*) / 2 FROM dbstat WHERE name = 'options' AND pagetype = 'leaf')")
head -c 8192 /dev/zero | tr '\0' '\125' |
    dd of="$WORK/bad-options.db" bs=4096 seek=$((page - 1)) count=2 conv=notrunc 2>/dev/null
same "the copy with damaged options pages fails integrity_check" \
    "$(sql "$WORK/bad-options.db" 'PRAGMA integrity_check' 2>&1 | head -n 1 | grep -qv '^ok$' && echo damaged)" damaged
expect_error "facet options on damaged options pages" 'bad-options.db: .*(malformed|damaged)' \
    "$FACET" options "$WORK/bad-options.db"
runs_before=$(sql "$WORK/bad-options.db" 'SELECT count(*) FROM runs')
expect_error "optimize into a file with damaged options pages" 'bad-options.db: .*(malformed|damaged)' \
    "$FACET" optimize "$ROOF" --db "$WORK/bad-options.db" --u 10:11 --v 12:12
same "no run added to the damaged file" "$(sql "$WORK/bad-options.db" 'SELECT count(*) FROM runs')" "$runs_before"
# Then a few pages in the middle of the file (here, stored panels).
cp "$DB" "$WORK/bad-middle.db"
pages=$(sql "$DB" 'PRAGMA page_count')
head -c 8192 /dev/zero | tr '\0' '\125' |
    dd of="$WORK/bad-middle.db" bs=4096 seek=$((pages / 2)) count=2 conv=notrunc 2>/dev/null
same "the copy damaged in the middle fails integrity_check" \
    "$(sql "$WORK/bad-middle.db" 'PRAGMA integrity_check' 2>&1 | head -n 1 | grep -qv '^ok$' && echo damaged)" damaged
expect_error "optimize into a file damaged in the middle" 'bad-middle.db: .*(malformed|damaged)' \
    "$FACET" optimize "$ROOF" --db "$WORK/bad-middle.db" --u 10:11 --v 12:12

expect_error "resume of a done run" 'run 1 is done' "$FACET" optimize --db "$DB" --resume 1
expect_error "resume of a run that does not exist" 'no run 99' "$FACET" optimize --db "$DB" --resume 99
expect_error "missing OBJ" 'nothere.obj' \
    "$FACET" optimize "$WORK/nothere.obj" --db "$WORK/fresh.db" "${SMALL[@]}"
expect_error "--u 0:5" "facet: --u: '0:5' is out of range \(1 to 2000\)" "$FACET" optimize "$ROOF" --db "$WORK/fresh.db" --u 0:5
expect_error "--u 10:5 (backwards)" "facet: --u: 10:5 runs backwards" "$FACET" optimize "$ROOF" --db "$WORK/fresh.db" --u 10:5
expect_error "--threshold 5:1 (backwards)" "facet: --threshold: 5:1" \
    "$FACET" optimize "$ROOF" --db "$WORK/fresh.db" --threshold 5:1
expect_error "--threshold 1:5 --method exhaustive needs a step" "facet: --threshold 1:5: .*step" \
    "$FACET" optimize "$ROOF" --db "$WORK/fresh.db" --threshold 1:5 --method exhaustive
expect_error "--objectives nosuch" "facet: --objectives: unknown metric 'nosuch'" \
    "$FACET" optimize "$ROOF" --db "$WORK/fresh.db" --objectives nosuch
expect_error "--db missing" 'name the result database' "$FACET" optimize "$ROOF" "${SMALL[@]}"
expect_error "--resume with an OBJ" 'give no OBJ' "$FACET" optimize "$ROOF" --db "$DB" --resume 1
# A front at the edge of the search: the roof priced SP as FP with no size
# limit worth the name piles its Pareto options at the finest grid; the
# note names the bound and the count, which sqlite3 counts too.
run "$FACET" optimize "$ROOF" --db "$WORK/edge.db" --u 3:9 --v 3:9 --threshold 3 --max-panel-area 1000
edge_db=$WORK/edge.db
at_top=$(sqlite3 "$edge_db" "SELECT count(*) FROM options WHERE run = 1 AND rank = 1 AND nv = 9")
pareto=$(sqlite3 "$edge_db" "SELECT count(*) FROM options WHERE run = 1 AND rank = 1")
if [ "$at_top" -gt 0 ]; then
    stdout_has "optimize notes the front at V's top" "^note: .*$at_top of $pareto Pareto options sit at V = 9, the top of its range 3:9"
    run "$FACET" runs "$edge_db"
    stdout_has "runs notes it too" "^run 1: .*sit at V = 9, the top of its range 3:9.*widen the range"
    run "$FACET" runs "$edge_db" --json
    json_check "runs --json: front_at_bounds as sqlite3 counts it" \
        "{'variable':'nv','bound':'max','value':9,'pareto':$at_top} in j[0]['front_at_bounds']"
else
    fail "the edge case has Pareto options at V = 9 (sqlite3 counts $at_top)"
fi
# A space whose front sits inside: no note.
run "$FACET" optimize "$ROOF" --db "$WORK/inner.db" --u 5:5 --v 5:5 --threshold 3
if grep -q '^note:' "$OUT"; then fail "one grid: no edge note"; else pass "one grid: no edge note"; fi
# The progress line never claims a rate before it has one.
run "$FACET" optimize "$ROOF" --db "$WORK/progress.db" --u 4:20 --v 4:20 --threshold 3
# A rate of 0.0/s, not one that ends in it (2590.0/s).
if grep -qE '(^|[^0-9.])0\.0/s|ETA 0 s' "$ERR"; then
    fail "progress: no 0.0/s or ETA 0 s before a rate is measured"
else
    pass "progress: no 0.0/s or ETA 0 s before a rate is measured"
fi
if tail -n 1 "$ERR" | grep -qE '^progress: 289/289 options \(100%\), [0-9.]+/s, took [0-9.]+ s$'; then
    pass "progress: the last line gives the rate and the time taken"
else
    fail "progress: the last line gives the rate and the time taken"
fi
# Issue 32 item 8: NSGA-II's progress ends at 100 % with the time taken,
# as exhaustive's does. Its total is population x generations, the first
# generation counted (nsga2.h: 8 x 3 = 24 points met, repeats included).
run "$FACET" optimize "$ROOF" --db "$WORK/nsga2-progress.db" --method nsga2 \
    --pop 8 --gens 3 --u 4:20 --v 4:20 --threshold 1:5 --seed 3
if tail -n 1 "$ERR" | grep -qE '^progress: 24/24 options \(100%\), [0-9.]+/s, took [0-9.]+ s$'; then
    pass "progress: NSGA-II ends at 24/24 (100 %) with the time taken"
else
    fail "progress: NSGA-II ends at 24/24 (100 %) with the time taken (last line: $(tail -n 1 "$ERR"))"
fi
# Issue 32 item 7: before a space of hours, optimize says how long, at the
# rate of the file's earlier runs: their panels (options x the mean grid
# of their space) over their seconds, as sqlite3 reads them, for the new
# space's options x its mean grid; a short space says nothing. The run is
# stopped as soon as it has said so.
run "$FACET" optimize "$ROOF" --db "$WORK/estimate.db" --u 10:14 --v 10:14 --threshold 3
if grep -q 'earlier run' "$ERR"; then
    fail "estimate: a run of seconds is not announced"
else
    pass "estimate: a run of seconds is not announced"
fi
"$FACET" optimize "$ROOF" --db "$WORK/estimate.db" --u 1:2000 --v 1:2000 \
    --table 0 >"$OUT" 2>"$ERR" &
pid=$!
for _ in $(seq 1 600); do
    grep -q 'earlier run' "$ERR" 2>/dev/null && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
done
kill -INT "$pid" 2>/dev/null
wait "$pid"
line=$(grep 'earlier run' "$ERR")
want=$(sqlite3 "$WORK/estimate.db" "SELECT sum(options * (u_min + u_max) / 2.0 * (v_min + v_max) / 2.0), sum(elapsed) FROM runs WHERE id = 1" |
    python3 -c '
import sys
work, seconds = map(float, sys.stdin.read().split("|"))
# nsga2 by default for 4 million points: 100 x 50 options, mean grid
# 1000.5 x 1000.5
left = 5000 * 1000.5 * 1000.5 / (work / seconds)
print("%.1f h" % (left / 3600) if left < 48 * 3600 else "%.1f days" % (left / 86400))')
if echo "$line" | grep -qF "facet: 5,000 options (nsga2, at most), about $want at the rate of the 1 earlier run in"; then
    pass "estimate: a space of hours is announced: $want, as sqlite3's rate gives"
else
    fail "estimate: a space of hours is announced: $want, as sqlite3's rate gives (said: $line)"
fi
if echo "$line" | grep -q "Ctrl-C stops it.*--resume goes on"; then
    pass "estimate: ... and says how to stop and go on"
else
    fail "estimate: ... and says how to stop and go on"
fi
# A mesh coarser than the space's finest panels: one warning line before
# the work, stored with the run, and listed by facet runs; a fine mesh has
# none. The warnings depend on the space's finest grid alone (50 x 50), so
# a space of 9 grids ending there checks them as well as the 1,681 of
# 10:50 x 10:50 did, in a hundredth of the time.
"$FACET" example dome --res 4 -o "$WORK/dome4.obj" || exit 1
"$FACET" example dome --res 120 -o "$WORK/dome120.obj" || exit 1
run "$FACET" optimize "$WORK/dome4.obj" --db "$WORK/coarse.db" --u 48:50 --v 48:50 --threshold 3
same "coarse mesh: one warning line on stderr" \
    "$(grep -c '^facet: warning: the mesh is coarse for the finest grid of the space, 50 x 50' "$ERR")" 1
same "coarse mesh: stored with the run" \
    "$(sqlite3 "$WORK/coarse.db" "SELECT warnings LIKE 'the mesh is coarse for the finest grid of the space, 50 x 50:%' FROM runs")" 1
run "$FACET" runs "$WORK/coarse.db" --json
# The dome at 4 x 4 quads: facets 5.2 m, sagging far more than 3 mm too.
json_check "coarse mesh: runs --json lists it, and the facets' sag" 'len(j[0]["warnings"]) == 2 and "coarse" in j[0]["warnings"][0] and "facets sag" in j[0]["warnings"][1]'
run env COLUMNS=80 "$FACET" runs "$WORK/coarse.db"
stdout_has "coarse mesh: runs says it" '^run 1: warning: the mesh is coarse'
run "$FACET" optimize "$WORK/dome120.obj" --db "$WORK/fine.db" --u 48:50 --v 48:50 --threshold 3
if grep -q 'warning' "$ERR"; then fail "fine mesh: no warning"; else pass "fine mesh: no warning"; fi
same "fine mesh: nothing stored" "$(sqlite3 "$WORK/fine.db" "SELECT warnings = '' FROM runs")" 1

# The run's table shows the objectives beyond the paper's columns: a search
# for moulds and kinks lists them, each Pareto row's values as SQLite holds
# them (moulds whole, max kink in degrees to 2 decimals).
"$FACET" example roof --res 30 -o "$WORK/objroof.obj" --force >/dev/null || exit 1
run env COLUMNS=200 "$FACET" optimize "$WORK/objroof.obj" --db "$WORK/obj.db" \
    --u 4:6 --v 4:6 --objectives cost,moulds,max_kink --max-panel-area 1000 --table 0
stdout_has "the table heads the objectives' columns" 'rank +moulds +max kink'
got=$(grep -E '^ +[0-9]+ \*' "$OUT" | sed -E 's/ (knee|infeasible|knee infeasible)$//' |
      awk '{print $1, $(NF-1), $NF}' | sort -n)
want=$(sqlite3 -separator ' ' "$WORK/obj.db" \
    "SELECT number, moulds, printf('%.2f', max_kink) FROM options WHERE rank = 1 ORDER BY number")
same "its rows hold each Pareto option's moulds and max kink" "$got" "$want"

# Issue 32 item 4: a yes/no column is a JSON boolean in options --json,
# as in classify --json (it was 1/0 in one, true/false in the other).
run "$FACET" options "$WORK/obj.db" --run 1 --json
if /usr/bin/python3 -c '
import json, sys
rows = json.load(open(sys.argv[1]))
ok = rows and all(type(r[k]) is bool for r in rows for k in ("feasible", "knee"))
ok = ok and sum(r["knee"] for r in rows) == 1
sys.exit(0 if ok else 1)' "$OUT"; then
    pass "options --json: feasible and knee are true/false, one knee"
else
    fail "options --json: feasible and knee are true/false ($(head -c 300 "$OUT"))"
fi
run "$FACET" classify "$WORK/objroof.obj" --grid 4x4 --json
if /usr/bin/python3 -c '
import json, sys
sys.exit(0 if type(json.load(open(sys.argv[1]))["totals"]["feasible"]) is bool else 1)' "$OUT"; then
    pass "classify --json: feasible is true/false too"
else
    fail "classify --json: feasible is true/false too"
fi

# Issue 32 item 12: --table N prints N rows, a front longer than N cut
# (the cheapest of it first), and says so. The truth: sqlite3's front,
# longer than 2 here, and its two cheapest options.
front=$(sqlite3 "$WORK/obj.db" "SELECT count(*) FROM options WHERE rank = 1")
run env COLUMNS=200 "$FACET" optimize "$WORK/objroof.obj" --db "$WORK/obj2.db" \
    --u 4:6 --v 4:6 --objectives cost,moulds,max_kink --max-panel-area 1000 --table 2
got=$(grep -cE '^ +[0-9]+ \*' "$OUT")
if [ "$front" -gt 2 ] && [ "$got" = 2 ]; then
    pass "--table 2 prints 2 rows of a front of $front"
else
    fail "--table 2 prints 2 rows of a front of $front (printed $got)"
fi
got=$(grep -E '^ +[0-9]+ \*' "$OUT" | awk '{print $1}' | tr '\n' ' ')
want=$(sqlite3 "$WORK/obj2.db" "SELECT number FROM options WHERE rank = 1 ORDER BY cost, number LIMIT 2" | tr '\n' ' ')
same "... the front's two cheapest" "$got" "$want"
stdout_has "... and says the front is cut, naming the command that lists it" \
    "\(2 of [0-9]+ options, the cheapest 2 of $front Pareto-optimal; 'facet options .*obj2\.db --run 1 --pareto' lists the front\)"
exit 0
