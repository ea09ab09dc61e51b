#!/usr/bin/env bash
# End-to-end: facets that sag a fair part of t. A strip whose vertices lie
# on a cylinder of R = 7.567 m, each facet's chord sagging 4.1 mm from it:
# classify, optimize and a project run warn of the sag (and store it with
# the run), and its ruled panels are built on cylinders, none DP, at t = 3
# mm (measured on the facets they were all misfits). A 180-face skin at
# --res 12, whose facets are larger than its panels, stores both warnings.
# layers: core study cli
. "$(dirname "$0")/lib.sh"
sql() { sqlite3 -batch "$1" "$2"; }

/usr/bin/python3 - "$WORK/strip.obj" <<'PY'
import math, sys
r, sag, around, along, length = 7.567, 0.0041, 40, 60, 35.0
step = 2 * math.acos(1 - sag / r)
with open(sys.argv[1], "w") as out:
    for j in range(along + 1):
        for i in range(around + 1):
            t = i * step
            out.write("v %.17g %.17g %.17g\nvt %.17g %.17g\n" % (
                r * math.sin(t), length * j / along, r * math.cos(t), i / around, j / along))
    for j in range(along):
        for i in range(around):
            a = j * (around + 1) + i + 1
            b, c, d = a + 1, a + around + 2, a + around + 1
            out.write("f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n" % (a, a, b, b, c, c, a, a, c, c, d, d))
PY

for grid in 6x6 20x35; do
    expect "strip: classify --grid $grid" 0 "$FACET" classify "$WORK/strip.obj" --grid "$grid" --json
    if grep -q 'warning: the facets sag 4.1 mm .*t = 3 mm' "$ERR"; then
        pass "strip $grid: classify warns of the 4.1 mm sag"
    else
        fail "strip $grid: classify warns of the 4.1 mm sag"
    fi
    json_check "strip $grid: every panel ruled (SP), none built DP" \
        'all(p["type"] == "SP" for p in j["panels"]) and all(p["built_type"] == "SP" for p in j["panels"]) and j["totals"]["sp_misfits"] == 0'
done

expect "strip: optimize" 0 "$FACET" optimize "$WORK/strip.obj" --db "$WORK/s.db" \
    --u 6:8 --v 6:8 --threshold 3 --table 0
if grep -q 'warning: the facets sag 4.1 mm' "$ERR"; then pass "optimize warns of the sag"; else fail "optimize warns of the sag"; fi
same "optimize: the sag stored with the run" \
    "$(sql "$WORK/s.db" "SELECT warnings LIKE '%the facets sag 4.1 mm%smallest threshold of the space, t = 3 mm%' FROM runs")" 1
same "optimize: no option builds any of it DP" \
    "$(sql "$WORK/s.db" 'SELECT max(dp_area), max(sp_misfits) FROM options')" "0.0|0"

# The finest grid is 8 x 8 at t = 3: the sag (4.1 mm) is under a quarter of
# t = 20 mm, so a run from 20 mm up says nothing of it.
expect "strip: optimize at 20 mm" 0 "$FACET" optimize "$WORK/strip.obj" --db "$WORK/s20.db" \
    --u 6:6 --v 6:6 --threshold 20 --table 0
if grep -q 'sag' "$ERR"; then fail "at t = 20 mm no sag warning"; else pass "at t = 20 mm no sag warning"; fi

"$FACET" example skin --res 12 -o "$WORK/skin.obj" >/dev/null 2>&1 || exit 1
expect "skin --res 12: a project run" 0 "$FACET" optimize "$WORK/skin.obj" --db "$WORK/k.db" \
    --module 1.5x1.5 --threshold 3 --table 0
same "skin: the coarse mesh stored with the run" \
    "$(sql "$WORK/k.db" "SELECT warnings LIKE '%the mesh is coarse for the smallest module, 1.5 x 1.5 m, on 180 of 180 surfaces%' FROM runs")" 1
same "skin: the facets' sag stored with the run" \
    "$(sql "$WORK/k.db" "SELECT warnings LIKE '%the facets sag % mm%the smallest threshold, t = 3 mm, on % of 180 surfaces%' FROM runs")" 1
