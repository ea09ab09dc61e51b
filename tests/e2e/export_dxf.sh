#!/usr/bin/env bash
# End-to-end: the flat patterns as DXF (issue 30 item 2), read back by
# ezdxf (Debian python3-ezdxf) against the store read by Python's sqlite3
# (export_dxf.py: audit, one labelled pattern per panel with the
# schedule's id, layers as built, areas with derived tolerances, sheets
# without overlaps); a plane's patterns are its panels exactly; a
# cylinder's and a cone's written from their formulas; a building's
# option; every panel's polylines carry its id as XDATA, and a planarized
# option's moved panels are their moved quads with their corner distance
# and move (issue 33); the same option twice is the same file; a bad sheet size or a
# panel no sheet holds is refused in one line and leaves nothing.
# layers: cli study core
. "$(dirname "$0")/lib.sh"
HERE=$(cd "$(dirname "$0")" && pwd)
CHECK="/usr/bin/python3 $HERE/export_dxf.py"
if ! /usr/bin/python3 -c 'import ezdxf' 2>/dev/null; then
    skip "every DXF check" "python3-ezdxf is not installed (make deps)"
    exit 0
fi
cd "$WORK" || exit 1

# export_dxf DB OPTION NAME SHEET MESH [exact]: exports NAME.dxf and
# NAME.csv of run 1's option and checks them.
export_dxf() {
    local db=$1 option=$2 name=$3 sheet=$4 mesh=$5
    expect "$name: its patterns are written" 0 "$FACET" export "$db" \
        --run 1 --option "$option" --dxf "$name.dxf" --csv "$name.csv" \
        --sheet "$sheet"
    stdout_has "$name: it says what it wrote" "^wrote $name\\.dxf$"
    $CHECK "$db" 1 "$option" "$name.dxf" "$name.csv" "$sheet" "$mesh" $6 ||
        echo "not ok - export_dxf.py on $name (status $?)"
}

# A plane, 20 x 15 m: every pattern is its panel, exactly.
"$FACET" example plane --res 12 -o plane.obj || exit 1
expect "a plane runs" 0 "$FACET" optimize plane.obj --db plane.db --u 20 \
    --v 15 --threshold 3
export_dxf plane.db 1 plane 6000x3000 plane.obj exact

# The roof: FP, SP and DP panels.
"$FACET" example roof --res 30 -o roof.obj || exit 1
expect "a roof runs" 0 "$FACET" optimize roof.obj --db roof.db --u 21:22 \
    --v 24:25 --threshold 3 --mould-cost 900,4000
KNEE=$(sqlite3 roof.db 'SELECT number FROM options WHERE run=1 AND fp_count > 0 AND sp_fitted > 0 AND dp_count > 0 ORDER BY number LIMIT 1')
same "an option of the roof has panels of every type" \
    "$(sqlite3 roof.db "SELECT fp_count > 0, sp_fitted > 0, dp_count > 0 FROM options WHERE run=1 AND number=$KNEE")" \
    "1|1|1"
export_dxf roof.db "$KNEE" roof 6000x3000 roof.obj
exported_again "the same option" roof.dxf again.dxf \
    "$FACET" export roof.db --run 1 --option "$KNEE" --dxf again.dxf \
    --sheet 6000x3000

# A cylinder and a cone from their formulas, on tilted axes: SP panels
# unrolled on their fits.
for kind in cylinder cone; do
    /usr/bin/python3 "$HERE/developables.py" $kind sp_$kind.obj \
        >/dev/null || exit 1
    expect "a $kind runs" 0 "$FACET" optimize sp_$kind.obj \
        --db sp_$kind.db --u 8 --v 6 --threshold 3
    same "its panels are all SP, fitted" \
        "$(sqlite3 sp_$kind.db 'SELECT sp_count = panels, sp_fitted = panels FROM options')" \
        "1|1"
    export_dxf sp_$kind.db 1 sp_$kind 3000x1500 sp_$kind.obj
done

# A building of four files: ids unique across it, each surface's panels
# evaluated again.
for s in plane cylinder dome hypar; do
    fixture "$s.obj" "$WORK/b_$s.obj" || exit 1
