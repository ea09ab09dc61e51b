#!/usr/bin/env bash
# End-to-end: the IFC4 model (issue 30) of a single surface's option and of
# a building's, read back by web-ifc (npm, pinned in tests/ifc, installed
# by make deps) against the store read by the sqlite3 program
# (export_ifc.mjs); a planarized option's plates are their moved quads
# with their corner distance and move (issue 33); the same option exported
# twice is the same file, byte
# for byte; a path that cannot be written is refused in one line and
# leaves nothing.
# layers: cli study store core
. "$(dirname "$0")/lib.sh"
HERE=$(cd "$(dirname "$0")" && pwd)
READER=$(cd "$HERE/../ifc" && pwd)
if ! command -v node >/dev/null; then
    skip "every IFC check" "node is not installed (make deps)"
    exit 0
fi
if [ ! -r "$READER/node_modules/web-ifc/package.json" ]; then
    skip "every IFC check" "web-ifc is not installed in tests/ifc/node_modules (make deps)"
    exit 0
fi
CHECK="node $HERE/export_ifc.mjs $READER"
cd "$WORK" || exit 1

# A single surface whose file's name needs escaping in STEP: a quote and
# letters outside ASCII.
"$FACET" example roof --res 30 -o "façade d'été.obj" || exit 1
expect "a roof runs" 0 "$FACET" optimize "façade d'été.obj" --db one.db \
    --u 8:10 --v 8:9 --threshold 3 --mould-cost 900,4000
KNEE=$(sqlite3 one.db 'SELECT number FROM options WHERE run=1 AND knee')
expect "its knee's model is written" 0 "$FACET" export one.db --run 1 \
    --option "$KNEE" --ifc one.ifc
stdout_has "it says what it wrote" '^wrote one\.ifc$'
$CHECK one.db 1 "$KNEE" one.ifc "façade d'été" ||
    echo "not ok - export_ifc.mjs on a single surface (status $?)"
if grep -q "IFCCURTAINWALL('[^']*',\$,'fa\\\\X2\\\\00E7\\\\X0\\\\ade d''\\\\X2\\\\00E9\\\\X0\\\\t\\\\X2\\\\00E9\\\\X0\\\\'" one.ifc; then
    pass "the surface's name in STEP: ' doubled, ç and é as \\X2\\"
else
    echo "not ok - the surface's name escaped as ISO 10303-21 says"
    grep -m1 IFCCURTAINWALL one.ifc | sed 's/^/  /'
fi
# SP by class alone (--sp-fit no): the panels no cylinder or cone fits stay
# SP as classed and are built DP, so type as built is not type as classed.
expect "the roof runs SP by class" 0 "$FACET" optimize "façade d'été.obj" \
    --db class.db --u 8:10 --v 8:9 --threshold 3 --sp-fit no
MISFIT=$(sqlite3 class.db 'SELECT number FROM options WHERE run=1 ORDER BY sp_count DESC, number LIMIT 1')
expect "an option with SP panels as IFC" 0 "$FACET" export class.db --run 1 \
    --option "$MISFIT" --ifc misfit.ifc
same "its store has panels classed SP, built DP" \
    "$(sqlite3 class.db "SELECT count(*) > 0 FROM panels WHERE run=1 AND option=$MISFIT AND type='SP' AND built_type='DP'")" 1
$CHECK class.db 1 "$MISFIT" misfit.ifc "façade d'été" ||
    echo "not ok - export_ifc.mjs on panels classed SP, built DP (status $?)"
# Two options of one run: no object of one has the other's GlobalId.
OTHER=$(sqlite3 one.db "SELECT number FROM options WHERE run=1 AND number != $KNEE LIMIT 1")
expect "another option of the run as IFC" 0 "$FACET" export one.db --run 1 \
    --option "$OTHER" --ifc other.ifc
if [ -z "$(comm -12 <(grep -o "^#[0-9]*=IFCPLATE('[^']*'" one.ifc | cut -d"'" -f2 | sort) \
                  <(grep -o "^#[0-9]*=IFCPLATE('[^']*'" other.ifc | cut -d"'" -f2 | sort))" ]; then
    pass "two options of a run share no plate's GlobalId"
