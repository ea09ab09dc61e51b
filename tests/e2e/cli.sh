#!/usr/bin/env bash
# End-to-end: the facet command's help, examples, info and its errors, run
# as a user would run them.
# layers: cli
. "$(dirname "$0")/lib.sh"

# Help, from the one command table.
expect "facet --help exits 0" 0 "$FACET" --help
stdout_has "--help lists info" '^  info '
stdout_has "--help lists example" '^  example '
expect "facet help info exits 0" 0 "$FACET" help info
stdout_has "help info shows usage" '^usage: facet info SURFACE.obj'
expect "facet info --help exits 0" 0 "$FACET" info --help
stdout_has "info --help shows options" '--units m[|]cm[|]mm[|]in[|]ft'
expect_error "no command is bad usage" 'usage: facet COMMAND|unknown' "$FACET" frobnicate
expect_error "unknown option" "unknown option '--frob'" "$FACET" info --frob x.obj
expect_error "help for unknown command" "unknown command 'nope'" "$FACET" help nope

# Every example writes, loads back, and is one surface with UV.
for name in plane cylinder dome hypar torus wave roof; do
    expect "example $name writes" 0 "$FACET" example "$name" -o "$WORK/$name.obj"
    expect "info $name --json" 0 "$FACET" info "$WORK/$name.obj" --json
    json_check "$name has valid UV, one component, one loop" \
        'j["has_uv"] and j["uv_valid"] and j["components"]==1 and j["boundary_loops"]==1'
done
run "$FACET" info "$WORK/roof.obj" --json
json_check "roof is about 1,240 m^2" 'abs(j["area"]-1240)/1240 < 0.01'
json_check "info --json has the documented keys" \
    'all(k in j for k in ["vertices","texcoords","normals","faces","triangles","has_uv","bbox","area","components","boundary_loops","objects"])'
json_check "bbox is [[min],[max]]" 'len(j["bbox"])==2 and all(len(b)==3 for b in j["bbox"]) and all(j["bbox"][0][k] <= j["bbox"][1][k] for k in range(3))'
expect "info roof (human)" 0 "$FACET" info "$WORK/roof.obj"
stdout_has "human info shows area in m^2" '^area +1[0-9]{3}\.[0-9]{3} m\^2'
stdout_has "human info shows UV valid" '^UV +valid'

expect "example --res" 0 "$FACET" example plane --res 4 -o "$WORK/p4.obj"
run "$FACET" info "$WORK/p4.obj" --json
json_check "--res 4 gives 25 vertices" 'j["vertices"]==25'
expect_error "example refuses to overwrite" 'exists.*--force' "$FACET" example plane -o "$WORK/p4.obj"
expect "example --force overwrites" 0 "$FACET" example plane --res 2 --force -o "$WORK/p4.obj"
expect_error "unknown example" "unknown example 'blob'" "$FACET" example blob
expect_error "example --res 0" 'res' "$FACET" example plane --res 0
expect_error "example to an unwritable path" 'cannot write' "$FACET" example plane -o /nonexistent/dir/x.obj

# Units: converted once at load, and a warning when they look wrong.
run "$FACET" info "$WORK/p4.obj" --json --units mm
json_check "--units mm scales area by 1e-6" 'abs(j["area"]-300e-6) < 1e-9'
json_check "a 20 mm facade is warned about" 'any("metres" in w or "units" in w for w in j["warnings"])'
expect_error "bad units" "units 'furlong'" "$FACET" info "$WORK/p4.obj" --units furlong

# Bad input: one line naming the problem, status 2, never a crash.
expect_error "missing file" 'nothere.obj' "$FACET" info "$WORK/nothere.obj"
expect_error "a directory" "$WORK" "$FACET" info "$WORK"
: >"$WORK/empty.obj"
expect_error "empty file" 'empty.obj.*empty' "$FACET" info "$WORK/empty.obj"
head -c 4096 /dev/urandom >"$WORK/binary.obj"
expect_error "binary file" 'binary.obj.*binary' "$FACET" info "$WORK/binary.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n' >"$WORK/range.obj"
expect_error "index out of range names the line" 'range.obj:4' "$FACET" info "$WORK/range.obj"
printf 'v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n' >"$WORK/nan.obj"
expect_error "NaN coordinate names the line" 'nan.obj:2' "$FACET" info "$WORK/nan.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 0 3\n' >"$WORK/zero.obj"
expect_error "zero index" 'zero.obj:4' "$FACET" info "$WORK/zero.obj"
printf 'v 0 0 0\nv 1 0 0\nf 1 2\n' >"$WORK/short.obj"
expect_error "face of two vertices" 'short.obj:3' "$FACET" info "$WORK/short.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n' >"$WORK/before.obj"
expect_error "relative index before the first vertex" 'before.obj:4' "$FACET" info "$WORK/before.obj"
expect_error "info with no file" 'name one OBJ file' "$FACET" info

