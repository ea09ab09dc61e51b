#!/usr/bin/env bash
# End-to-end: the UV a surface takes (vt, structured grid, plane, harmonic
# with holes capped), --uv forcing one and refusing what cannot apply, a
# texture atlas refused, and --uv kept with a run for --resume.
# layers: core store cli
. "$(dirname "$0")/lib.sh"
sql() { sqlite3 -batch "$1" "$2"; }

# A 240-degree vault with a round oculus and a rectangular opening, as
# quads without vt: it folds when projected, so it needs the harmonic map
# of its capped disk. Its area, cell by cell, is printed to $WORK/holed.area.
/usr/bin/python3 - "$WORK/holed.obj" "$WORK/holed.area" <<'PY'
import math, sys
nt, nz, r, sweep, length = 48, 24, 5.0, math.radians(240), 12.0
def cut(a, b):
    s = r * sweep * (a + 0.5) / nt
    z = length * (b + 0.5) / nz
    ds, dz = s - r * sweep * 0.3, z - 6
    return ds * ds + dz * dz < 4 or (30 <= a < 38 and 14 <= b < 20)
with open(sys.argv[1], "w") as out:
    for b in range(nz + 1):
        for a in range(nt + 1):
            t = sweep * a / nt
            out.write("v %.17g %.17g %.17g\n" % (r * math.cos(t), length * b / nz, r * math.sin(t)))
    kept = 0
    for b in range(nz):
        for a in range(nt):
            if cut(a, b):
                continue
            v = b * (nt + 1) + a + 1
            out.write("f %d %d %d %d\n" % (v, v + nt + 1, v + nt + 2, v + 1))
            kept += 1
chord = 2 * r * math.sin(sweep / nt / 2)
open(sys.argv[2], "w").write("%.17g\n" % (kept * chord * length / nz))
PY
area=$(cat "$WORK/holed.area")
expect "holed vault: info" 0 "$FACET" info "$WORK/holed.obj"
stdout_has "info says harmonic, holes capped, and why" '^UV map +harmonic \(.*plane projection folds.*2 holes capped\)'
expect "holed vault: classify" 0 "$FACET" classify "$WORK/holed.obj" --grid 12x10 --json
json_check "harmonic map; panels add up to the vault's area" \
    "j['surface']['uv']=='harmonic' and abs(sum(p['area'] for p in j['panels']) - $area) < 1e-9*$area"
expect_error "--uv plane on the holed vault: folds" 'plane projection folds' \
    "$FACET" classify "$WORK/holed.obj" --grid 4x4 --uv plane

# Bad --uv values, on a generated surface.
"$FACET" example roof --res 12 -o "$WORK/roof.obj" || exit 1
expect_error "--uv unknown" "uv: 'bogus' is not vt, grid, plane, harmonic" \
    "$FACET" classify "$WORK/roof.obj" --grid 4x4 --uv bogus
expect_error "info --uv unknown" "uv: 'bogus'" "$FACET" info "$WORK/roof.obj" --uv bogus
expect "--uv plane on a surface with vt" 0 "$FACET" classify "$WORK/roof.obj" --grid 4x4 --uv plane --json
json_check "plane taken" 'j["surface"]["uv"]=="plane"'
grep -v '^vt' "$WORK/roof.obj" | sed -E 's#/[0-9]+##g' >"$WORK/roof-novt.obj"
expect_error "--uv vt without vt" 'no texture coordinates' \
    "$FACET" classify "$WORK/roof-novt.obj" --grid 4x4 --uv vt

# Two charts: two squares whose vt jump apart across their shared edge.
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nvt 0 0\nvt 0.5 0\nvt 1 0\nvt 0 1\nvt 0.5 1\nvt 1 1\nvt 0.6 0\nvt 0.6 1\nf 1/1 2/2 5/5\nf 1/1 5/5 4/4\nf 2/7 3/3 6/6\nf 2/7 6/6 5/8\n' >"$WORK/charts.obj"
expect_error "two UV charts are refused" '2 separate UV charts.*--object' \
    "$FACET" classify "$WORK/charts.obj" --grid 2x2
expect "--uv harmonic re-parameterizes them" 0 "$FACET" classify "$WORK/charts.obj" --grid 2x1 --uv harmonic --json
json_check "harmonic, the plate's area" 'j["surface"]["uv"]=="harmonic" and abs(j["totals"]["area"]-2) < 1e-9'

# The real files.
# (have_data prints the skip line run.py counts: a skip said as a comment
# was counted as nothing.)
have_data conical1.obj barrel.obj fish.obj hemisphere.obj || exit 0
expect "info conical1" 0 "$FACET" info "$FACET_DATA/conical1.obj"
stdout_has "conical1 is a 30 x 36 grid" '^UV map +grid \(30 x 36 quads, structured\)'
run "$FACET" info "$FACET_DATA/conical1.obj" --json
json_check "info --json: uv_method, uv_reason" 'j["uv_method"]=="grid" and "30 x 36" in j["uv_reason"]'
for case in "conical1 30x36" "barrel 20x20"; do
    set -- $case
    expect "$1 at $2" 0 "$FACET" classify "$FACET_DATA/$1.obj" --grid "$2" --json
    json_check "$1 at $2: grid UV, one panel per quad, >= 95 % FP area" \
        'j["surface"]["uv"]=="grid" and j["totals"]["panels"]==j["surface"]["triangles"]//2 and j["totals"]["fp_area"] >= 0.95*j["totals"]["area"]'
