#!/usr/bin/env bash
# End-to-end: facet classify on generated and real surfaces, its JSON, its
# CSV schedule, its map, and its errors.
# layers: core cli
. "$(dirname "$0")/lib.sh"

fixture roof.obj || exit 1
"$FACET" example hypar --res 40 -o "$WORK/hypar.obj" || exit 1
"$FACET" example plane --res 8 -o "$WORK/plane.obj" || exit 1

expect "classify roof at the paper's grid" 0 "$FACET" classify "$WORK/roof.obj" --grid 37x49
stdout_has "totals table" '^total +1,813 '
stdout_has "classes table" '^convex_round '
stdout_has "panel map (plain letters, not a terminal)" '^  [FSD.]{37}$'
run "$FACET" classify "$WORK/roof.obj" --grid 37x49
if grep -q $'\033' "$OUT"; then fail "no colour codes when stdout is not a terminal"; else pass "no colour codes when stdout is not a terminal"; fi

expect "classify --json" 0 "$FACET" classify "$WORK/roof.obj" --grid 37x49 --json
json_check "json: documented top-level keys" \
    'all(k in j for k in ["surface","grid","threshold_mm","curvature_tol","panels","totals"])'
json_check "json: surface keys" 'all(k in j["surface"] for k in ["file","units","area","triangles"])'
json_check "json: grid" 'j["grid"]=={"nu":37,"nv":49}'
json_check "json: panel keys" \
    'all(all(k in p for k in ["i","j","class","type","area","deviation","k1","k2","K","H"]) for p in j["panels"])'
json_check "json: totals keys" \
    'all(k in j["totals"] for k in ["panels","fp_count","sp_count","dp_count","fp_area","sp_area","dp_area","area","cost","planarity","max_deviation","max_panel_area","feasible"])'
json_check "json: panel areas add up to the surface area" \
    'abs(sum(p["area"] for p in j["panels"]) - j["surface"]["area"]) < 1e-9*j["surface"]["area"]'
json_check "json: cost = sum of area x price, as a spreadsheet computes it" \
    'abs(sum(p["area"]*{"FP":701,"SP":766,"DP":1518}[p["type"]] for p in j["panels"]) - j["totals"]["cost"]) < 1e-6*j["totals"]["cost"]'
json_check "json: planarity = sum of non-DP deviations" \
    'abs(sum(p["deviation"] for p in j["panels"] if p["type"]!="DP") - j["totals"]["planarity"]) < 1e-9'
json_check "json: K = k1 k2 and H = (k1+k2)/2" \
    'all(abs(p["K"]-p["k1"]*p["k2"]) <= 1e-9*max(1e-12,abs(p["K"])) and abs(p["H"]-(p["k1"]+p["k2"])/2) <= 1e-12+1e-9*abs(p["H"]) for p in j["panels"])'
json_check "json: threshold rule (deviation within 3 mm is FP)" \
    'all(p["type"]=="FP" for p in j["panels"] if p["deviation"] <= 0.003)'
json_check "json: roof has FP, SP and DP panels" \
    'j["totals"]["fp_count"]>0 and j["totals"]["sp_count"]>0 and j["totals"]["dp_count"]>0'
json_check "json: counts add up" \
    'j["totals"]["fp_count"]+j["totals"]["sp_count"]+j["totals"]["dp_count"]==j["totals"]["panels"]==len(j["panels"])'

expect "--sp-as-fp and --prices" 0 "$FACET" classify "$WORK/roof.obj" --grid 20x35 --json --prices 100,200,300 --sp-as-fp
json_check "prices applied, SP priced as FP" \
    'abs(j["totals"]["cost"] - (100*(j["totals"]["fp_area"]+j["totals"]["sp_area"]) + 300*j["totals"]["dp_area"])) < 1e-6*j["totals"]["cost"]'
expect "--threshold 1000 makes every panel flat" 0 "$FACET" classify "$WORK/roof.obj" --grid 10x10 --threshold 1000 --json
json_check "all FP" 'j["totals"]["fp_count"]==j["totals"]["panels"]'
expect "--max-panel-area" 0 "$FACET" classify "$WORK/roof.obj" --grid 5x5 --max-panel-area 1.92 --json
json_check "5x5 panels are too large" 'not j["totals"]["feasible"]'
expect "--per-panel mean" 0 "$FACET" classify "$WORK/roof.obj" --grid 20x35 --per-panel mean --json
json_check "mean mode reports k1 >= k2" 'all(p["k1"]>=p["k2"] for p in j["panels"])'
expect "--curvature-tol" 0 "$FACET" classify "$WORK/roof.obj" --grid 20x35 --curvature-tol 1000 --json
json_check "a huge tolerance makes every class flat" 'all(p["class"]=="flat" for p in j["panels"])'

