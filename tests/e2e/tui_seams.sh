#!/usr/bin/env bash
# End-to-end: a building's seams in the workbench (issue 31), driven in
# tmux, on the buildings of seams_faces.py whose seams are known by
# construction:
#   - the map by gap and by kink marks the seam joints where they lie: the
#     hinge's face A (x from -4 to 0) meets B along its last column, B
#     meets A along its first; flat panels on planes leave no gap and add
#     no kink, so under --max-gap 1 and --max-kink 10 every panel and seam
#     joint is at level 0: A's rows are 0s then =s, B's =s then 0s, the
#     =s exactly the characters a fitted picture of 4 columns gives the
#     seam's column (cols - floor(3 cols / 4));
#   - the cylinder's thirds, one face of 4 flat panels: its two rulings
#     are its first and last columns, each seam joint's gap (about 1 m,
#     sqlite3's seam_max_gap) over --max-gap 1: '!' at both ends, the
#     middle panels their own levels; the legend says what = and ! mean
#     and how many seam joints the surface has (3 for A: its 3 rows meet
#     B's 3; 2 for the third: one row at each ruling);
#   - the New run form's weld field: a bad weld (out of range, not a
#     number, without a module) refused with a one-line message and no
#     run made; the hinge 2 mm apart run from the form at weld 3 stores
#     runs.weld_mm 3 and finds the seam (1 seam, gap the design's 2 mm),
#     read with sqlite3;
#   - "like this" (L) on a building's option fills the form with the
#     run's files, the module one step either way, the surfaces' own
#     grids, the weld and the objectives; the run it starts stores them
#     (sqlite3), and its option of the same grids costs what the first
#     run's did.
# layers: tui
. "$(dirname "$0")/lib.sh"

. "$(dirname "$0")/tui_lib.sh"

if ! command -v sqlite3 >/dev/null; then
    echo "skip - every seams view check (sqlite3 is not installed)"
    exit 0
fi
HERE=$(cd "$(dirname "$0")" && pwd)
/usr/bin/python3 "$HERE/seams_faces.py" "$WORK" || exit 1
q() { sqlite3 -batch "$WORK/s.db" "$1"; }
"$FACET" optimize "$WORK/hinge.obj" --db "$WORK/s.db" --module 1:1x1:1 \
    --threshold 3 --max-gap 1 --max-kink 10 --table 0 >/dev/null 2>&1 || exit 1
"$FACET" optimize "$WORK/thirds.obj" --db "$WORK/s.db" --module 7:7x4:4 \
    --grid third1=2x1,third2=4x1 --max-panel-area 100 --threshold 5000 \
    --max-gap 1 --table 0 >/dev/null 2>&1 || exit 1

