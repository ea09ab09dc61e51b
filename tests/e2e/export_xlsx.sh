#!/usr/bin/env bash
# End-to-end: the XLSX panel schedule (issue 30) of a single surface's
# option and of a building's, read back by openpyxl against the store read
# by Python's sqlite3 (export_xlsx.py); the same option exported twice is
# the same file, byte for byte; a path that cannot be written is refused
# in one line and leaves nothing.
# layers: cli study store core
. "$(dirname "$0")/lib.sh"
HERE=$(cd "$(dirname "$0")" && pwd)
CHECK="/usr/bin/python3 $HERE/export_xlsx.py"
if ! /usr/bin/python3 -c 'import openpyxl' 2>/dev/null; then
    skip "every XLSX check" "python3-openpyxl is not installed (make deps)"
    exit 0
fi
cd "$WORK" || exit 1

# A single surface: its panels stored, panel by panel.
"$FACET" example roof --res 30 -o roof.obj || exit 1
expect "a roof runs" 0 "$FACET" optimize roof.obj --db one.db --u 8:10 \
    --v 8:9 --threshold 3 --mould-cost 900,4000
KNEE=$(sqlite3 one.db 'SELECT number FROM options WHERE run=1 AND knee')
expect "its knee's schedule is written" 0 "$FACET" export one.db --run 1 \
    --option "$KNEE" --xlsx one.xlsx
stdout_has "it says what it wrote" '^wrote one\.xlsx$'
$CHECK one.db 1 "$KNEE" one.xlsx || echo "not ok - export_xlsx.py on a single surface (status $?)"
sleep 1  # a clock that shows would show now
expect "exported again" 0 "$FACET" export one.db --run 1 --option "$KNEE" \
    --xlsx again.xlsx
if cmp -s one.xlsx again.xlsx; then
    pass "the same option twice: the same bytes"
else
    echo "not ok - the same option twice differs"
fi

# A barrel vault of radius 10 m: its SP panels' bending radii.
"$FACET" example cylinder --res 60 -o cyl.obj || exit 1
expect "a cylinder runs" 0 "$FACET" optimize cyl.obj --db cyl.db --u 8 \
    --v 8 --threshold 3
expect "its schedule is written" 0 "$FACET" export cyl.db --run 1 \
    --option 1 --xlsx cyl.xlsx
same "its panels are all SP, fitted" \
    "$(sqlite3 cyl.db 'SELECT sp_count, sp_fitted FROM options')" "64|64"
$CHECK cyl.db 1 1 cyl.xlsx 10 || echo "not ok - export_xlsx.py on a cylinder (status $?)"

# A cylinder and a cone written from their formulas (developables.py),
# on tilted axes: each SP panel's fitted surface in the schedule against
# them (export_sp_fit.py).
for kind in cylinder cone; do
    /usr/bin/python3 "$HERE/developables.py" $kind sp_$kind.obj >sp_$kind.truth ||
        exit 1
    expect "a $kind runs" 0 "$FACET" optimize sp_$kind.obj --db sp_$kind.db \
        --u 4 --v 3 --threshold 3
    expect "its schedule is written" 0 "$FACET" export sp_$kind.db --run 1 \
        --option 1 --xlsx sp_$kind.xlsx
    /usr/bin/python3 "$HERE/export_sp_fit.py" sp_$kind.db sp_$kind.xlsx $kind \
        sp_$kind.truth || echo "not ok - export_sp_fit.py on the $kind (status $?)"
done

# The export schedules each SP panel from the fit the evaluation stored
# (schema v13), not a fit of its own (the last stop's review: the fits
# were made twice). The truth is the store itself, read by sqlite3: a
# stored radius moved by 1 mm is the workbook's, to the bit, where a fit
# made again would give the surface's own radius. And a store without
# the bending radii (as schema 12 left them) is fitted again: every
# panel's radius and bending radius then the evaluation's to 1e-12.
cp sp_cylinder.db moved.db
sqlite3 moved.db "UPDATE panels SET sp_radius = sp_radius + 0.001 WHERE sp_surface = 'cylinder'"
expect "the moved store exports" 0 "$FACET" export moved.db --run 1 --option 1 --xlsx moved.xlsx
if out=$(/usr/bin/python3 - moved.db moved.xlsx <<'PY' 2>&1
import sqlite3, sys, openpyxl
con = sqlite3.connect(sys.argv[1])
stored = {(i, j): (r, b) for i, j, r, b in con.execute(
    "SELECT i, j, sp_radius, sp_bending_radius FROM panels WHERE run=1 AND option=1 AND sp_surface='cylinder'")}
ws = openpyxl.load_workbook(sys.argv[2])["panels"]
head = [c.value for c in ws[1]]
rows = [dict(zip(head, r)) for r in ws.iter_rows(min_row=2, values_only=True)]
got = {(r["column i"], r["row j"]): r["SP cylinder radius (m)"] for r in rows
       if r["SP cylinder radius (m)"] is not None}
assert stored and got.keys() == stored.keys(), (len(stored), len(got))
# the workbook holds 16 digits (libxlsxwriter's %.16g): the store's to
# 1e-15, where a fit made again would be the 1 mm move off
bad = [(k, got[k], stored[k][0]) for k in stored
       if abs(got[k] - stored[k][0]) > 1e-15 * abs(stored[k][0])]
assert not bad, bad[:3]
print(len(stored))
PY
); then
    pass "the workbook's cylinder radii are the store's, as stored (to its 16 digits), for $out panels: no fit made again"
