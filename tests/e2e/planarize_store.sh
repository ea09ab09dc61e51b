#!/usr/bin/env bash
# End-to-end: planarized options stored like any option (issue 33, items
# 1 to 3). facet optimize --planarize adds the planarized option of each
# Pareto grid beside the classified ones: read back with sqlite3, a
# classified option's closeness and planarity are NULL (never 0) and its
# kind 0; a planarized option's row and panels are checked by
# planarize_store_check.py against numpy's own measure of the stored
# corners (brute-force distance to the surface's triangles, each quad's
# diagonals) and against facet planarize --json for the same grid. A
# surface of revolution (a conjugate net) planarizes feasibly and beats
# its classified options on cost; the hypar's rulings are stored
# infeasible, never called planar. facet planarize --db stores the same
# as a run of its own. Bad input: one line, status 2.
# layers: cli study store core
. "$(dirname "$0")/lib.sh"
HERE=$(cd "$(dirname "$0")" && pwd)
cd "$WORK" || exit 1
/usr/bin/python3 "$HERE/planarize_check.py" vase vase.obj || exit 1

run "$FACET" optimize vase.obj --db v.db --u 10:11 --v 8:8 --threshold 3 \
    --planarize 0.1
[ "$STATUS" -eq 0 ] && pass "optimize --planarize 0.1 on a surface of revolution" ||
    fail "optimize --planarize 0.1 on a surface of revolution"
q() { sqlite3 v.db "$1"; }
same "the run stores its budget (mm)" "$(q 'SELECT planarize_closeness_mm FROM runs')" "0.1"
same "one planarized option per Pareto grid" \
    "$(q 'SELECT count(*) FROM options WHERE planarized = 1')" \
    "$(q 'SELECT count(DISTINCT nu || "x" || nv) FROM options WHERE planarized = 0 AND rank = 1')"
same "classified options reached nothing: NULL, never 0" \
    "$(q 'SELECT count(*) FROM options WHERE planarized = 0 AND (closeness_reached IS NOT NULL OR closeness_mean IS NOT NULL OR planarity_reached IS NOT NULL OR planar_over IS NOT NULL)')" "0"
same "planarized options reached something" \
    "$(q 'SELECT count(*) FROM options WHERE planarized = 1 AND (closeness_reached IS NULL OR planarity_reached IS NULL OR planar_over IS NULL)')" "0"
same "a classified option's panels moved no corner: NULL" \
    "$(q 'SELECT count(*) FROM panels p JOIN options o ON o.run = p.run AND o.number = p.option WHERE o.planarized = 0 AND (p.corner_moved IS NOT NULL OR p.corner_distance IS NOT NULL)')" "0"
OPT=$(q 'SELECT number FROM options WHERE planarized = 1 AND nu = 10')
same "the 10 x 8 planarized option is feasible, all FP" \
    "$(q "SELECT feasible, fp_count, planar_over FROM options WHERE number = $OPT")" "1|80|0"
same "planarizing beats classifying on this surface: it is the cheapest" \
    "$(q 'SELECT planarized FROM options ORDER BY cost LIMIT 1')" "1"
same "and it is on the front" "$(q "SELECT rank FROM options WHERE number = $OPT")" "1"
run "$FACET" planarize vase.obj --grid 10x8 --closeness 0.1 --json
cp "$OUT" vase10.json
/usr/bin/python3 "$HERE/planarize_store_check.py" vase.obj v.db 1 "$OPT" vase10.json ||
    fail "planarize_store_check.py did not finish on the vase"

# What a fabricator gets: the schedule's corner columns and the OBJ's quads,
# checked against the panels table and numpy by planarize_export_check.py.
COPT=$(q 'SELECT number FROM options WHERE planarized = 0 ORDER BY number LIMIT 1')
for kind in p c; do
    o=$OPT; [ "$kind" = c ] && o=$COPT
    run "$FACET" export v.db --run 1 --option "$o" --csv "x-$kind.csv" \
        --json "x-$kind.json" --xlsx "x-$kind.xlsx" --obj "x-$kind.obj"
    [ "$STATUS" -eq 0 ] && pass "export of option $o ($kind)" ||
        fail "export of option $o ($kind): $(cat "$ERR")"