# rows PATTERN FIRST: checks the map's picture (the screen's lines from 2
# on, the part left of the legend) against python's closed form: every
# row's characters are runs described by FIRST: "0=" (0s, then the seam's
# =s over the last of 4 columns), "=0" (the first column's =s, then 0s),
# "!d!" (the first and last of 4 columns !, digits between).
rows() {
    screen | /usr/bin/python3 -c '
import re, sys
kind = sys.argv[1]
lines = sys.stdin.read().split("\n")[1:]
picture = []
for line in lines:
    m = re.match(r"^ ([0-9=!]+) ", line)
    if not m:
        break
    picture.append(m.group(1))
if not picture:
    sys.exit("no picture")
for row in picture:
    cols = len(row)
    last = cols - (3 * cols) // 4      # characters over column 4 of 4
    first = -(-cols // 4)              # over column 1 of 4
    if kind == "0=":
        want = "0" * (cols - last) + "=" * last
        ok = row == want
    elif kind == "=0":
        want = "=" * first + "0" * (cols - first)
        ok = row == want
    else:
        want = "!" * first + "[0-3]" + "{%d}" % (cols - first - last) + "!" * last
        ok = re.fullmatch(want, row) is not None
    if not ok:
        sys.exit("row %r, want %r" % (row, want))
print(len(picture))
' "$1"
}
check_rows() {
    local got i=0
    while [ $i -lt 40 ]; do
        if got=$(rows "$2" 2>&1); then pass "$1 ($got rows)"; return; fi
        sleep 0.1
        i=$((i + 1))
    done
    echo "not ok - $1: $got"
    screen | sed 's/^/  screen: /'
}

start 100 30 -- s.db
check "the runs list the two buildings" '^ +2 done +exhaustive'
keys Up Enter
check "run 1 (the hinge) opens" '^ Run 1 hinge\.obj'
keys Enter
check "the map shows surface A" 'surface 1 of 2: A \(4 x 3\)'
keys c c c
check "c c c: by worst gap" 'by worst gap'
check_rows "A by gap: 0s, its last column the seam's =s (no gap: level 0)" "0="
check "the legend says what = means, and A's 3 seam joints (3 rows meet 3)" \
    ' = seam joint: its gap, 3 here'
check "... and what ! means (a limit is set)" ' ! a seam joint over the limit'
# seam_max_gap is in mm (schema v16)
gap=$(q "select printf('%.2f', seam_max_gap) from options where run = 1")
check "the building's seams line, sqlite3's seam gap ($gap mm)" " building: 1 seams, $gap mm"
keys c
check "c: by worst kink" 'by worst kink'
check_rows "A by kink: the seam's =s, the kink added to the 30 degree crease 0" "0="
check "the legend: the kink added" ' = seam joint: kink added, 3 here'
keys ']'
check "] shows surface B" 'surface 2 of 2: B \(4 x 3\)'
check_rows "B by kink: its first column the seam's =s" "=0"
check "the cursor on B's seam panel names its seam joints" \
    'seam gap 0\.00 mm, kink \+0\.00 deg'
keys q q
check "back to the runs" '^ Facet runs'
keys Down Enter
check "run 2 (the cylinder's thirds) opens" '^ Run 2 thirds\.obj'
keys Enter
check "its map shows third0" 'surface 1 of 3: third0'
keys c c c ']' ']'
check "third2, by gap" 'surface 3 of 3: third2 \(4 x 1\) .*by worst gap'
over=$(q "select seam_gaps_over || ' ' || (seam_max_gap > 1) from options where run = 2")
if [ "$over" = "3 1" ]; then
    pass "sqlite3: the thirds' 3 seam joints are over the 1 mm gap limit"
else
    echo "not ok - sqlite3: the thirds' 3 seam joints are over the 1 mm gap limit ($over)"
fi
check_rows "third2 by gap: ! over both rulings (its first and last columns), its panels between" "!d!"
check "the legend: its 2 seam joints (one row at each ruling)" ' = seam joint: its gap, 2 here'
# a seam gap that is not 0, so that a unit slip shows: mm, as sqlite3 has it
gap=$(q "select printf('%.2f', seam_max_gap) from options where run = 2")
check "the thirds' seams line, sqlite3's seam gap ($gap mm, over the 1 mm limit)" \
    " building: [0-9]+ seams, ${gap//./\\.} mm"
keys q q

# The New run form's weld field (item 2).
runs_before=$(q "select count(*) from runs")
keys F7
check "F7 opens the New run form" '^ New run into'
check "the form has a weld field" '^ Seam weld \(mm\)'
keys C-u "hinge_apart.obj" Up Up Up Up Up C-u 3 F5
check "a weld without a module is refused, in one line" \
    "^new run: Seam weld \(mm\) is where a building's surfaces meet: it needs Module W x H \(m\)"
keys Down C-u "1:1x1:1" Up C-u "-1" F5
check "weld -1 is refused, the CLI's range" \
    '^new run: Seam weld \(mm\): -1 is out of range \(1e-06 to 100\)'
keys C-u "abc" F5
check "weld abc is refused" "^new run: Seam weld \(mm\): 'abc' is not a number"
keys C-u "1e9" F5
check "weld 1e9 is refused" '^new run: Seam weld \(mm\): 1e9 is out of range'
if [ "$(q "select count(*) from runs")" = "$runs_before" ]; then
    pass "no run made by a bad weld"
else
    echo "not ok - no run made by a bad weld"
fi
keys C-u 3 F5
check "weld 3 starts the building's run" '^ Run 3 hinge_apart\.obj .*done'
keys F10
check_exit "the workbench quits cleanly"
weld=$(q "select weld_mm from runs where id = 3")
if /usr/bin/python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) == 3 else 1)" "$weld" 2>/dev/null; then
    pass "sqlite3: the form's run stores runs.weld_mm = 3"
