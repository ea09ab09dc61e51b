#!/usr/bin/env bash
# End-to-end: a building's option out of Facet (issue 30). Its schedule
# lists every panel of every surface, with a surface column and IDs
# unique across the building, read back against the store with Python's
# csv and sqlite3 (export_project.py); what cannot be written for a
# building yet is refused in one line, names a command that works, and
# leaves no file.
# layers: cli study store core
. "$(dirname "$0")/lib.sh"
DB=$WORK/b.db
CHECK=$(cd "$(dirname "$0")" && pwd)/export_project.py
cd "$WORK" || exit 1
for s in plane cylinder dome hypar; do
    "$FACET" example "$s" --res 10 -o "$WORK/$s.obj" || exit 1
done
expect "a building of four files runs" 0 "$FACET" optimize plane.obj \
    cylinder.obj dome.obj hypar.obj --db "$DB" --module 2:3x2:3 \
    --threshold 4 --mould-cost 900,4000 --joint-cost 12
OPTION=$(sqlite3 "$DB" 'SELECT number FROM options WHERE run=1 ORDER BY number LIMIT 1 OFFSET 1')
[ -n "$OPTION" ] || { echo "not ok - run 1 has options"; exit 1; }

expect "the building's schedule is written" 0 "$FACET" export "$DB" \
    --run 1 --option "$OPTION" --csv "$WORK/b.csv"
stdout_has "it says what it wrote" '^wrote .*b\.csv$'
/usr/bin/python3 "$CHECK" "$DB" 1 "$OPTION" \
    "$WORK/b.csv" "$WORK/b-totals.csv" ||
    echo "not ok - export_project.py (status $?)"

# The issue's case: the 180-face skin (coarse, 14,400 triangles), one
# module.
"$FACET" example skin --res 8 -o "$WORK/skin.obj" || exit 1
expect "the skin runs" 0 "$FACET" optimize skin.obj --db skin.db \
    --module 3x3 --threshold 4
expect "the skin's schedule is written" 0 "$FACET" export skin.db --run 1 \
    --option 1 --csv "$WORK/skin.csv"
/usr/bin/python3 "$CHECK" skin.db 1 1 "$WORK/skin.csv" \
    "$WORK/skin-totals.csv" >"$WORK/skin.checks" ||
    echo "not ok - export_project.py on the skin (status $?)"
# 180 surfaces, three checks each: one line for the lot.
if grep -q '^not ok' "$WORK/skin.checks"; then
    grep '^not ok' "$WORK/skin.checks" | head -5
else
    pass "the skin: $(grep -c '^ok' "$WORK/skin.checks") checks of its schedule against the store"
fi

# A surface named with a comma and quotes (Rhino allows both): its CSV
# field quoted, read back whole by Python's csv.
"$FACET" example skin --res 4 -o "$WORK/q.obj" || exit 1
sed -i 's/^o skin_r00_c00$/o podium, "west"/' "$WORK/q.obj"
expect "a skin with a quoted name runs" 0 "$FACET" optimize q.obj \
    --db q.db --module 4x4 --threshold 4
expect "its schedule is written" 0 "$FACET" export q.db --run 1 \
    --option 1 --csv "$WORK/q.csv"
/usr/bin/python3 "$CHECK" q.db 1 1 "$WORK/q.csv" "$WORK/q-totals.csv" \
    >"$WORK/q.checks" || echo "not ok - export_project.py on the quoted name (status $?)"
if grep -q '^not ok' "$WORK/q.checks" ||
    ! grep -q '^ok - surface podium, "west": ' "$WORK/q.checks"; then
    echo "not ok - the quoted name's panels read back"
    grep '^not ok' "$WORK/q.checks" | head -5
else
    pass "a surface named 'podium, \"west\"': its panels read back whole"
fi

# No format of a building writes an empty file and calls it done: those
# not written yet are refused, before any file is made.
for f in obj json svg; do
    expect_error "--$f of a building's option is refused in one line" \
        "not written yet.*facet show" \
        "$FACET" export "$DB" --run 1 --option "$OPTION" --$f "$WORK/b.$f"
    if [ ! -e "$WORK/b.$f" ] && [ -z "$(ls "$WORK" | grep -F "b.$f")" ]; then
        pass "--$f: no file left"
    else
        echo "not ok - --$f left $(ls "$WORK" | grep -F "b.$f")"
    fi
    # The command the message gives runs.
    suggested=$(grep -oE 'facet show .*$' "$ERR")
    read -r -a words <<<"${suggested#facet }"
    run "$FACET" "${words[@]}"
    if [ "$STATUS" -eq 0 ] && grep -q '^module' "$OUT"; then
        pass "--$f: the command it names works: $suggested"
    else
        fail "--$f: the command it names fails: $suggested"
    fi
done
exit 0
