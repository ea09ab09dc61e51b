#!/usr/bin/env bash
# End-to-end: a run an older Facet stored, before schema v5 counted moulds
# and measured joints. A run of the example torus is taken back to schema 4
# (tools/store_v4); the next Facet migrates it and its options' new
# columns are NULL (the truth, read with sqlite3). Facet shows them as not
# known, never as 0: empty in --csv, null in --json, "- (not measured
# ...)" in show, "not measured" in the workbench's detail pane and "-" in
# its map legend; a sort by them keeps every option. A command that reads refuses the older file
# until facet migrate has migrated it.
# layers: store cli
. "$(dirname "$0")/lib.sh"

build=${BUILD:-build/release}
store_v4=$build/tools/store_v4
if [ ! -x "$store_v4" ]; then
    echo "not ok - store_v4 tool built ($store_v4 missing; make $store_v4)"
    exit 1
fi
if ! command -v sqlite3 >/dev/null; then
    echo "skip - every older store check (sqlite3 is not installed)"
    exit 0
fi
"$FACET" example torus --res 24 -o "$WORK/torus.obj" >/dev/null || exit 1
"$FACET" optimize "$WORK/torus.obj" --db "$WORK/old.db" --u 4:5 --v 4:5 \
    --threshold 3 >/dev/null 2>&1 || exit 1
# the schema this Facet writes, from the file it just wrote
CURRENT=$(sqlite3 "$WORK/old.db" 'PRAGMA user_version')
"$store_v4" "$WORK/old.db" || exit 1
q() { sqlite3 "$WORK/old.db" "$1"; }
same "(the file is at schema 4)" "$(q 'PRAGMA user_version')" 4

# Reading never migrates (issue 28, item 6): options refuses the file in
# one line that says how to migrate it, and leaves it byte for byte; facet
# migrate, a writer asked for by name, migrates it.
sum_before=$(sha256sum <"$WORK/old.db")
expect_error "facet options refuses an older file, saying how to migrate it" \
    "old.db: written by an older Facet \\(schema 4; this one reads $CURRENT\\).*facet migrate FILE" \
    "$FACET" options "$WORK/old.db" --csv
same "(sha256: the older file is as it was)" "$(sha256sum <"$WORK/old.db")" "$sum_before"
expect "facet migrate migrates it" 0 "$FACET" migrate "$WORK/old.db"
stdout_has "  ... and says so" "old.db: migrated from schema 4 to $CURRENT\$"
expect "(facet options lists the run)" 0 "$FACET" options "$WORK/old.db" --csv
same "(sqlite3: migrated past 4, the old options' mould counts and joints NULL)" \
    "$(q 'SELECT (SELECT user_version >= 5 FROM pragma_user_version), count(*) FROM options
          WHERE moulds IS NULL AND sp_moulds IS NULL AND dp_moulds IS NULL
          AND largest_family IS NULL AND single_moulds IS NULL
          AND joint_length IS NULL AND mould_cost IS NULL')" "1|4"
V5='moulds sp_moulds dp_moulds largest_family single_moulds joint_length area_cost mould_cost'
# (the CSV names a column with its unit: csv_names.py)
if PYTHONPATH=$(dirname "$0") python3 - "$OUT" $V5 <<'EOF'
import csv, sys
from csv_names import csv_name
rows = list(csv.DictReader(open(sys.argv[1])))
sys.exit(0 if len(rows) == 4 and
         all(r[csv_name(c)] == "" for r in rows for c in sys.argv[2:]) else 1)
EOF
then pass "--csv: the NULL columns are empty fields (not 0)"
else fail "--csv: the NULL columns are empty fields (not 0)"; fi
run "$FACET" options "$WORK/old.db" --json
json_check "--json: the NULL columns are null (not 0)" \
    "len(j) == 4 and all(o[c] is None for o in j for c in '$V5'.split())"

knee=$(q 'SELECT number FROM options WHERE knee')
same "(the knee's panels are stored: show reads its totals from the file)" \
    "$(q "SELECT count(*) > 0 FROM panels WHERE option = $knee")" 1
run "$FACET" show "$WORK/old.db" --run 1 --option "$knee"
stdout_has "show: moulds not stored, not 0" '^moulds +- \(not measured in this run, or stored by an older Facet'
stdout_has "show: joint length not stored, not nan" '^joint length +- \(not measured in this run, or stored by an older Facet'
stdout_has "show: the cost terms not stored" '^cost terms +- \(not measured in this run, or stored by an older Facet'
if grep -qiE '(^| )nan( |$)' "$OUT"; then fail "show writes no nan"; else pass "show writes no nan"; fi
run "$FACET" show "$WORK/old.db" --run 1 --option "$knee" --json
json_check "show --json: the totals not stored are null" \
    "all(j['totals'][c] is None for c in '$V5'.split())"