# Several surfaces in one file: said, and listed.
printf 'o left\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\no right\nv 5 0 0\nv 6 0 0\nv 5 1 0\nf 4 5 6\n' >"$WORK/two.obj"
expect "info on two objects" 0 "$FACET" info "$WORK/two.obj"
stdout_has "two surfaces are listed" '^left .*two\.obj'
stdout_has "two surfaces are listed (2)" '^right .*two\.obj'
run "$FACET" info "$WORK/two.obj" --object right --json
json_check "--object selects one" 'j["components"]==1 and j["triangles"]==1'
expect_error "unknown object is named" "nope" "$FACET" info "$WORK/two.obj" --object nope

# Did you mean: commands and flags suggest the nearest known word.
expect_error "did you mean a command" "unknown command 'optimise' \\(did you mean 'facet optimize'\\?\\)" "$FACET" optimise
expect_error "did you mean a flag" "unknown option '--sortt' \\(did you mean --sort\\?\\)" "$FACET" options x.db --sortt cost
expect_error "did you mean a swapped flag" "did you mean --grid\\?" "$FACET" classify x.obj --gird 3x3
expect_error "nothing near: the help" "unknown command 'zzz' \\(see 'facet --help'\\)" "$FACET" zzz
expect_error "nothing near a flag: the help" "unknown option '--zzzzzz' \\(see 'facet runs --help'\\)" "$FACET" runs x.db --zzzzzz

# Issue 32 item 16: every help fits 80 columns (facet --help ran to 122),
# and export's help says where the CSV's totals go, where a run of export
# puts them.
for cmd in "" $("$FACET" --help | awk '/^commands:/ { on = 1; next } on && /^  [a-z]/ { print $1 }'); do
    run "$FACET" $cmd --help
    widest=$(awk '{ if (length($0) > w) w = length($0) } END { print w + 0 }' "$OUT")
    if [ "$STATUS" -eq 0 ] && [ "$widest" -le 80 ]; then
        pass "facet ${cmd:+$cmd }--help fits 80 columns ($widest)"
    else
        fail "facet ${cmd:+$cmd }--help fits 80 columns ($widest, status $STATUS)"
    fi
done
run "$FACET" export --help
stdout_has "export --help: the CSV's totals in FILE-totals.csv" 'FILE-totals\.csv beside it'

# Width: the human tables fit an 80-column terminal (COLUMNS, as a terminal
# would say), and --wide prints every column.
"$FACET" example roof --res 30 -o "$WORK/wroof.obj" || exit 1
run env COLUMNS=80 "$FACET" optimize "$WORK/wroof.obj" --db "$WORK/w.db" --u 4:9 --v 4:9 --threshold 3 --name "a rather long run name for the width check"
widest=$(awk '{ if (length($0) > w) w = length($0) } END { print w + 0 }' "$OUT")
if [ "$widest" -le 80 ]; then pass "optimize's table fits 80 columns ($widest)"; else fail "optimize's table fits 80 columns ($widest)"; fi
for cmd in runs options; do
    run env COLUMNS=80 "$FACET" "$cmd" "$WORK/w.db"
    widest=$(awk '{ if (length($0) > w) w = length($0) } END { print w + 0 }' "$OUT")
    if [ "$widest" -le 80 ]; then pass "$cmd fits 80 columns ($widest)"; else fail "$cmd fits 80 columns ($widest)"; fi
    stdout_has "$cmd says what it left out" 'left out to fit the terminal; --wide shows every column'
    run env COLUMNS=80 "$FACET" "$cmd" "$WORK/w.db" --wide
    if grep -q 'left out' "$OUT"; then fail "$cmd --wide leaves nothing out"; else pass "$cmd --wide leaves nothing out"; fi
done
run env COLUMNS=80 "$FACET" options "$WORK/w.db" --wide
stdout_has "options --wide has the FP and SP areas" 'FP area +SP area'
run env COLUMNS=80 "$FACET" runs "$WORK/w.db"
stdout_has "runs cuts a long name with ..." '\.\.\.$'
run "$FACET" options "$WORK/w.db"
stdout_has "no terminal, no COLUMNS: every column" 'FP area +SP area'
expect "--help gives examples" 0 "$FACET" options --help
stdout_has "options --help: an example" '^  facet options runs.db --run 1 --pareto --sort cost$'