done
/usr/bin/python3 "$HERE/planarize_export_check.py" vase.obj v.db 1 "$OPT" "$COPT" x ||
    fail "planarize_export_check.py did not finish"

run "$FACET" show v.db --run 1 --option "$OPT"
stdout_has "show says the option is planarized" "^kind +planarized"
stdout_has "show says what it reached" "^closeness +reached [0-9.]+ mm at most.*budget 0.1 mm"
run "$FACET" show v.db --run 1 --option 1
stdout_has "show says a classified option is classified" "^kind +classified"
run "$FACET" options v.db --run 1 --csv
if /usr/bin/python3 - "$OUT" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
p = [r for r in rows if r["planarized"] == "1"]
c = [r for r in rows if r["planarized"] == "0"]
ok = p and c and all(r["closeness_reached_m"] != "" for r in p) and \
    all(r["closeness_reached_m"] == "" and r["planarity_reached"] == ""
        for r in c)
sys.exit(0 if ok else 1)
PY
then pass "options --csv: closeness_reached_m and planarity_reached, empty when classified"
else fail "options --csv: closeness_reached_m and planarity_reached, empty when classified"
fi

"$FACET" example hypar -o hypar.obj 2>/dev/null
run "$FACET" optimize hypar.obj --db h.db --u 6:6 --v 6:6 --threshold 3 \
    --planarize 5
[ "$STATUS" -eq 0 ] && pass "optimize --planarize 5 on the hypar" ||
    fail "optimize --planarize 5 on the hypar"
HOPT=$(sqlite3 h.db 'SELECT number FROM options WHERE planarized = 1')
same "the hypar's planarized option is stored infeasible, far off the surface" \
    "$(sqlite3 h.db "SELECT feasible, planar_over > 0, closeness_reached > 0.005 FROM options WHERE number = $HOPT")" "0|1|1"
run "$FACET" planarize hypar.obj --grid 6x6 --closeness 5 --json
cp "$OUT" hypar6.json
/usr/bin/python3 "$HERE/planarize_store_check.py" hypar.obj h.db 1 "$HOPT" hypar6.json ||
    fail "planarize_store_check.py did not finish on the hypar"
run "$FACET" show h.db --run 1 --option "$HOPT"
stdout_has "show says the hypar's option is INFEASIBLE, not planar" \
    "^planarized +INFEASIBLE: [0-9]+ quads not planar or beyond the budget"

# facet planarize --db: the option stored like any option, a new run of
# the one grid, its classified option beside it; checked as optimize
# --planarize's (sqlite3, and numpy by planarize_store_check.py against
# the stored corners and facet planarize --json's own run).
run "$FACET" planarize vase.obj --grid 11x8 --closeness 0.2 --db pv.db --json
[ "$STATUS" -eq 0 ] && pass "planarize --db stores the vase's 11 x 8 grid" ||
    fail "planarize --db stores the vase's 11 x 8 grid: $(cat "$ERR")"
cp "$OUT" stored.json
p() { sqlite3 pv.db "$1"; }
same "one run, of the vase, its budget 0.2 mm" \
    "$(p 'SELECT count(*), max(planarize_closeness_mm), max(surface_path LIKE "%vase.obj") FROM runs')" "1|0.2|1"
same "the grid classified and planarized: two options, one planarized" \
    "$(p 'SELECT count(*), sum(planarized), min(nu), max(nu), min(nv), max(nv) FROM options')" "2|1|11|11|8|8"
POPT=$(p 'SELECT number FROM options WHERE planarized = 1')
COPT2=$(p 'SELECT number FROM options WHERE planarized = 0')
same "its panels are stored, every one with its corner distance" \
    "$(p "SELECT count(*), count(corner_distance) FROM panels WHERE option = $POPT")" "88|88"
same "it says the run and options it stored" \
    "$(/usr/bin/python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); print(j["run"], j["option"], j["classified_option"])' stored.json)" \
    "1 $POPT $COPT2"
if /usr/bin/python3 - stored.json pv.db "$POPT" <<'PY'
import json, sqlite3, sys
j = json.load(open(sys.argv[1]))
r = sqlite3.connect(sys.argv[2]).execute(
    "SELECT closeness_reached, closeness_mean, planarity_reached, planar_over,"
    " cost FROM options WHERE number = ?", (int(sys.argv[3]),)).fetchone()
