#!/usr/bin/env bash
# End-to-end: the cost model beyond area (panels, joints, moulds; issue 15)
# through classify, optimize, the store, show and export, checked against
# SQLite and sums made here; and the paper's study unchanged when the new
# terms are 0: the options of the paper's space, to the last bit, as the
# Facet before the cost model (commit 55c44a9) stored them, with the
# classes issue 29 items 1-2 corrected (a curvature the estimate cannot
# tell from zero is zero: 335 of the 397 classes that changed on the fine
# roof now agree with the formula's Table 1, 14 no longer do), made again
# by Facet after that change with sqlite3 (data/paper_space_issue29.csv); terms that
# are 0 change nothing of it.
# layers: core study store cli
. "$(dirname "$0")/lib.sh"

HERE=$(cd "$(dirname "$0")" && pwd)
sql() { sqlite3 -batch "$1" "$2"; }

fixture roof.obj || exit 1
ROOF=$WORK/roof.obj
COSTS=(--panel-cost 250 --joint-cost 40 --mould-cost 3000,20000)

# --- The paper's study: today's numbers when the new terms are 0 --------
# The paper types SP by class alone (--sp-fit no); as built (the default)
# the panels no cylinder or cone fits are DP and its numbers change
# (docs/method.md, "Panels as built").
# (the fixture paper.db: --u 20:40 --v 35:50 --threshold 3 --sp-as-fp
# --max-panel-area 1.92 --sp-fit no --name paper)
fixture_run paper.db "$WORK/paper.db"
if [ "$STATUS" -ne 0 ]; then fail "paper space runs"; else pass "paper space runs"; fi
sqlite3 -batch -csv "$WORK/paper.db" "SELECT nu,nv,printf('%.17g',threshold_mm),panels,fp_count,sp_count,dp_count,printf('%.17g',fp_area),printf('%.17g',sp_area),printf('%.17g',dp_area),printf('%.17g',cost),printf('%.17g',planarity),printf('%.17g',max_deviation),printf('%.17g',max_panel_area),feasible,rank,printf('%.17g',crowding),knee FROM options ORDER BY number" >"$WORK/paper.csv"
if cmp -s "$WORK/paper.csv" "$HERE/data/paper_space_issue29.csv"; then
    pass "paper space: the 336 options of the pin (55c44a9, classes of issue 29), every number to the bit"
else
    echo "not ok - paper space: the 336 options of the pin (55c44a9, classes of issue 29), every number to the bit"
    diff "$WORK/paper.csv" "$HERE/data/paper_space_issue29.csv" | head -5
fi
same "paper space: terms 0, cost = area cost" \
    "$(sql "$WORK/paper.db" "SELECT count(*) FROM options WHERE panel_cost = 0 AND joint_cost = 0 AND mould_cost = 0 AND cost = fp_cost + sp_cost + dp_cost")" 336
# Nothing it reads needs moulds or joints (issue 27): the run records
# that it measured none of them; its Pareto options are measured in full,
# every other option's moulds and joint length are not measured (NULL),
# never 0.
same "paper space: the run measured nothing beyond the classed panels" \
    "$(sql "$WORK/paper.db" "SELECT quote(measured) FROM runs")" "''"
same "paper space: the Pareto options' moulds counted, all the same" \
    "$(sql "$WORK/paper.db" "SELECT count(*) = (SELECT count(*) FROM options WHERE rank = 1) FROM options WHERE rank = 1 AND moulds = sp_moulds + dp_moulds AND moulds > 0 AND joint_length > 0 AND max_gap >= 0 AND sp_fitted >= 0")" 1
same "paper space: the other options' moulds, joints and fits not measured (NULL)" \
    "$(sql "$WORK/paper.db" "SELECT count(*) FROM options WHERE rank > 1 AND moulds IS NULL AND sp_moulds IS NULL AND joint_length IS NULL AND max_gap IS NULL AND gaps_over IS NULL AND sp_misfits IS NULL")" \
    "$(sql "$WORK/paper.db" "SELECT count(*) FROM options WHERE rank > 1")"

# --- classify: the terms, the totals CSV, the schedule's families --------
run "$FACET" classify "$ROOF" --grid 20x24 "${COSTS[@]}" --csv "$WORK/c.csv"
if [ "$STATUS" -eq 0 ]; then pass "classify with costs"; else fail "classify with costs"; fi
run "$FACET" classify "$ROOF" --grid 20x24 "${COSTS[@]}"
stdout_has "classify report: mould cost line" '^mould cost +SP [0-9]+ x 3000 \+ DP [0-9]+ x 20000 USD'
stdout_has "classify report: moulds line says upper bound" '^moulds .*at most'
check_sum() {
    /usr/bin/python3 - "$@" <<'PY'
import csv, sys
t = list(csv.DictReader(open(sys.argv[1])))[0]
p = list(csv.DictReader(open(sys.argv[2])))
f = lambda k: float(t[k])
area = f('fp_cost_usd') + f('sp_cost_usd') + f('dp_cost_usd')
want = area + 250 * int(t['panels']) + 40 * f('joint_length_m') + \
       3000 * int(t['sp_moulds']) + 20000 * int(t['dp_moulds'])
assert abs(f('cost_usd') - want) <= 1e-9 * want, (f('cost_usd'), want)
assert int(t['moulds']) == int(t['sp_moulds']) + int(t['dp_moulds'])
fam = {ty: {r['mould_family'] for r in p if r['type'] == ty} for ty in ('FP', 'SP', 'DP')}
assert fam['FP'] == {''} or not fam['FP'], fam['FP']
assert '' not in fam['SP'] and '' not in fam['DP']
assert len(fam['SP']) == int(t['sp_moulds']), (len(fam['SP']), t['sp_moulds'])
assert len(fam['DP']) == int(t['dp_moulds'])
assert not (fam['SP'] & fam['DP'])
sizes = {}
for r in p:
    if r['mould_family']:
        sizes[r['mould_family']] = sizes.get(r['mould_family'], 0) + 1
assert max(sizes.values()) == int(t['largest_family'])
assert sum(1 for v in sizes.values() if v == 1) == int(t['single_moulds'])
PY
}
if check_sum "$WORK/c-totals.csv" "$WORK/c.csv" 2>"$ERR"; then
    pass "classify CSV: cost is the sum of its terms, families match the counts"