expect "hypar 5x5" 0 "$FACET" classify "$WORK/hypar.obj" --grid 5x5 --json
json_check "hypar: only feature-curve areas (K < 0)" \
    'all(p["class"] in ("convex_feature_curve","concave_feature_curve","saddle") for p in j["panels"]) and {"convex_feature_curve","concave_feature_curve"} <= {p["class"] for p in j["panels"]}'
expect "--flip-normals" 0 "$FACET" classify "$WORK/hypar.obj" --grid 5x5 --json --flip-normals
json_check "flipping swaps convex and concave" \
    'all(p["class"] in ("convex_feature_curve","concave_feature_curve","saddle") for p in j["panels"])'

expect "--csv schedule" 0 "$FACET" classify "$WORK/plane.obj" --grid 4x3 --csv "$WORK/plane.csv"
if [ "$(wc -l <"$WORK/plane.csv")" -eq 13 ] && head -1 "$WORK/plane.csv" | grep -q '^id,i,j,class,type,area_m2,deviation_m,'; then
    pass "csv has a header and one row per panel"
else
    fail "csv has a header and one row per panel"
fi
/usr/bin/python3 - "$WORK/plane.csv" <<'PY' && pass "csv areas are 25 m^2 each" || fail "csv areas are 25 m^2 each"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
sys.exit(0 if all(abs(float(r["area_m2"]) - 25) < 1e-6 and r["type"] == "FP" for r in rows) else 1)
PY

# Real surfaces: no vt, so Facet makes its own UV.
if have_data compas_hypar.obj hemisphere.obj botanic-garden-bubble-0.obj igloo.obj; then
    expect "compas hypar (no vt: an 8x8 structured quad grid)" 0 "$FACET" classify "$FACET_DATA/compas_hypar.obj" --grid 5x5 --json
    json_check "compas hypar is all feature curves" \
        'all(p["class"] in ("convex_feature_curve","concave_feature_curve","saddle") for p in j["panels"]) and j["surface"]["uv"]=="grid"'
    expect "hemisphere (no vt)" 0 "$FACET" classify "$FACET_DATA/hemisphere.obj" --grid 10x10 --json
    json_check "hemisphere: trimmed panels add up to its area" \
        'abs(sum(p["area"] for p in j["panels"]) - j["surface"]["area"]) < 1e-9*j["surface"]["area"]'
    expect "bubble roof (no vt)" 0 "$FACET" classify "$FACET_DATA/botanic-garden-bubble-0.obj" --grid 20x20 --json
    expect "igloo (vt)" 0 "$FACET" classify "$FACET_DATA/igloo.obj" --grid 20x20 --json
fi

# A torus section without vt folds when projected: its triangles pair into
# a 60 x 60 quad grid, and asked for, the harmonic map applies too.
"$FACET" example torus --res 60 -o "$WORK/torus.obj" || exit 1
grep -v '^vt' "$WORK/torus.obj" | sed -E 's#/[0-9]+##g' >"$WORK/torus-novt.obj"
expect "torus without vt" 0 "$FACET" classify "$WORK/torus-novt.obj" --grid 10x12 --json
json_check "its triangles pair into a quad grid" 'j["surface"]["uv"]=="grid" and j["totals"]["panels"]==120'
expect "torus without vt, --uv harmonic" 0 "$FACET" classify "$WORK/torus-novt.obj" --grid 10x12 --uv harmonic --json
json_check "harmonic parameterization, every panel, areas add up" \
    'j["surface"]["uv"]=="harmonic" and j["totals"]["panels"]==120 and abs(j["totals"]["area"]-j["surface"]["area"]) < 1e-9*j["surface"]["area"]'
if have_data conical1.obj; then
    expect "conical roof (no vt)" 0 "$FACET" classify "$FACET_DATA/conical1.obj" --grid 10x10 --json
    json_check "conical roof takes its quad grid as UV" 'j["surface"]["uv"]=="grid" and j["totals"]["panels"] == 100'
fi

# A mesh coarser than its panels: a dome of R = 20 m meshed with 4 x 4
# quads (5 m facets) at 50 x 50 panels (0.4 m, so eps = 8 t / d^2 exceeds
# 1/R and every panel is flat by curvature) warns, and the panels across its
# fold lines deviate more than t; its count of them is the one the schedule
# shows. The same dome finely meshed does not warn.
"$FACET" example dome --res 4 -o "$WORK/dome4.obj" || exit 1
"$FACET" example dome --res 200 -o "$WORK/dome200.obj" || exit 1
expect "coarse mesh" 0 "$FACET" classify "$WORK/dome4.obj" --grid 50x50 --json
if [ "$(grep -c 'warning: the mesh is coarse for 50 x 50 panels' "$ERR")" -eq 1 ]; then
    pass "coarse mesh: one warning line on stderr"
else
    fail "coarse mesh: one warning line on stderr"
fi
json_check "coarse mesh: fp_over_threshold counts FP panels deviating more than t" \
    'j["totals"]["fp_over_threshold"] == sum(1 for p in j["panels"] if p["type"]=="FP" and p["deviation"] > 0.003*(1+1e-9)) > 0'