done
expect "a building runs" 0 "$FACET" optimize b_plane.obj b_cylinder.obj \
    b_dome.obj b_hypar.obj --db b.db --module 2:3x2:3 --threshold 4 \
    --mould-cost 900,4000
OPTION=$(sqlite3 b.db 'SELECT number FROM options WHERE run=1 ORDER BY dp_count DESC, number LIMIT 1')
export_dxf b.db "$OPTION" building 6000x4500 \
    b_plane.obj:b_cylinder.obj:b_dome.obj:b_hypar.obj
exported_again "a building's option" building.dxf building2.dxf \
    "$FACET" export b.db --run 1 --option "$OPTION" --dxf building2.dxf \
    --sheet 6000x4500

# Planarized options (issue 33): each moved panel's 3D outline is its
# moved quad at the stored corners, planar to the option's reported
# planarity, and its XDATA's corner distance is numpy's brute-force
# distance of those corners to the surface's triangles. A surface of
# revolution's meridians and parallels (a conjugate net: feasible within
# 0.2 mm) and a hypar's rulings (planar only some 350 mm off it).
/usr/bin/python3 "$HERE/planarize_check.py" vase vase.obj || exit 1
expect "a surface of revolution planarizes" 0 "$FACET" optimize vase.obj \
    --db vase.db --u 11 --v 8 --threshold 3 --planarize 0.2
VOPT=$(sqlite3 vase.db 'SELECT number FROM options WHERE planarized = 1')
same "its planarized option moved its corners, within the budget" \
    "$(sqlite3 vase.db "SELECT feasible, closeness_reached > 1e-6 FROM options WHERE number = $VOPT")" "1|1"
export_dxf vase.db "$VOPT" vase 20000x20000 vase.obj
"$FACET" example hypar -o hypar.obj 2>/dev/null || exit 1
expect "a hypar planarizes" 0 "$FACET" optimize hypar.obj --db hypar.db \
    --u 6 --v 6 --threshold 3 --planarize 5
HOPT=$(sqlite3 hypar.db 'SELECT number FROM options WHERE planarized = 1')
same "its planarized option is infeasible, far off the surface" \
    "$(sqlite3 hypar.db "SELECT feasible, closeness_reached > 0.1 FROM options WHERE number = $HOPT")" "0|1"
export_dxf hypar.db "$HOPT" hypar 20000x20000 hypar.obj
# And its classified option: no corner numbers at all.
export_dxf hypar.db 1 hypar_classified 20000x20000 hypar.obj

# Real surfaces (../shared/data): a barrel vault (SP), an igloo (FP, SP
# and DP, trimmed panels at its door).
for f in barrel igloo; do
    if have_data $f.obj; then
        expect "$f runs" 0 "$FACET" optimize "$FACET_DATA/$f.obj" \
            --db real_$f.db --u 6 --v 6 --threshold 5
        export_dxf real_$f.db 1 real_$f 20000x20000 "$FACET_DATA/$f.obj"
    fi
done

# Bad sheets: one line, a non-zero exit, no file, no partial file.
for sheet in 0x1500 -3000x1500 nanx1500 3000xinf axb 3000 3000x x1500 \
    3000x1500x2; do
    expect_error "--sheet $sheet is refused in one line" "^facet: --sheet" \
        "$FACET" export roof.db --run 1 --option "$KNEE" --dxf bad.dxf \
        --sheet "$sheet"
done
expect_error "a sheet smaller than a panel is refused, naming the panel" \
    "panel [0-9]+ \\(roof, cell [0-9]+, [0-9]+\\) lies flat in [0-9]+ x [0-9]+ mm" \
    "$FACET" export roof.db --run 1 --option "$KNEE" --dxf bad.dxf \
    --csv bad.csv --sheet 500x400
expect_error "--sheet without --dxf is refused" "^facet: export: --sheet.*--dxf" \
    "$FACET" export roof.db --run 1 --option "$KNEE" --csv bad.csv \
    --sheet 500x400
same "no file left by any of them" "$(ls | grep '^bad')" ""
exit 0