else
    echo "not ok - sqlite3: the form's run stores runs.weld_mm = 3 (got '$weld')"
fi
seam=$(q "select seams || ' ' || printf('%.6f', seam_max_gap) from options where run = 3")
if [ "$seam" = "1 2.000000" ]; then
    pass "... and finds the faces 2 mm apart within it: 1 seam, gap the design's 2 mm"
else
    echo "not ok - ... and finds the faces 2 mm apart within it: 1 seam, gap 2 mm (got '$seam')"
fi


# "Like this" on a building's option (issue 31 item 4): a run with a weld,
# its own grids and objectives that are not the defaults, from the CLI.
# Its one file of three objects has a comma in its name, which the form
# takes as that one file (a readable file is itself, commas and all).
cp "$WORK/thirds.obj" "$WORK/thirds,liked.obj"
"$FACET" optimize "$WORK/thirds,liked.obj" --db "$WORK/s.db" --module 6.5:7.5:0.5x4:4 \
    --grid third1=2x1,third2=4x1 --max-panel-area 100 --threshold 5000 \
    --max-gap 1 --weld 2.5 --objectives cost,moulds --name liked \
    --table 0 >/dev/null 2>&1 || exit 1
liked=$(q "select id from runs where name = 'liked'")
start 120 40 -- s.db
check "the runs list the liked run" "^ +$liked done .*liked"
check "the runs list has a weld column at 120 columns" '^ +id status .* elapsed weld mm started'
w=$(q "select printf('%g', weld_mm) from runs where id = $liked")
check "... and the liked run's weld in it, as sqlite3 has it ($w mm)" \
    "^ +$liked done .* s +${w//./\\.} 20[0-9][0-9]-"
keys End Enter
check "the liked run opens" "^ Run $liked liked"
keys L
check "L opens the New run form like the option" '^ New run into'
check "like this: the run's one file, its comma and all" "^ Surface \(OBJ\) +$WORK/thirds,liked\.obj\$"
check "like this: the module one step of the run either way (0.5 m; 0.1 m, its default)" \
    '^ Module W x H \(m\) +6:7:0\.5x3\.9:4\.1:0\.1$'
check "like this: the surfaces' own grids" '^ Surface grids +third1=2x1,third2=4x1$'
check "like this: the weld" '^ Seam weld \(mm\) +2\.5$'
check "like this: the objectives" '^ Objectives +cost,moulds$'
check "... and the form counts its modules (3 x 3) at 9 thresholds, not U x V" 'F5 starts: 81 options'
keys F5
check "the liked form's run starts" "^ Run $((liked + 1)) "
i=0
while [ $i -lt $((POLLS * 4)) ] &&
    [ "$(q "select status from runs where id = $((liked + 1))")" != done ]; do
    sleep 0.05; i=$((i + 1))
done
keys F10
check_exit "the workbench quits cleanly after the liked run"
same() {
    if [ "$2" = "$3" ]; then pass "$1"; else echo "not ok - $1 (want '$3', got '$2')"; fi
}
same "sqlite3: the liked run's weld, objectives and module range" \
    "$(q "select weld_mm, objectives, module_w_min, module_w_max, module_w_step, module_h_min, module_h_max, module_h_step from runs where id = $((liked + 1))")" \
    "2.5|cost,moulds|6.0|7.0|0.5|3.9|4.1|0.1"
same "sqlite3: the liked run's surfaces keep their own grids" \
    "$(q "select group_concat(name || '=' || coalesce(grid_nu || 'x' || grid_nv, '-'), ',') from surfaces where run = $((liked + 1))")" \
    "third0=-,third1=2x1,third2=4x1"
# Modules that give every surface the same grids are one option (the
# first of them stored): the liked option is the one of the same grids.
same "sqlite3: its option of the liked grids and threshold costs what the liked one did" \
    "$(q "select count(*) from options a join options b on b.run = $((liked + 1)) and b.threshold_mm = a.threshold_mm and b.cost = a.cost where a.run = $liked and a.number = 1 and (select group_concat(nu || 'x' || nv) from option_surfaces where run = a.run and option = a.number) = (select group_concat(nu || 'x' || nv) from option_surfaces where run = b.run and option = b.number)")" \
    1
