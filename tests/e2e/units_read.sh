#!/usr/bin/env bash
# End-to-end: a file whose size, read in the default metres, is no
# building's, while another unit gives it one, is refused in one line that
# names the --units to give (issue 32 item 18); units the user names are
# read as asked, with the warning. The sizes come from the OBJ's own
# coordinates, read here, not from facet.
# layers: core study cli
. "$(dirname "$0")/lib.sh"

expect "example roof writes" 0 "$FACET" example roof -o "$WORK/roof.obj"
# The roof in millimetres: every v scaled by 1000, the rest as written.
km=$(/usr/bin/python3 "$(dirname "$0")/obj_scaled.py" 1000 "$WORK/roof.obj" "$WORK/roof-mm.obj")
metres=$km  # the file's diagonal: km read as metres, m in mm

expect_error "optimize refuses a millimetre file read as metres" \
    "roof-mm\.obj is $km km across in m.*in mm it is $metres m: give --units mm" \
    "$FACET" optimize "$WORK/roof-mm.obj" --db "$WORK/refused.db" --u 2:3 --v 2:3
runs=$(sqlite3 "$WORK/refused.db" "select count(*) from runs" 2>/dev/null || echo 0)
same "the refused run is not stored" "$runs" 0
expect_error "classify refuses it too" "give --units mm" \
    "$FACET" classify "$WORK/roof-mm.obj" --grid 4x4
expect_error "curvature refuses it too" "give --units mm" \
    "$FACET" curvature "$WORK/roof-mm.obj"

expect "--units mm reads it" 0 \
    "$FACET" optimize "$WORK/roof-mm.obj" --db "$WORK/mm.db" --u 2:3 --v 2:3 \
    --units mm
run "$FACET" info "$WORK/roof.obj" --json
area=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["area"])' "$OUT")
same "the run is in mm, with the metre file's area" \
    "$(sqlite3 "$WORK/mm.db" "select units, abs(surface_area - $area) < 1e-9 * $area from runs")" \
    "mm|1"
expect "an explicit --units m goes on as asked" 0 \
    "$FACET" optimize "$WORK/roof-mm.obj" --db "$WORK/m.db" --u 2:3 --v 2:3 \
    --units m
if grep -q "$km km across in m" "$ERR"; then pass "with the warning";
else fail "with the warning"; fi
same "the run is stored in metres" \
    "$(sqlite3 "$WORK/m.db" "select units from runs")" m
expect "classify --units m goes on as asked" 0 \
    "$FACET" classify "$WORK/roof-mm.obj" --grid 4x4 --units m
expect "the roof in metres is read without --units" 0 \
    "$FACET" classify "$WORK/roof.obj" --grid 4x4

# A project is judged as the building its surfaces make: the box around
# all of them, from the files' own coordinates (read here), in one line
# naming the --units to give; --units names them as asked.
fixture four.obj || exit 1
read -r km metres < <(python3 - "$WORK/four.obj" "$WORK/four-mm.obj" "$WORK/roof-mm.obj" <<'PY'
import math, sys
lo, hi = [math.inf] * 3, [-math.inf] * 3
def box(path, scale, out=None):
    with open(path) as src:
        dst = open(out, "w") if out else None
        for line in src:
            if line.startswith("v "):
                p = [float(x) * scale for x in line.split()[1:4]]
                for k in range(3):
                    lo[k], hi[k] = min(lo[k], p[k]), max(hi[k], p[k])
                line = "v %r %r %r\n" % tuple(p)
            if dst:
                dst.write(line)
box(sys.argv[1], 1000, sys.argv[2])
box(sys.argv[3], 1)
d = math.dist(lo, hi)
print("%.1f %.1f" % (d / 1000, d / 1000))
PY
)
expect_error "a project in millimetres read as metres is refused, as a building" \
    "the building of .*four-mm\.obj and 1 more files is $km km across in m.*in mm it is $metres m: give --units mm" \
    "$FACET" optimize "$WORK/four-mm.obj" "$WORK/roof-mm.obj" --module 2x2 \
    --db "$WORK/project-refused.db"
runs=$(sqlite3 "$WORK/project-refused.db" "select count(*) from runs" 2>/dev/null || echo 0)
same "the refused project run is not stored" "$runs" 0
expect "--units mm reads the project" 0 \
    "$FACET" optimize "$WORK/four-mm.obj" "$WORK/roof-mm.obj" --module 2x2 \
    --db "$WORK/project-mm.db" --units mm --table 0
same "the project run is in mm" "$(sqlite3 "$WORK/project-mm.db" "select units from runs")" mm
expect "the project in metres is read without --units" 0 \
    "$FACET" optimize "$WORK/four.obj" --module 2x2 --db "$WORK/project-m.db" --table 0