run "$FACET" classify "$WORK/dome4.obj" --grid 50x50
stdout_has "coarse mesh: classify says how many FP panels exceed t" '^FP beyond t +[1-9][0-9]* of [0-9]+ FP panels deviate more than 3 mm \(up to '
expect "fine mesh" 0 "$FACET" classify "$WORK/dome200.obj" --grid 50x50
if grep -q 'coarse' "$ERR"; then fail "fine mesh: no coarse warning"; else pass "fine mesh: no coarse warning"; fi
stdout_has "fine mesh: no FP panel beyond t" '^FP beyond t +0 of '
if have_data compas_hypar.obj; then
    expect "compas hypar at 20x35 (8 x 8 quads)" 0 "$FACET" classify "$FACET_DATA/compas_hypar.obj" --grid 20x35
    if grep -q 'warning: the mesh is coarse for 20 x 35 panels' "$ERR"; then
        pass "compas hypar at 20x35: the mesh is coarse"
    else
        fail "compas hypar at 20x35: the mesh is coarse"
    fi
fi

# Bad input.
expect_error "unknown units" "units 'yard'" "$FACET" classify "$WORK/roof.obj" --grid 5x5 --units yard
expect_error "no grid" 'grid' "$FACET" classify "$WORK/roof.obj"
# A grid is a pair as --module's is: X for x, blanks around it.
expect "grid 4X3" 0 "$FACET" classify "$WORK/roof.obj" --grid 4X3 --json
json_check "grid 4X3 is 4 x 3" 'j["grid"]["nu"] == 4 and j["grid"]["nv"] == 3'
expect "grid ' 4 x 3 '" 0 "$FACET" classify "$WORK/roof.obj" --grid " 4 x 3 " --json
json_check "grid ' 4 x 3 ' is 4 x 3" 'j["grid"]["nu"] == 4 and j["grid"]["nv"] == 3'
expect_error "malformed grid" "'37by49' is not NUxNV" "$FACET" classify "$WORK/roof.obj" --grid 37by49
expect_error "absurd grid" 'out of range' "$FACET" classify "$WORK/roof.obj" --grid 100000x5
expect_error "zero grid" 'out of range' "$FACET" classify "$WORK/roof.obj" --grid 0x5
expect_error "NaN threshold" 'threshold' "$FACET" classify "$WORK/roof.obj" --grid 5x5 --threshold nan
expect_error "negative threshold" 'threshold' "$FACET" classify "$WORK/roof.obj" --grid 5x5 --threshold -1
expect_error "bad prices" 'prices' "$FACET" classify "$WORK/roof.obj" --grid 5x5 --prices 1,2
expect_error "bad per-panel" 'per-panel' "$FACET" classify "$WORK/roof.obj" --grid 5x5 --per-panel median
if have_data acj_suzanne.obj; then
    expect_error "closed mesh is refused" 'acj_suzanne.obj' "$FACET" classify "$FACET_DATA/acj_suzanne.obj" --grid 5x5
fi
expect_error "missing file" 'nothere' "$FACET" classify "$WORK/nothere.obj" --grid 5x5
expect_error "unwritable csv" 'cannot write' "$FACET" classify "$WORK/plane.obj" --grid 2x2 --csv /nonexistent/x.csv
# Issue 32 item 8: a fine grid works for most of a minute, so classify
# shows its steps on a terminal (a pty here): read, prepare, then the
# option's five stages, each as it starts, and the time taken at the end;
# in a log (stderr not a terminal) nothing but its warnings.
got=$(python3 - "$FACET" "$WORK/roof.obj" <<'EOF2'
import os, pty, select, sys
pid, fd = pty.fork()
if pid == 0:
    os.execv(sys.argv[1], [sys.argv[1], 'classify', sys.argv[2], '--grid', '200x200'])
seen = b''
while True:
    try:
        if select.select([fd], [], [], 0.1)[0]:
            chunk = os.read(fd, 65536)
            if not chunk:
                break
            seen += chunk
    except OSError:
        break
os.waitpid(pid, 0)
for part in seen.replace(b'\n', b'\r').split(b'\r'):
    if part.startswith(b'[') and b'] ' in part[:40]:
        print(part.decode().split('] ', 1)[1].split(',')[0].strip())
EOF2
)
same "classify on a terminal: its steps in order, then the time taken" \
    "$(echo "$got" | sed 's/took [0-9.]* s/took N s/' | tr '\n' '|')" \
    "0/7 reading the surface|1/7 preparing the surface|2/7 building the panels|3/7 measuring the panels' widths|4/7 measuring the joint lines|5/7 fitting panels|6/7 finding the mould families|7/7 took N s|"
run "$FACET" classify "$WORK/roof.obj" --grid 200x200
if grep -q '^\[\|/7 ' "$ERR"; then
    fail "classify in a log: no steps drawn"
else
    pass "classify in a log: no steps drawn"
fi
exit 0
