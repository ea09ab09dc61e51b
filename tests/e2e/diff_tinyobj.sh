#!/usr/bin/env bash
# diff_tinyobj.sh: Facet's OBJ loader reads what Debian's tinyobjloader
# reads, on every real OBJ in the shared data and on a few generated ones
# (quads, negative indices, n-gons, CRLF).
#
#   tests/e2e/diff_tinyobj.sh [BUILD_DIR]     (from the repository root)
#
# BUILD_DIR (or $BUILD, default build/release) holds tools/objdump. Data
# comes from $FACET_DATA or ../shared/data. Uses Debian's /usr/bin/python3,
# which has the tinyobjloader module. Prints one "ok"/"not ok" line per
# file and exits 1 if any file disagrees.
# layers: core
set -uo pipefail
cd "$(dirname "$0")/../.."
build=${1:-${BUILD:-build/release}}
data=${FACET_DATA:-../shared/data}
python=/usr/bin/python3
objdump=$build/tools/objdump
if [ ! -x "$objdump" ]; then
    echo "not ok - objdump tool built ($objdump missing; make $objdump)"
    exit 1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cat > "$work/quads.obj" <<'OBJ'
# 3 x 2 quad grid with texture coordinates
v 0 0 0.125
v 1 0 0.25
v 2 0 0.5
v 3 0 0.1
v 0 1 0
v 1 1 0.333333
v 2 1 0.666667
v 3 1 1e-3
v 0 2 -0.5
v 1 2 -1.25
v 2 2 -2.0e0
v 3 2 -3.5E-1
vt 0 0
vt 0.333333 0
vt 0.666667 0
vt 1 0
vt 0 0.5
vt 0.333333 0.5
vt 0.666667 0.5
vt 1 0.5
vt 0 1
vt 0.333333 1
vt 0.666667 1
vt 1 1
f 1/1 2/2 6/6 5/5
f 2/2 3/3 7/7 6/6
f 3/3 4/4 8/8 7/7
f 5/5 6/6 10/10 9/9
f 6/6 7/7 11/11 10/10
f 7/7 8/8 12/12 11/11
OBJ

cat > "$work/negative.obj" <<'OBJ'
o first
v 0 0 0
v 1 0 0
v 1 1 0
vn 0 0 1
f -3//-1 -2//-1 -1//-1
o second
v 5 0 0
v 6 0 0
v 6 1 0
v 5 1 0
vn 0 0 -1
f -4//-1 -3//-1 -2//-1 -1//-1
OBJ

{
    # A convex pentagon, a concave L hexagon and a 12-gon. (No '\'
    # continuations: this tinyobjloader does not join lines.)
    echo "v 0 0 0"; echo "v 2 0 0"; echo "v 3 1.5 0"; echo "v 1 3 0"
    echo "v -1 1.5 0"
    echo "v 0 0 1"; echo "v 3 0 1"; echo "v 3 1 1"; echo "v 1 1 1"
    echo "v 1 3 1"; echo "v 0 3 1"
    for i in $(seq 0 11); do
        awk -v i="$i" 'BEGIN { a = 6.283185307179586 * i / 12
            printf "v %.6f %.6f 2\n", cos(a), sin(a) }'
    done
    echo "f 1 2 3 4 5"
    echo "f 6 7 8 9 10 11"
    echo "f 12 13 14 15 16 17 18 19 20 21 22 23"
} > "$work/ngons.obj"
sed 's/$/\r/' "$work/quads.obj" > "$work/quads_crlf.obj"

status=0
ls "$data"/*.obj >/dev/null 2>&1 ||
    echo "skip - the real OBJ files ($data holds none)"
for file in "$data"/*.obj "$work"/*.obj; do
    [ -f "$file" ] || continue
    "$python" tests/e2e/diff_tinyobj.py "$objdump" "$file" || status=1
done
exit $status