ok = (j["closeness_max_mm"] == r[0] * 1000 and
      j["closeness_mean_mm"] == r[1] * 1000 and
      j["planarity_max"] == r[2] and j["quads_missed"] == r[3] and
      j["feasible"] == (r[3] == 0) and j["cost_usd"] == r[4])
sys.exit(0 if ok else 1)
PY
then pass "what it says was reached is what the store holds, exactly"
else fail "what it says was reached is what the store holds, exactly"
fi
run "$FACET" planarize vase.obj --grid 11x8 --closeness 0.2 --json
cp "$OUT" vase11.json
/usr/bin/python3 "$HERE/planarize_store_check.py" vase.obj pv.db 1 "$POPT" vase11.json ||
    fail "planarize_store_check.py did not finish on planarize --db"
run "$FACET" show pv.db --run 1 --option "$POPT"
stdout_has "show sees the stored option as planarized" "^kind +planarized"
run "$FACET" planarize hypar.obj --grid 6x6 --closeness 5 --db pv.db
[ "$STATUS" -eq 0 ] && pass "planarize --db adds the hypar's run to the same file" ||
    fail "planarize --db adds the hypar's run: $(cat "$ERR")"
stdout_has "it says the hypar is INFEASIBLE" "^result +INFEASIBLE under the 5 mm budget"
same "the hypar's run is stored infeasible, far off the surface" \
    "$(p 'SELECT feasible, planar_over > 0, closeness_reached > 0.005 FROM options WHERE run = 2 AND planarized = 1')" "0|1|1"
# Bad input: one line, status 2, no database made.
expect_error "planarize --db in a folder that does not exist" \
    "no/such/x\.db" "$FACET" planarize vase.obj --grid 4x4 --db no/such/x.db
echo "not a database" >text.db
expect_error "planarize --db of a file that is not a database" \
    "text\.db: not an SQLite database" "$FACET" planarize vase.obj \
    --grid 4x4 --db text.db
sqlite3 alien.db 'CREATE TABLE t(x); INSERT INTO t VALUES (1);'
expect_error "planarize --db of another application's database" \
    "alien\.db: an SQLite database of another application" "$FACET" \
    planarize vase.obj --grid 4x4 --db alien.db
expect_error "planarize --db of a surface that does not exist" \
    "missing\.obj: cannot open" "$FACET" planarize missing.obj --grid 4x4 \
    --db new.db
expect_error "planarize --db --closeness 0" "planarize: --closeness 0 and --db" \
    "$FACET" planarize vase.obj --grid 4x4 --closeness 0 --db new.db
expect_error "planarize --db --planarity" "planarize: --planarity and --db" \
    "$FACET" planarize vase.obj --grid 4x4 --planarity 0.01 --db new.db
expect_error "planarize --db --obj" "planarize: --obj and --db" \
    "$FACET" planarize vase.obj --grid 4x4 --obj x.obj --db new.db
same "none of them made a database" "$(ls new.db* x.obj 2>/dev/null)" ""
if [ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null; then
    # root writes anywhere: the read-only folder is tried as nobody.
    mkdir -p ro && chmod 555 ro && chmod 755 "$WORK" && chmod 644 vase.obj
    expect_error "planarize --db in a read-only folder" "ro/x\.db" \
        setpriv --reuid=nobody --regid=nogroup --clear-groups \
        "$FACET" planarize vase.obj --grid 4x4 --db ro/x.db
    same "nothing made in it" "$(ls -A ro)" ""
    chmod 755 ro; chmod 700 "$WORK"
else
    skip "planarize --db in a read-only folder" "it needs root and setpriv to act as another user"
fi

expect_error "--planarize 0" "^facet: --planarize" "$FACET" optimize \
    hypar.obj --db x.db --planarize 0
expect_error "--planarize negative" "^facet: --planarize" "$FACET" optimize \
    hypar.obj --db x.db --planarize -1
expect_error "--planarize NaN" "^facet: --planarize" "$FACET" optimize \
    hypar.obj --db x.db --planarize nan
expect_error "--planarize on --resume" "give no --planarize" "$FACET" \
    optimize --db h.db --resume 1 --planarize 5
exit 0