done
expect "--uv harmonic on conical1" 0 "$FACET" classify "$FACET_DATA/conical1.obj" --grid 30x36 --uv harmonic --json
json_check "the harmonic map, asked for (what was taken before grids)" 'j["surface"]["uv"]=="harmonic" and j["totals"]["fp_area"] < 0.5*j["totals"]["area"]'
expect "--uv plane on barrel" 0 "$FACET" classify "$FACET_DATA/barrel.obj" --grid 20x20 --uv plane --json
json_check "the plane projection, asked for" 'j["surface"]["uv"]=="plane" and j["totals"]["fp_area"] < 0.5*j["totals"]["area"]'
expect_error "--uv plane on conical1: folds" 'conical1.obj: the plane projection folds' \
    "$FACET" classify "$FACET_DATA/conical1.obj" --grid 4x4 --uv plane
expect_error "--uv grid on a triangle mesh" 'not a structured quad grid: not a quad mesh' \
    "$FACET" classify "$FACET_DATA/hemisphere.obj" --grid 4x4 --uv grid
expect_error "info --uv grid on a triangle mesh" 'not a structured quad grid' \
    "$FACET" info "$FACET_DATA/hemisphere.obj" --uv grid
expect_error "--uv vt on conical1" 'no texture coordinates' \
    "$FACET" classify "$FACET_DATA/conical1.obj" --grid 4x4 --uv vt
expect_error "--uv harmonic on a closed mesh" 'no harmonic map' \
    "$FACET" classify "$FACET_DATA/fish.obj" --grid 4x4 --uv harmonic
expect_error "fish's five charts are refused" 'fish.obj: the texture coordinates form 5 separate UV charts' \
    "$FACET" classify "$FACET_DATA/fish.obj" --grid 6x6
expect "info fish still describes it" 0 "$FACET" info "$FACET_DATA/fish.obj" --json
json_check "no UV map, and why" 'j["uv_method"] is None and "5 separate UV charts" in j["uv_reason"]'
expect_error "optimize --uv grid on a triangle mesh" 'not a structured quad grid' \
    "$FACET" optimize "$FACET_DATA/hemisphere.obj" --db "$WORK/bad.db" --u 3:3 --v 3:3 --uv grid

# --uv is a run's setting: stored, and what --resume takes.
db=$WORK/uv.db
# Typed by class alone: as built, every SP panel of these coarse grids of
# the barrel is a misfit whatever the UV, and both runs are all DP.
expect "optimize barrel --uv plane" 0 "$FACET" optimize "$FACET_DATA/barrel.obj" --db "$db" --u 5:6 --v 5:6 --uv plane --sp-fit no
expect "optimize barrel automatic" 0 "$FACET" optimize "$FACET_DATA/barrel.obj" --db "$db" --u 5:6 --v 5:6 --sp-fit no
same "runs.uv and uv_method" "$(sql "$db" "SELECT id, coalesce(uv, 'NULL'), uv_method FROM runs ORDER BY id")" \
    "$(printf '1|plane|plane\n2|NULL|grid')"
before=$(sql "$db" "SELECT number, cost, planarity FROM options WHERE run = 1 ORDER BY number")
sql "$db" "DELETE FROM panels WHERE run = 1; DELETE FROM panel_sets WHERE run = 1;
           DELETE FROM options WHERE run = 1 AND number > 1;
           UPDATE runs SET status = 'interrupted' WHERE id = 1"
expect "resume the plane run" 0 "$FACET" optimize --db "$db" --resume 1
same "resumed on the plane projection: the same options" \
    "$(sql "$db" "SELECT number, cost, planarity FROM options WHERE run = 1 ORDER BY number")" "$before"
if [ "$before" != "$(sql "$db" "SELECT number, cost, planarity FROM options WHERE run = 2 ORDER BY number")" ]; then
    pass "the grid run's options differ (the UV matters)"
else
    fail "the grid run's options differ (the UV matters)"
fi

# A version-3 file (no runs.uv) is migrated to the current version by
# facet migrate.
# (tools/store_v4 takes it back to version 4 first, as a Facet before the
# cost model left it.)
current=$(sql "$db" 'PRAGMA user_version')  # the schema this Facet writes
"$(dirname "$FACET")/tools/store_v4" "$db" || fail "store_v4 took the file back to version 4"
sql "$db" "ALTER TABLE runs DROP COLUMN uv; ALTER TABLE runs DROP COLUMN warnings; ALTER TABLE runs DROP COLUMN store_panels; PRAGMA user_version = 3;"
expect "facet migrate on a v3 file" 0 "$FACET" migrate "$db"
expect "facet runs on the migrated file" 0 "$FACET" runs "$db"
same "migrated: version $current, runs.uv back, NULL, runs.warnings empty" \
    "$(sql "$db" "SELECT (SELECT user_version FROM pragma_user_version), (SELECT count(*) FROM runs WHERE uv IS NULL), (SELECT count(*) FROM runs WHERE warnings = '')")" "$current|2|2"
exit 0