else
    echo "not ok - two options of a run share plates' GlobalIds"
fi
exported_again "the same option" one.ifc again.ifc \
    "$FACET" export one.db --run 1 --option "$KNEE" --ifc again.ifc

# A cylinder: every panel SP, the geometry curved.
"$FACET" example cylinder --res 60 -o cyl.obj || exit 1
expect "a cylinder runs" 0 "$FACET" optimize cyl.obj --db cyl.db --u 8 \
    --v 8 --threshold 3
expect "its model is written" 0 "$FACET" export cyl.db --run 1 \
    --option 1 --ifc cyl.ifc
$CHECK cyl.db 1 1 cyl.ifc cyl ||
    echo "not ok - export_ifc.mjs on a cylinder (status $?)"

# Planarized options (issue 33): each moved plate's body is its moved
# quad at the stored corners, planar to the option's reported planarity,
# with CornerDistance (the brute-force distance of its corners to the
# surface's triangles, measured by export_ifc.mjs) and CornerMoved; a
# classified option's plates have neither value. A surface of revolution's
# conjugate net (within 0.2 mm) and a hypar's rulings (some 350 mm off).
/usr/bin/python3 "$HERE/planarize_check.py" vase vase.obj || exit 1
expect "a surface of revolution planarizes" 0 "$FACET" optimize vase.obj \
    --db vase.db --u 11 --v 8 --threshold 3 --planarize 0.2
"$FACET" example hypar -o hypar.obj 2>/dev/null || exit 1
expect "a hypar planarizes" 0 "$FACET" optimize hypar.obj --db hypar.db \
    --u 6 --v 6 --threshold 3 --planarize 5
for s in vase hypar; do
    OPT=$(sqlite3 $s.db 'SELECT number FROM options WHERE planarized = 1')
    same "$s: its planarized option moved its corners" \
        "$(sqlite3 $s.db "SELECT closeness_reached > 1e-6 FROM options WHERE number = $OPT")" 1
    expect "$s: its planarized option as IFC" 0 "$FACET" export $s.db \
        --run 1 --option "$OPT" --ifc $s.ifc
    PLANAR_MESH=$s.obj $CHECK $s.db 1 "$OPT" $s.ifc $s ||
        echo "not ok - export_ifc.mjs on the $s's planarized option (status $?)"
done
expect "the hypar's classified option as IFC" 0 "$FACET" export hypar.db \
    --run 1 --option 1 --ifc hypar-c.ifc
PLANAR_MESH=hypar.obj $CHECK hypar.db 1 1 hypar-c.ifc hypar ||
    echo "not ok - export_ifc.mjs on the hypar's classified option (status $?)"

# A building of four files: its panels evaluated again, against
# option_surfaces; ids unique across it.
four_surfaces || exit 1
expect "a building runs" 0 "$FACET" optimize plane.obj cylinder.obj \
    dome.obj hypar.obj --db b.db --module 2:3x2:3 --threshold 4 \
    --mould-cost 900,4000 --joint-cost 12
OPTION=$(sqlite3 b.db 'SELECT number FROM options WHERE run=1 ORDER BY dp_count DESC, number LIMIT 1')
expect "a building's option as IFC" 0 "$FACET" export b.db --run 1 \
    --option "$OPTION" --ifc b.ifc
IDS_OUT=$WORK/b.ids $CHECK b.db 1 "$OPTION" b.ifc ||
    echo "not ok - export_ifc.mjs on a building (status $?)"
# The same ids in every format (issue 30): the IFC's, as web-ifc reads
# them, are the CSV schedule's and the DXF's labels, panel by panel.
"$FACET" export b.db --run 1 --option "$OPTION" --csv b.csv --dxf b.dxf --sheet 20000x20000 \
    >/dev/null 2>&1
