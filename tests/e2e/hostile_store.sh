#!/usr/bin/env bash
# End-to-end: a database someone sends you (issue 28, item 6). Hostile
# files are made from a real Facet database with sqlite3: triggers, a
# table replaced by a view, views that recurse for ever, a column changed,
# an older schema. Every command refuses them in one line, at once (under
# timeout 20: a hang fails), and the truth of what did not happen is read
# with sqlite3: no trigger's side effect, no file changed (sha256).
# layers: store cli tui
. "$(dirname "$0")/lib.sh"

if ! command -v sqlite3 >/dev/null; then
    echo "skip - every hostile store check (sqlite3 is not installed)"
    exit 0
fi
store_v4=$(dirname "$FACET")/tools/store_v4
if [ ! -x "$store_v4" ]; then
    echo "not ok - store_v4 tool built ($store_v4 missing; make $store_v4)"
    exit 1
fi

# Two small runs of the plane: run 2 is the one the triggers forge.
"$FACET" example plane --res 8 -o "$WORK/p.obj" >/dev/null || exit 1
for name in one two; do
    "$FACET" optimize "$WORK/p.obj" --db "$WORK/r.db" --u 2:3 --v 2:3 \
        --name "$name" >/dev/null 2>&1 || exit 1
done
q() { sqlite3 -batch "$1" "$2"; }
costs() { q "$1" "SELECT group_concat(cost, ',') FROM options WHERE run = 2"; }
truth=$(costs "$WORK/r.db")
# The schema this Facet writes, as SQLite reads it from the file it made.
V=$(q "$WORK/r.db" 'PRAGMA user_version')
same "(run 2's costs are its own, not 1)" "$(echo "$truth" | grep -c '^1.0')" 0
# An option of run 1 whose panels are not stored: show and export compute
# and store them, as a writer.
unstored=$(q "$WORK/r.db" "SELECT min(number) FROM options WHERE run = 1 AND
    number NOT IN (SELECT option FROM panel_sets WHERE run = 1)")
FORGE="UPDATE options SET cost = 1.0 WHERE run = 2;"
LOOP="WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL SELECT i + 1 FROM n)"
# A run whose writer is gone: a writer's open marks it interrupted (an
# UPDATE of runs), which a trigger on runs would follow.
ORPHAN="UPDATE runs SET status = 'running', writer_pid = 2147483646,
    writer_host = '$(hostname)' WHERE id = 1;"

# hostile NAME SQL: a copy of r.db with SQL run on it by sqlite3.
hostile() {
    cp "$WORK/r.db" "$WORK/$1.db"
    q "$WORK/$1.db" "$2" || echo "not ok - (sqlite3 made $1.db)"
}

# refused NAME PATTERN DB CMD...: CMD (on DB) exits 2 within 20 s with one
# line on stderr matching PATTERN, and DB is byte for byte as it was.
refused() {
    local name=$1 pattern=$2 db=$3 sum
    shift 3
    sum=$(sha256sum <"$db")
    run timeout 20 "$@"
    if [ "$STATUS" -eq 2 ] && [ "$(wc -l <"$ERR")" -eq 1 ] &&
        grep -qE "$pattern" "$ERR" && [ "$(sha256sum <"$db")" = "$sum" ]; then
        pass "$name"
    else
        fail "$name (want status 2, one line matching: $pattern, the file unchanged)"
    fi
}

# (a) Triggers on the paths that write: show and export store the panels
# they compute, --resume claims the run. None fires: the file is refused,
# and run 2's costs are its own (sqlite3).
hostile panels "CREATE TRIGGER forge AFTER INSERT ON panel_sets BEGIN $FORGE END;"
refused "show: a trigger on panel_sets is refused, not fired" \
    "panels\.db: holds trigger 'forge' on panel_sets, which Facet never makes" \
    "$WORK/panels.db" "$FACET" show "$WORK/panels.db" --run 1 --option "$unstored"
same "  ... run 2's costs not forged (sqlite3)" "$(costs "$WORK/panels.db")" "$truth"
hostile export "CREATE TRIGGER forge AFTER INSERT ON panels BEGIN $FORGE END;"
refused "export: a trigger on panels is refused, not fired" "holds trigger 'forge' on panels" \
    "$WORK/export.db" "$FACET" export "$WORK/export.db" --run 1 --option "$unstored" \
    --csv "$WORK/schedule.csv"
same "  ... run 2's costs not forged, no schedule written" \
    "$(costs "$WORK/export.db") $([ -e "$WORK/schedule.csv" ] && echo written)" "$truth "
hostile resume "UPDATE runs SET status = 'interrupted' WHERE id = 1;
    CREATE TRIGGER forge AFTER UPDATE ON runs BEGIN $FORGE END;"
refused "--resume: a trigger on runs is refused, not fired" "holds trigger 'forge' on runs" \
    "$WORK/resume.db" "$FACET" optimize --db "$WORK/resume.db" --resume 1
same "  ... run 2's costs not forged, run 1 still interrupted" \
    "$(costs "$WORK/resume.db") $(q "$WORK/resume.db" 'SELECT status FROM runs WHERE id = 1')" \
    "$truth interrupted"

# (b) An older schema: a command that reads does not migrate it (a writer
# would, and the file's triggers would run); it says how to, and the file
# is byte for byte as it was. facet migrate migrates it.
cp "$WORK/r.db" "$WORK/old.db"
"$store_v4" "$WORK/old.db" || exit 1
for cmd in "runs" "options" "show --run 1 --option $unstored" "plot --run 1 -o $WORK/plot.svg"; do
    # shellcheck disable=SC2086
    refused "${cmd%% *} on an older file: refused, saying how to migrate it, the file unchanged" \
        "old\\.db: written by an older Facet \\(schema 4; this one reads $V\\).*facet migrate FILE" \
        "$WORK/old.db" "$FACET" ${cmd%% *} "$WORK/old.db" ${cmd#"${cmd%% *}"}
done
expect "facet migrate migrates it" 0 "$FACET" migrate "$WORK/old.db"
stdout_has "  ... saying from and to" "old\\.db: migrated from schema 4 to $V\$"
same "  ... schema $V (sqlite3)" "$(q "$WORK/old.db" 'PRAGMA user_version')" "$V"
expect "  ... and facet runs reads it" 0 "$FACET" runs "$WORK/old.db"
expect "facet migrate again: nothing to do" 0 "$FACET" migrate "$WORK/old.db"
stdout_has "  ... and says so" "already at schema $V; nothing to do"
# What the issue saw: facet runs migrated an older file as a writer, and
# a trigger then forged another run's costs.
cp "$WORK/r.db" "$WORK/oldtrigger.db"
"$store_v4" "$WORK/oldtrigger.db" || exit 1
q "$WORK/oldtrigger.db" "$ORPHAN CREATE TRIGGER forge AFTER UPDATE ON runs BEGIN $FORGE END;"
refused "runs on an older file with a trigger: refused, not migrated" "holds trigger 'forge' on runs" \
    "$WORK/oldtrigger.db" "$FACET" runs "$WORK/oldtrigger.db"
same "  ... run 2's costs not forged, schema still 4 (sqlite3)" \
    "$(costs "$WORK/oldtrigger.db") $(q "$WORK/oldtrigger.db" 'PRAGMA user_version')" "$truth 4"
refused "facet migrate refuses it too" "holds trigger 'forge' on runs" \
    "$WORK/oldtrigger.db" "$FACET" migrate "$WORK/oldtrigger.db"

# (c) A table replaced by a view, a view or trigger that never ends: one
# line and exit 2 at once, never a hang.
hostile runsview "ALTER TABLE runs RENAME TO runs_kept;
    CREATE VIEW runs AS SELECT * FROM runs_kept;"
refused "runs: a view where the runs table should be is refused" \
    "'runs' is a view where Facet keeps a table" \
    "$WORK/runsview.db" "$FACET" runs "$WORK/runsview.db"
hostile runsloop "ALTER TABLE runs RENAME TO runs_kept;
    CREATE VIEW runs AS $LOOP SELECT runs_kept.* FROM runs_kept, n;"
for cmd in "runs" "options" "show --run 1 --option 1"; do
    # shellcheck disable=SC2086
    refused "${cmd%% *}: a runs view that recurses for ever: refused at once" \
        "'runs' is a view where Facet keeps a table" \
        "$WORK/runsloop.db" "$FACET" ${cmd%% *} "$WORK/runsloop.db" ${cmd#"${cmd%% *}"}
done
hostile optionsloop "ALTER TABLE options RENAME TO options_kept;
    CREATE VIEW options AS $LOOP SELECT options_kept.* FROM options_kept, n;"
refused "options: an options view that recurses for ever: refused at once" \
    "'options' is a view where Facet keeps a table" \
    "$WORK/optionsloop.db" "$FACET" options "$WORK/optionsloop.db"
hostile paretoloop "DROP VIEW pareto; CREATE VIEW pareto AS $LOOP SELECT * FROM n;"
refused "runs: a view Facet did not make (Facet's pareto, redefined) is refused" \
    "holds view 'pareto', which is not Facet's" \
    "$WORK/paretoloop.db" "$FACET" runs "$WORK/paretoloop.db"
hostile triggerloop "$ORPHAN CREATE TRIGGER spin AFTER UPDATE ON runs BEGIN
    $LOOP SELECT count(*) FROM n; END;"
refused "show: a trigger that never ends is refused, not fired" "holds trigger 'spin' on runs" \
    "$WORK/triggerloop.db" "$FACET" show "$WORK/triggerloop.db" --run 2 --option 1

# (d) Facet's tables as Facet declares them: a column's type changed, a
# column dropped.
hostile texttype "PRAGMA writable_schema = ON;
    UPDATE sqlite_schema SET sql = replace(sql, ' cost REAL NOT NULL,', ' cost TEXT NOT NULL,')
    WHERE name = 'options';"
same "(sqlite3: options.cost is TEXT)" \
    "$(q "$WORK/texttype.db" "SELECT type FROM pragma_table_info('options') WHERE name = 'cost'")" TEXT
refused "options: a column's type changed is refused, naming it" \
    "column options\.cost is 'TEXT NOT NULL' where Facet's schema $V has 'REAL NOT NULL'" \
    "$WORK/texttype.db" "$FACET" options "$WORK/texttype.db"
hostile dropped "ALTER TABLE options DROP COLUMN knee;"
refused "runs: a column dropped is refused, naming it" "table options has no column knee" \
    "$WORK/dropped.db" "$FACET" runs "$WORK/dropped.db"

# What the pragmas do not show: a CHECK of the file's own on a Facet
# table, and an index on an expression, both run by Facet's writes.
hostile check "PRAGMA writable_schema = ON;
    UPDATE sqlite_schema SET sql = replace(sql, ' cost REAL NOT NULL,',
        ' cost REAL NOT NULL CHECK (length(printf(''%.*c'', 100000000, ''x'')) > 0),')
    WHERE name = 'options';"
refused "options: a CHECK of the file's own on options is refused" \
    "table options is not declared as Facet's schema $V declares it" \
    "$WORK/check.db" "$FACET" options "$WORK/check.db"
hostile expression "CREATE INDEX spin ON panels(length(printf('%.*c', 100000000, 'x')));"
refused "show: an index on an expression is refused" "holds index 'spin' on panels, on an expression" \
    "$WORK/expression.db" "$FACET" show "$WORK/expression.db" --run 1 --option "$unstored"

# What the file may add of its own: an index and a table of its own read
# as before.
hostile mine "CREATE INDEX mine ON options(cost, nu); CREATE TABLE notes (text TEXT);"
expect "runs: a file with an index and a table of the user's own" 0 "$FACET" runs "$WORK/mine.db"
expect "options: likewise" 0 "$FACET" options "$WORK/mine.db"

# (e) A shard whose options table was rebuilt without NOT NULL hid a NULL
# cost from the merge's check (it read the shard's own NOT NULL): the
# shard is refused against Facet's declared schema, nothing is written.
for i in 1 2; do
    "$FACET" optimize "$WORK/p.obj" --db "$WORK/shard$i.db" --u 2:3 --v 2:3 \
        --shard "$i/2" >/dev/null 2>&1 || exit 1
done
q "$WORK/shard1.db" "PRAGMA writable_schema = ON;
    UPDATE sqlite_schema SET sql = replace(sql, ' cost REAL NOT NULL,', ' cost REAL,')
    WHERE name = 'options';"
q "$WORK/shard1.db" "UPDATE options SET cost = NULL WHERE number = (SELECT min(number) FROM options);"
same "(sqlite3: shard 1 holds a NULL cost)" \
    "$(q "$WORK/shard1.db" 'SELECT count(*) FROM options WHERE cost IS NULL')" 1
run timeout 20 "$FACET" merge "$WORK/merged.db" "$WORK/shard1.db" "$WORK/shard2.db"
same "merge: a shard without NOT NULL on cost is refused in one line, naming it, nothing written" \
    "$STATUS $(wc -l <"$ERR") $(grep -c "shard1\.db: column options\.cost is 'REAL' where Facet's schema $V has 'REAL NOT NULL'" "$ERR") $(ls "$WORK" | grep -c '^merged\.db')" \
    "2 1 1 0"

# (f) The workbench opening a hostile file: the message, not a hang.
. "$(dirname "$0")/tui_lib.sh"
# tui_refused NAME PATTERN DB: facet tui DB ends with status 2 and one
# line on stderr matching PATTERN, DB unchanged.
tui_refused() {
    local sum i=0
    sum=$(sha256sum <"$3")
    start 100 30 -- "$(basename "$3")"
    while [ ! -s "$WORK/exit" ] && [ $i -lt 400 ]; do sleep 0.05; i=$((i + 1)); done
    if [ "$(cat "$WORK/exit" 2>/dev/null)" = 2 ] && [ "$(wc -l <"$WORK/tui.err")" -eq 1 ] &&
        grep -qE "$2" "$WORK/tui.err" && [ "$(sha256sum <"$3")" = "$sum" ]; then
        pass "$1"
    else
        echo "not ok - $1 (exit '$(cat "$WORK/exit" 2>/dev/null)', want 2 and one line matching: $2)"
        sed 's/^/  stderr: /' "$WORK/tui.err" | head -n 5
        screen | sed 's/^/  screen: /' | head -n 10
    fi
    end_session
}
tui_refused "tui: a runs view that recurses for ever: refused at once" \
    "'runs' is a view where Facet keeps a table" "$WORK/runsloop.db"
tui_refused "tui: a trigger that never ends: refused" "holds trigger 'spin' on runs" \
    "$WORK/triggerloop.db"
cp "$WORK/r.db" "$WORK/oldtui.db"
"$store_v4" "$WORK/oldtui.db" || exit 1
tui_refused "tui: an older file is not migrated behind the user's back" \
    "written by an older Facet \\(schema 4; this one reads $V\\).*facet migrate FILE" "$WORK/oldtui.db"
exit 0
