#!/usr/bin/env bash
# End-to-end: the New run form reads the Units field as the CLI reads
# --units (issue 32, the form's leftover of item 18). Left empty, a mesh
# is read in metres and checked against its size: the roof drawn in mm is
# refused, and the message names the form's field and the unit its size
# says, never a command-line flag. Typed, the units are the user's word,
# "m" too: then the same file runs, in metres, as asked (sqlite3 reads the
# run back). Before, the field held "m" from the start, so typing "m"
# could not be told from the default and metres could not be insisted on.
# The sizes come from the OBJ's own coordinates, read here.
# layers: tui study
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/tui_lib.sh"

"$FACET" example roof --res 8 -o "$WORK/roof.obj" >/dev/null 2>&1 || exit 1
# km, read as metres (the file's diagonal, from its coordinates)
km=$(/usr/bin/python3 "$(dirname "$0")/obj_scaled.py" 1000 "$WORK/roof.obj" "$WORK/roof-mm.obj")

start 120 30 -- u.db
check "a new store is offered" 'Create a new result database there'
keys y
check "the runs list, empty" 'runs'
keys a
check "the New run form" '^ New run into u\.db'
screen | grep -qE '^ *Units +\S' && echo "not ok - the Units field starts empty" ||
    pass "the Units field starts empty"
keys roof-mm.obj Down
check "on Units, its hint says what empty means" 'empty: m, refused if the size says otherwise'
keys Down C-u 2:3 Down C-u 2:3 F5
# The message wraps over the status rows: read them as one.
check "left empty, the mm roof is refused" "new run refused: .*roof-mm\.obj is $km km"
joined=$(screen | tail -n 4 | tr '\n' ' ' | tr -s ' ')
if grep -qE "roof-mm\.obj is $km km across in m.*in mm it is .*: type mm in New run's Units \(or m to go on in metres\)" <<<"$joined"; then
    pass "... naming the form's field, the unit its size says, and how to insist on metres"
else
    echo "not ok - ... naming the form's field, the unit its size says, and how to insist on metres"
    screen | sed 's/^/  screen: /'
fi
if screen | grep -E 'refused' | grep -qE -- '--[a-z]'; then
    echo "not ok - the refusal names no command-line flag"
else
    pass "the refusal names no command-line flag"
fi
same "... and no run is recorded" "$(sqlite3 "$WORK/u.db" 'SELECT count(*) FROM runs' 2>/dev/null || echo 0)" 0
keys Up Up C-u m F5
check "typed, m is the user's word: the run starts" '^ Run 1 '
wait_for_done() {
    local i=0
    while [ $i -lt $((POLLS * 4)) ]; do
        [ "$(sqlite3 "$WORK/u.db" 'SELECT status FROM runs WHERE id = 1' 2>/dev/null)" = done ] && return 0
        sleep 0.05
        i=$((i + 1))
    done
    return 1
}
wait_for_done || echo "not ok - the run in metres ends"
same "... read in metres, as asked (sqlite3)" \
    "$(sqlite3 "$WORK/u.db" 'SELECT units, status, options FROM runs WHERE id = 1')" "m|done|4"
keys F10
check_exit "F10 quits"
exit 0
