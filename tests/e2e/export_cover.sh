#!/usr/bin/env bash
# End-to-end: an exported OBJ covers its surface exactly. Every SP or DP
# panel's exported patch adds up to its schedule area, and the export adds
# up to the surface's own area (export_cover.py, reading both OBJ files
# with tinyobjloader), on an annulus shell rolled into a long tube (whose
# harmonic map squeezes the far end to a point: the export dropped
# triangles there that the schedule counted) and on every real surface of
# ../shared/data under every UV method that applies to it.
# layers: core study cli
. "$(dirname "$0")/lib.sh"
COVER="/usr/bin/python3 $(dirname "$0")/export_cover.py"

# cover NAME SURFACE UV GRID: optimize at one grid at t = 0 (every panel
# curved that is not exactly flat), export, check. A UV method that cannot
# apply to the surface (refused with status 2) is a skip, said.
cover() {
    local name=$1 surface=$2 uv=$3 db=$WORK/c.db
    rm -f "$db" "$db-wal" "$db-shm"
    run "$FACET" optimize "$surface" --db "$db" --u "${4%x*}" --v "${4#*x}" \
        --threshold 0 --uv "$uv" --table 0
    if [ "$STATUS" -eq 2 ] && grep -qE 'no texture|not a structured|fold|not a disk|separate|charts' "$ERR"; then
        skip "$name: --uv $uv" "$(head -c 100 "$ERR")"
        return
    fi
    if [ "$STATUS" -ne 0 ]; then fail "$name: --uv $uv optimize"; return; fi
    run "$FACET" export "$db" --run 1 --option 1 --obj "$WORK/e.obj" \
        --csv "$WORK/e.csv" --force
    if [ "$STATUS" -ne 0 ]; then fail "$name: --uv $uv export"; return; fi
    if $COVER "$WORK/e.obj" "$WORK/e.csv" "$surface" >"$OUT" 2>"$ERR"; then
        pass "$name: --uv $uv $4: export covers the surface ($(cat "$OUT"))"
    else
        STATUS=1
        fail "$name: --uv $uv $4: export covers the surface"
    fi
}

# The tube: radius 1 m, 16 m long, 24 x 80 quads cut into triangles, each
# ring turned half a facet. Its two rims make it an annulus; the harmonic
# map sends the first rim to a circle and caps the other, which lands
# e^-16 of the way in, with whole facets within 1e-9 of a cell in UV.
/usr/bin/python3 - "$WORK/tube.obj" <<'PY'
import math, sys
nt, nz, r, length = 24, 80, 1.0, 16.0
with open(sys.argv[1], "w") as out:
    for i in range(nz + 1):
        for j in range(nt):
            a = 2 * math.pi * (j + 0.5 * (i % 2)) / nt
            out.write("v %.17g %.17g %.17g\n" % (r * math.cos(a), r * math.sin(a), length * i / nz))
    for i in range(nz):
        for j in range(nt):
            a, b = i * nt + j + 1, (i + 1) * nt + j + 1
            c, d = (i + 1) * nt + (j + 1) % nt + 1, i * nt + (j + 1) % nt + 1
            out.write("f %d %d %d\nf %d %d %d\n" % (a, b, c, a, c, d))
PY
cover "annulus shell as a 16 m tube" "$WORK/tube.obj" harmonic 20x35
cover "annulus shell as a 16 m tube" "$WORK/tube.obj" harmonic 7x5

# Every real surface, every UV method.
if [ -d "$FACET_DATA" ]; then
    for f in "$FACET_DATA"/*.obj; do
        for uv in vt grid plane harmonic; do
            cover "$(basename "$f")" "$f" "$uv" 20x35
        done
    done
else
    skip "export coverage on the real surfaces" "$FACET_DATA is absent"
fi
