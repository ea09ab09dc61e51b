#!/usr/bin/env bash
# End-to-end: facet planarize (issue 33). A surface of revolution written
# from its formula (planarize_check.py vase), its meridians and parallels
# a conjugate net, planarizes feasibly at 1e-6 of the diagonal within
# 0.1 mm; the example hypar's grid along its rulings is reported
# infeasible at 5 mm. For both, planarize_check.py measures the exported
# OBJ itself with numpy (every quad's planarity, every corner's distance
# to the surface's triangles by brute force) against what facet reported.
# Bad input: a one-line error and status 2.
# layers: cli core
. "$(dirname "$0")/lib.sh"
HERE=$(cd "$(dirname "$0")" && pwd)
cd "$WORK" || exit 1
/usr/bin/python3 "$HERE/planarize_check.py" vase vase.obj || exit 1

run "$FACET" planarize vase.obj --grid 16x12 --closeness 0.1 \
    --planarity 1e-6 --obj vase-planar.obj --json
[ "$STATUS" -eq 0 ] && pass "planarize a surface of revolution" ||
    fail "planarize a surface of revolution"
cp "$OUT" vase.json
json_check "meridians and parallels: feasible" "j['feasible'] is True"
json_check "meridians and parallels: planar to 1e-6 of the diagonal" \
    "j['planarity_max'] <= 1e-6 and j['quads_over'] == 0"
json_check "meridians and parallels: corners within 0.1 mm" \
    "j['closeness_max_mm'] <= 0.1"
/usr/bin/python3 "$HERE/planarize_check.py" check vase.obj vase-planar.obj \
    vase.json

"$FACET" example hypar -o hypar.obj 2>/dev/null
run "$FACET" planarize hypar.obj --grid 10x10 --closeness 5 \
    --obj hypar-planar.obj --json
[ "$STATUS" -eq 0 ] && pass "planarize the hypar (exit 0, infeasible said)" ||
    fail "planarize the hypar (exit 0, infeasible said)"
cp "$OUT" hypar.json
json_check "hypar along its rulings: infeasible at 5 mm" \
    "j['feasible'] is False and j['closeness_max_mm'] > 5"
/usr/bin/python3 "$HERE/planarize_check.py" check hypar.obj hypar-planar.obj \
    hypar.json
run "$FACET" planarize hypar.obj --grid 10x10 --closeness 5
stdout_has "the hypar's text says INFEASIBLE and the closeness reached" \
    "^result +INFEASIBLE under the 5 mm budget: .*corners up to [0-9.]+ mm"
if head -1 hypar-planar.obj | grep -q INFEASIBLE; then
    pass "the hypar's OBJ says INFEASIBLE in its first line"
else
    fail "the hypar's OBJ says INFEASIBLE in its first line"
fi

# CHOLMOD (and OpenBLAS, LAPACK, gfortran under it) is loaded by the
# process that solves, never by facet's start (core/planar/sparse_solver.h):
# every other facet call is spared its loading and its threads.
if ldd "$FACET" >"$OUT" 2>"$ERR" && ! grep -qE 'libcholmod|blas|lapack' "$OUT"; then
    pass "facet starts without CHOLMOD or a BLAS"
else
    STATUS=1
    fail "facet starts without CHOLMOD or a BLAS (ldd names them)"
fi
LD_DEBUG=files "$FACET" planarize hypar.obj --grid 4x4 --closeness 5 \
    >"$OUT" 2>"$ERR"
STATUS=$?
if [ "$STATUS" -eq 0 ] && grep -q 'file=libcholmod' "$ERR"; then
    pass "planarize loads CHOLMOD when it solves"
else
    fail "planarize loads CHOLMOD when it solves"
fi

expect_error "no grid" "give the grid" "$FACET" planarize hypar.obj
expect_error "an absurd grid" "^facet: --grid" "$FACET" planarize hypar.obj --grid 0x5
expect_error "a grid too fine" "^facet: --grid" "$FACET" planarize hypar.obj \
    --grid 3000x3000
expect_error "a negative closeness" "^facet: --closeness" "$FACET" planarize \
    hypar.obj --grid 4x4 --closeness -1
expect_error "a closeness not a number" "^facet: --closeness" "$FACET" planarize \
    hypar.obj --grid 4x4 --closeness nan
expect_error "a planarity of 0" "^facet: --planarity" "$FACET" planarize hypar.obj \
    --grid 4x4 --planarity 0
expect_error "a planarity NaN" "^facet: --planarity" "$FACET" planarize hypar.obj \
    --grid 4x4 --planarity NaN
expect_error "a missing surface" "absent.obj" "$FACET" planarize absent.obj \
    --grid 4x4
expect_error "an OBJ that exists" "exists" "$FACET" planarize hypar.obj \
    --grid 4x4 --obj hypar-planar.obj
exit 0