for key in moulds joint_length; do
    run "$FACET" options "$WORK/old.db" --sort "$key,cost" --csv
    if [ "$STATUS" = 0 ] && [ "$(tail -n +2 "$OUT" | wc -l)" = 4 ]; then
        pass "--sort $key (no option has a value): every option"
    else
        fail "--sort $key (no option has a value): every option"
    fi
done

# Migrated on to schema 10: the run intact, its options no module (NULL),
# no surfaces recorded (8, projects), what it measured not recorded (9:
# NULL, every measure, as every run before took them), no smallest SP
# bending radius (10: NULL, never measured then), no smallest panel, its
# width or slivers and no width limit (12: NULL, never measured then).
same "(sqlite3: v4 migrated to $CURRENT, the run's options without a module)" \
    "$(q 'SELECT (SELECT user_version FROM pragma_user_version), count(*), count(module_w), count(module_h), count(modules), (SELECT count(*) FROM surfaces), (SELECT count(*) FROM option_surfaces), (SELECT module_w_min IS NULL FROM runs), (SELECT measured IS NULL FROM runs), count(sp_min_radius), count(min_panel_area), count(min_panel_width), count(slivers), (SELECT min_panel_width IS NULL FROM runs) FROM options')" \
    "$CURRENT|4|0|0|0|0|0|1|1|0|0|0|0|1"
# ... and no seams (15: NULL, a single surface's and never measured then),
# no welding tolerance.
same "(sqlite3: v4 migrated to $CURRENT, no seams, no welding tolerance)" \
    "$(q 'SELECT count(*), count(seams), count(seam_length), count(seam_max_gap), count(seam_max_kink), count(seam_max_crease), count(seam_gaps_over), count(seam_kinks_over), (SELECT weld_mm IS NULL FROM runs) FROM options')" \
    "4|0|0|0|0|0|0|0|1"

# A run of schema 7 (the last before projects) and one of schema 3: both
# are refused by facet runs, and migrate to 12 with their runs as they were.
for version in 7 3; do
    db=$WORK/v$version.db
    "$FACET" optimize "$WORK/torus.obj" --db "$db" --u 4:5 --v 4:5 --threshold 3 >/dev/null 2>&1 || exit 1
    before=$(sqlite3 "$db" 'SELECT id, name, status, surface_sha256, u_min, u_max, v_min, v_max, options, knee, hypervolume FROM runs;
                             SELECT number, nu, nv, cost, rank FROM options ORDER BY number')
    if [ "$version" = 7 ]; then
        "$store_v4" "$db" 7 || exit 1
    else
        "$store_v4" "$db" || exit 1
        sqlite3 "$db" "ALTER TABLE runs DROP COLUMN uv; ALTER TABLE runs DROP COLUMN warnings;
                       ALTER TABLE runs DROP COLUMN store_panels; PRAGMA user_version = 3;"
    fi
    same "(the file is at schema $version)" "$(sqlite3 "$db" 'PRAGMA user_version')" "$version"
    expect_error "schema $version: facet runs refuses it, saying how to migrate it" \
        "written by an older Facet \\(schema $version;.*facet migrate FILE" "$FACET" runs "$db"
    expect "schema $version: facet migrate migrates it" 0 "$FACET" migrate "$db"
    same "schema $version: migrated to $CURRENT, with the project tables" \
        "$(sqlite3 "$db" "SELECT (SELECT user_version FROM pragma_user_version), count(*) FROM sqlite_master WHERE name IN ('surfaces', 'option_surfaces')")" "$CURRENT|2"
    same "schema $version: the run and its options as they were" \
        "$(sqlite3 "$db" 'SELECT id, name, status, surface_sha256, u_min, u_max, v_min, v_max, options, knee, hypervolume FROM runs;
                          SELECT number, nu, nv, cost, rank FROM options ORDER BY number')" "$before"
    same "schema $version: no module, no surfaces for the old run" \
        "$(sqlite3 "$db" 'SELECT count(module_w) + count(modules), (SELECT count(*) FROM surfaces), (SELECT count(module_w_min) FROM runs) FROM options')" "0|0|0"
done

# The workbench: the detail pane and the map's legend by mould family.
. "$(dirname "$0")/tui_lib.sh"
start 160 40 -- old.db
check "(the runs)" '^ +1 done'
keys Enter
check "(the run's table)" '^ Run 1 '
keys K
check "(the knee)" "knee option $knee"
check "the detail pane: moulds not known" '^ .* moulds +not measured *$'
check "the detail pane: SP moulds not known" '^ .* SP moulds +not measured *$'
keys Enter
check "(its panel map)" '^ Panel map'
keys F2 F2
check "the legend by mould family: SP and DP families not known" '^ .* DP +- +[0-9]+ *$'
check "  ... the families not stored" 'families not stored \(older run\)'
check "the cursor's panel: its family not stored, not 'an FP panel'" "mould family not stored \(an older Facet's run\)"
keys F10
check_exit "(F10 quits)"