if out=$(/usr/bin/python3 - "$WORK/b.ids" b.csv b.dxf <<'PY' 2>&1
import csv, sys
ifc = {}
for line in open(sys.argv[1]):
    pid, surface, i, j = line.strip().split(",")
    ifc[int(pid)] = (surface, int(float(i)), int(float(j)))
rows = list(csv.DictReader(open(sys.argv[2], newline="")))
schedule = {int(r["id"]): (r["surface"], int(r["i"]), int(r["j"])) for r in rows}
assert len(ifc) == len(schedule) > 0, "%d plates, %d rows" % (len(ifc), len(schedule))
bad = [k for k in schedule if ifc.get(k) != schedule[k]]
assert not bad, "id %d: IFC %s, CSV %s" % (bad[0], ifc.get(bad[0]), schedule[bad[0]])
try:
    import ezdxf
except ImportError:
    print("%d ids (no ezdxf: the DXF not read)" % len(ifc))
    sys.exit(0)
labels = sorted(int(e.dxf.text) for e in ezdxf.readfile(sys.argv[3]).modelspace()
                .query("TEXT") if e.dxf.layer in ("FP", "SP", "DP")
                and e.dxf.text.isdigit())
assert labels == sorted(schedule), "DXF labels %s.. vs ids %s.." % (labels[:5], sorted(schedule)[:5])
print("%d ids" % len(ifc))
PY
); then
    pass "a building's panel ids are the same in the IFC, the CSV and the DXF ($out)"
else
    echo "not ok - a building's panel ids are the same in the IFC, the CSV and the DXF"
    printf '%s\n' "$out" | tail -n 3 | sed 's/^/  /'
fi
exported_again "a building's option" b.ifc b2.ifc \
    "$FACET" export b.db --run 1 --option "$OPTION" --ifc b2.ifc

# A building of the roof (its name escaped) and a plane.
"$FACET" example plane --res 16 -o plane.obj --force || exit 1
expect "a building with the roof runs" 0 "$FACET" optimize \
    "façade d'été.obj" plane.obj --db rb.db --module 3:5x3:5 --threshold 3 \
    --mould-cost 900,4000
OPTION=$(sqlite3 rb.db 'SELECT number FROM options WHERE run=1 ORDER BY sp_misfits DESC, number LIMIT 1')
expect "its option as IFC" 0 "$FACET" export rb.db --run 1 \
    --option "$OPTION" --ifc rb.ifc
$CHECK rb.db 1 "$OPTION" rb.ifc ||
    echo "not ok - export_ifc.mjs on the roof's building (status $?)"

# The 180-face skin (coarse): many surfaces, moulds shared across them.
"$FACET" example skin --res 8 -o skin.obj || exit 1
expect "the skin runs" 0 "$FACET" optimize skin.obj --db skin.db \
    --module 3x3 --threshold 4 --mould-cost 900,4000
expect "the skin's option as IFC" 0 "$FACET" export skin.db --run 1 \
    --option 1 --ifc skin.ifc
$CHECK skin.db 1 1 skin.ifc ||
    echo "not ok - export_ifc.mjs on the skin (status $?)"

# Hostile paths: one line, a non-zero exit, nothing half-written.
mkdir -p adir
expect_error "--ifc into a directory is refused" "adir is a directory" \
    "$FACET" export one.db --run 1 --option "$KNEE" --ifc adir
same "nothing written into it" "$(ls -A adir)" ""
echo "not a model" >existing.ifc
expect_error "an existing file is refused without --force" \
    "existing\.ifc exists" \
    "$FACET" export one.db --run 1 --option "$KNEE" --ifc existing.ifc
if [ "$(cat existing.ifc)" = "not a model" ] && [ -z "$(ls | grep partial)" ]; then
    pass "the existing file is untouched, no .partial left"
else
    echo "not ok - the existing file changed or a .partial was left"
fi
expect_error "a folder that does not exist is refused" "no/such" \
    "$FACET" export one.db --run 1 --option "$KNEE" --ifc no/such/x.ifc
expect_error "an option that does not exist: nothing written" "option" \
    "$FACET" export one.db --run 1 --option 999 --ifc none.ifc
same "no file for it" "$(ls | grep -c none)" "0"
exit 0