# Real files from public projects all load.
if have_data acj_spot.obj compas_hypar.obj; then
    for file in "$FACET_DATA"/*.obj; do
        expect "info $(basename "$file")" 0 "$FACET" info "$file" --json
    done
    run "$FACET" info "$FACET_DATA/acj_spot.obj" --json
    json_check "spot: counts as tinyobjloader reads them" 'j["vertices"]==2930 and j["texcoords"]==3225 and j["triangles"]==5856'
    json_check "spot: closed, so no boundary loop" 'j["boundary_loops"]==0 and j["components"]==1'
    run "$FACET" info "$FACET_DATA/compas_hypar.obj" --json
    json_check "hypar: no UV, one loop" 'not j["has_uv"] and j["boundary_loops"]==1'
fi

# The defaults the help states are the ones a run takes: each run below
# gives no flag but --method, and SQLite's own runs row is read against
# the numbers parsed out of `facet optimize --help`.
# A coarse plane: the runs are read for the defaults they record, and 10 x
# 10 quads take a tenth of the time of the example's own 20k vertices.
"$FACET" example plane --res 10 -o "$WORK/defaults.obj" >/dev/null 2>&1
for method in auto random nsga2; do
    run "$FACET" optimize "$WORK/defaults.obj" --db "$WORK/defaults.db" \
        --method "$method" --table 0
    [ "$STATUS" -eq 0 ] || fail "optimize with the defaults, --method $method"
done
"$FACET" optimize --help >"$WORK/help.txt" 2>&1
sqlite3 -batch -json "$WORK/defaults.db" "SELECT units, method, seed, u_min,
    u_max, v_min, v_max, threshold_min_mm, threshold_max_mm, price_fp,
    price_sp, price_dp, max_panel_area_limit, per_panel, objectives,
    store_panels, evaluations, population, generations, curvature_tol
    FROM runs ORDER BY id" >"$WORK/runs.json"
if /usr/bin/python3 - "$WORK/help.txt" "$WORK/runs.json" >"$WORK/defaults.out" 2>&1 <<'PY'
import json, re, sys
help = " ".join(open(sys.argv[1]).read().split())
auto, random, nsga2 = json.load(open(sys.argv[2]))
def said(pattern):
    m = re.search(pattern, help)
    if not m:
        sys.exit("the help lacks " + pattern)
    return m.groups()
u = said(r"--u A:B panels along u \(default (\d+):(\d+)")
v = said(r"--v A:B panels along v \(default (\d+):(\d+)")
t, = said(r"--threshold T flatness threshold in mm: one value, a range A:B, or A:B:STEP for exhaustive \(default ([\d.]+)\)")
limit, = said(r"--method auto\|exhaustive\|random\|nsga2 auto, exhaustive, random or nsga2 \(default auto: exhaustive up to ([\d,]+) points")
evals, = said(r"--evals N random: points to draw \(default (\d+)\)")
pop, = said(r"--pop N nsga2: population \(default (\d+)\)")
gens, = said(r"--gens N nsga2: generations \(default (\d+)\)")
seed, = said(r"the same seed gives the same options \(default (\d+)\)")
objectives, = said(r"max:NAME to maximise \(default ([a-z_:,]+)\)")
keep, = said(r"--store-panels front\|knee\|none .*?\(default (\w+)\)")
units, = said(r"--units m\|cm\|mm\|in\|ft what one OBJ unit is: m, cm, mm, in, ft \(default (\w+)\)")
tol = said(r"counts as zero \(default (8 t / d\^2)")
mode, = said(r"shape operator \(default (\w+)\)")
prices = said(r"USD/m\^2 \(default ([\d.]+),([\d.]+),([\d.]+)\)")
area, = said(r"feasibility limit \(default ([\d.]+)\)")
space = (int(u[1]) - int(u[0]) + 1) * (int(v[1]) - int(v[0]) + 1)
want = {
    "units": units, "seed": int(seed), "u_min": int(u[0]),
    "u_max": int(u[1]), "v_min": int(v[0]), "v_max": int(v[1]),
    "threshold_min_mm": float(t), "threshold_max_mm": float(t),
    "price_fp": float(prices[0]), "price_sp": float(prices[1]),
    "price_dp": float(prices[2]), "max_panel_area_limit": float(area),
    "per_panel": mode, "objectives": objectives, "store_panels": keep,
    "curvature_tol": None,
}
bad = []
for name, row in (("auto", auto), ("random", random), ("nsga2", nsga2)):
    for key, value in want.items():
        if row[key] != value:
            bad.append("%s: %s is %r, the help says %r" % (name, key, row[key], value))
# auto: exhaustive up to the limit with one threshold (the space is smaller)
if space <= int(limit.replace(",", "")) and auto["method"] != "exhaustive":
    bad.append("auto took %s for %d points" % (auto["method"], space))
if random["evaluations"] != int(evals):
    bad.append("random drew %r, the help says %s" % (random["evaluations"], evals))
if (nsga2["population"], nsga2["generations"]) != (int(pop), int(gens)):
    bad.append("nsga2 ran %r x %r, the help says %s x %s" % (nsga2["population"], nsga2["generations"], pop, gens))
if bad:
    sys.exit("\n".join(bad))
PY
then
    pass "optimize --help states the defaults a run records"
else
    echo "not ok - optimize --help states the defaults a run records"
    sed 's/^/  /' "$WORK/defaults.out"
fi

# classify --help's threshold is the one a classification takes.
run "$FACET" classify --help
t=$(tr -s ' \n' ' ' <"$OUT" | grep -oE 'best-fit plane is made flat \(default [0-9.]+\)' | grep -oE '[0-9.]+')
run "$FACET" classify "$WORK/defaults.obj" --grid 4x4 --json
json_check "classify --help states the threshold it takes ($t mm)" \
    "abs(j['threshold_mm'] - float('${t:-nan}')) < 1e-12"
exit 0