else
    echo "not ok - the workbook's cylinder radii are the store's, as stored: $out"
fi
for kind in cylinder cone; do
    cp sp_$kind.db v12_$kind.db
    sqlite3 v12_$kind.db "UPDATE panels SET sp_bending_radius = NULL"
    expect "a $kind's store without bending radii exports" 0 "$FACET" export \
        v12_$kind.db --run 1 --option 1 --xlsx v12_$kind.xlsx
    /usr/bin/python3 "$HERE/export_sp_fit.py" sp_$kind.db v12_$kind.xlsx $kind \
        sp_$kind.truth | sed 's/^\(not \)*ok - /&without bending radii, fitted again: /' ||
        echo "not ok - export_sp_fit.py on the $kind fitted again (status $?)"
done

# A building of four files: its panels evaluated again, against
# option_surfaces.
four_surfaces || exit 1
expect "a building runs" 0 "$FACET" optimize plane.obj cylinder.obj \
    dome.obj hypar.obj --db b.db --module 2:3x2:3 --threshold 4 \
    --mould-cost 900,4000 --joint-cost 12
OPTION=$(sqlite3 b.db 'SELECT number FROM options WHERE run=1 ORDER BY dp_count DESC, number LIMIT 1')
expect "a building's option as XLSX" 0 "$FACET" export b.db --run 1 \
    --option "$OPTION" --xlsx b.xlsx
$CHECK b.db 1 "$OPTION" b.xlsx || echo "not ok - export_xlsx.py on a building (status $?)"
sleep 1
expect "exported again" 0 "$FACET" export b.db --run 1 --option "$OPTION" \
    --xlsx b2.xlsx
if cmp -s b.xlsx b2.xlsx; then
    pass "a building's option twice: the same bytes"
else
    echo "not ok - a building's option twice differs"
fi

# The 180-face skin (coarse): SP panels on many surfaces, moulds shared
# across them.
"$FACET" example skin --res 8 -o skin.obj || exit 1
expect "the skin runs" 0 "$FACET" optimize skin.obj --db skin.db \
    --module 3x3 --threshold 4 --mould-cost 900,4000
expect "the skin's option as XLSX" 0 "$FACET" export skin.db --run 1 \
    --option 1 --xlsx skin.xlsx
$CHECK skin.db 1 1 skin.xlsx || echo "not ok - export_xlsx.py on the skin (status $?)"

# Hostile paths: one line, a non-zero exit, nothing half-written.
mkdir -p adir
expect_error "--xlsx into a directory is refused" "adir is a directory" \
    "$FACET" export one.db --run 1 --option "$KNEE" --xlsx adir
same "nothing written into it" "$(ls -A adir)" ""
expect_error "an existing file is refused without --force" "one\.xlsx exists" \
    "$FACET" export one.db --run 1 --option "$KNEE" --xlsx one.xlsx
run env TMPDIR="$WORK/no/such/folder" "$FACET" export one.db --run 1 \
    --option "$KNEE" --xlsx tmpfail.xlsx
if [ "$STATUS" -ne 0 ] && [ "$(wc -l <"$ERR")" -eq 1 ] &&
    [ -z "$(ls | grep tmpfail)" ]; then
    pass "no temporary folder: one line, exit $STATUS, no file left"
else
    fail "no temporary folder: one line and no file"
fi
if [ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null; then
    # root writes anywhere: the read-only folder is tried as nobody.
    mkdir -p ro && chmod 555 ro && chmod 755 "$WORK" && chmod 644 one.db*
    run setpriv --reuid=nobody --regid=nogroup --clear-groups \
        "$FACET" export one.db --run 1 --option "$KNEE" --xlsx ro/x.xlsx
    if [ "$STATUS" -ne 0 ] && [ "$(wc -l <"$ERR")" -eq 1 ] &&
        grep -q "cannot write ro/x.xlsx" "$ERR" && [ -z "$(ls -A ro)" ]; then
        pass "a read-only folder: one line, exit $STATUS, nothing in it"
    else
        fail "a read-only folder: one line and nothing in it"
    fi
    chmod 755 ro; chmod 700 "$WORK"
else
    skip "read-only folder check" "it needs root and setpriv to act as another user"
fi
exit 0