else
    fail "classify CSV: cost is the sum of its terms, families match the counts"
fi
expect_error "--mould-cost needs SP,DP" '^facet: --mould-cost: .*SP,DP' \
    "$FACET" classify "$ROOF" --grid 20x24 --mould-cost 5
expect_error "--joint-cost refuses a negative" '^facet: --joint-cost: -1 is out of range' \
    "$FACET" classify "$ROOF" --grid 20x24 --joint-cost -1
expect_error "--mould-tol refuses a negative" '^facet: --mould-tol: -1 is out of range' \
    "$FACET" classify "$ROOF" --grid 20x24 --mould-tol -1

# --- optimize: run settings, option columns, objectives, --where --------
DB=$WORK/cost.db
run "$FACET" optimize "$ROOF" --db "$DB" --u 14:17 --v 16:18 --threshold 2:4:1 \
    "${COSTS[@]}" --mould-tol 5 --mould-mirror --objectives cost,moulds --name costs
if [ "$STATUS" -eq 0 ]; then pass "optimize with costs"; else fail "optimize with costs"; fi
same "run settings stored" \
    "$(sql "$DB" "SELECT price_panel, price_joint, price_sp_mould, price_dp_mould, mould_tol_mm, mould_mirror, objectives FROM runs")" \
    "250.0|40.0|3000.0|20000.0|5.0|1|cost,moulds"
same "every option's cost is the sum of its terms (SQLite)" \
    "$(sql "$DB" "SELECT count(*) FROM options WHERE abs(fp_cost + sp_cost + dp_cost + panel_cost + joint_cost + mould_cost - cost) <= 1e-9 * cost AND panel_cost = 250 * panels AND abs(joint_cost - 40 * joint_length) <= 1e-9 * joint_cost AND mould_cost = 3000 * sp_moulds + 20000 * dp_moulds")" \
    "$(sql "$DB" "SELECT count(*) FROM options")"
# The front by cost and moulds, brute force in SQL: the options no other
# is better than in both (all are feasible: checked first).
same "every option of the space is feasible" \
    "$(sql "$DB" "SELECT count(*) FROM options WHERE feasible")" 36
same "the front is the non-dominated set of cost and moulds" \
    "$(sql "$DB" "SELECT group_concat(number) FROM (SELECT number FROM options a WHERE feasible AND NOT EXISTS (SELECT 1 FROM options b WHERE b.feasible AND b.cost <= a.cost AND b.moulds <= a.moulds AND (b.cost < a.cost OR b.moulds < a.moulds)) ORDER BY number)")" \
    "$(sql "$DB" "SELECT group_concat(number) FROM (SELECT number FROM options WHERE rank = 1 ORDER BY number)")"
run "$FACET" options "$DB" --where "moulds < 40" --csv
same "--where moulds" "$(($(wc -l <"$OUT") - 1))" "$(sql "$DB" "SELECT count(*) FROM options WHERE moulds < 40")"
knee=$(sql "$DB" "SELECT knee FROM runs")
run "$FACET" show "$DB" --run 1 --option "$knee"
stdout_has "show: the mould cost" '^mould cost +SP [0-9]+ x 3000 \+ DP [0-9]+ x 20000 USD'
stdout_has "show: the joint cost" '^joint cost +[0-9.,]+ m x 40 USD/m'
same "show: the total is the option's cost" \
    "$(grep '^total cost' "$OUT" | awk '{gsub(",", "", $3); print $3}')" \
    "$(sql "$DB" "SELECT printf('%.2f', cost) FROM options WHERE number = $knee")"

# --- export: OBJ groups mould_K, CSV column --------------------------------
run "$FACET" export "$DB" --run 1 --option "$knee" --obj "$WORK/k.obj" --csv "$WORK/k.csv"
if [ "$STATUS" -eq 0 ]; then pass "export with families"; else fail "export with families"; fi
same "OBJ: one mould_K group per family" \
    "$(grep -oE '^g panel_[0-9]+_[0-9]+ mould_[0-9]+' "$WORK/k.obj" | awk '{print $3}' | sort -u | wc -l)" \
    "$(sql "$DB" "SELECT moulds FROM options WHERE number = $knee")"
same "OBJ: every SP and DP panel in a mould group, no FP panel" \
    "$(grep -cE '^g panel_[0-9]+_[0-9]+ mould_' "$WORK/k.obj")" \
    "$(sql "$DB" "SELECT sp_count + dp_count FROM options WHERE number = $knee")"
same "stored panels: family ids as the export's" \
    "$(sql "$DB" "SELECT count(DISTINCT mould_family) FROM panels WHERE option = $knee")" \
    "$(python3 -c 'import csv,sys; print(len({r["mould_family"] for r in csv.DictReader(open(sys.argv[1])) if r["mould_family"]}))' "$WORK/k.csv")"
