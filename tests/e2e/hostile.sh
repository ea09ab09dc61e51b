#!/usr/bin/env bash
# End-to-end: hostile files, special paths, full disks and overflow (issue
# 14): every case is refused in one line with a non-zero exit, or written
# where it should be, and nothing outside the command's own files changes.
# layers: cli study store
. "$(dirname "$0")/lib.sh"

"$FACET" example plane --res 8 -o "$WORK/p.obj" || exit 1
"$FACET" optimize "$WORK/p.obj" --db "$WORK/r.db" --u 2:3 --v 2:3 >/dev/null 2>&1 || exit 1

# 1. A NUL byte in a name past the first 4 KB: FILE:LINE:, no crash.
/usr/bin/python3 - "$WORK/nul.obj" <<'PY'
import sys
body = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" * 20000
open(sys.argv[1], "wb").write(b"o abc\n" + body + b"o abc\x00def\nf 1 2 3\n")
PY
line=$((1 + 80000 + 1))
expect_error "NUL in an o name past 4 KB: info says FILE:LINE" "nul.obj:$line: a NUL byte" \
    "$FACET" info "$WORK/nul.obj"
expect_error "NUL in an o name past 4 KB: classify says FILE:LINE" "nul.obj:$line: a NUL byte" \
    "$FACET" classify "$WORK/nul.obj" --grid 2x2

# 2. Special paths as outputs.
before=$(stat -c '%F %t:%T' /dev/full)
run "$FACET" export "$WORK/r.db" --run 1 --option 1 --csv /dev/full --force
same "--csv /dev/full --force: exit 1 and the write error in one line" \
    "$STATUS $(wc -l <"$ERR") $(grep -c 'writing /dev/full failed: No space left on device' "$ERR")" "1 1 1"
same "/dev/full is still the device" "$(stat -c '%F %t:%T' /dev/full)" "$before"
run "$FACET" export "$WORK/r.db" --run 1 --option 1 --csv -
same "--csv - writes the schedule to stdout" "$(head -c 8 "$OUT")" "id,i,j,c"
if grep -q '^wrote' "$OUT"; then fail "--csv -: 'wrote' goes to stderr, not into the CSV"; else pass "--csv -: 'wrote' goes to stderr, not into the CSV"; fi
got=$("$FACET" export "$WORK/r.db" --run 1 --option 1 --csv /dev/stdout 2>/dev/null | head -c 8)
same "--csv /dev/stdout writes into the pipe (no --force needed)" "$got" "id,i,j,c"
ln -s "$WORK/target.csv" "$WORK/link.csv"
expect_error "a symbolic link is not replaced" 'link.csv is a symbolic link' \
    "$FACET" export "$WORK/r.db" --run 1 --option 1 --csv "$WORK/link.csv" --force
if [ -L "$WORK/link.csv" ] && [ ! -e "$WORK/target.csv" ]; then pass "the link is still a link"; else fail "the link is still a link"; fi
mkdir "$WORK/dir.csv"
expect_error "a directory is not replaced" 'dir.csv is a directory' \
    "$FACET" export "$WORK/r.db" --run 1 --option 1 --csv "$WORK/dir.csv" --force
mkfifo "$WORK/out.fifo"
run timeout 20 "$FACET" export "$WORK/r.db" --run 1 --option 1 --csv "$WORK/out.fifo"
same "a FIFO with no reader is refused at once" "$STATUS $(grep -c 'a FIFO with no reader' "$ERR")" "2 1"
( cat "$WORK/out.fifo" > "$WORK/from.fifo" ) & reader=$!
sleep 0.2
run timeout 20 "$FACET" export "$WORK/r.db" --run 1 --option 1 --csv "$WORK/out.fifo"
wait $reader
same "a FIFO with a reader gets the schedule" "$STATUS $(head -c 8 "$WORK/from.fifo")" "0 id,i,j,c"
expect_error "--obj to a stream is refused (its MTL has no place)" 'needs its MTL' \
    "$FACET" export "$WORK/r.db" --run 1 --option 1 --obj -

# 3. Inputs that never end or wait for a writer: refused, never a hang.
mkfifo "$WORK/in.fifo"
for input in /dev/zero /dev/urandom "$WORK/in.fifo"; do
    for cmd in "info" "classify --grid 2x2" "optimize --db $WORK/never.db --u 2:2 --v 2:2"; do
        # shellcheck disable=SC2086
        run timeout 20 "$FACET" ${cmd%% *} "$input" ${cmd#* }
        [ "$cmd" = info ] && run timeout 20 "$FACET" info "$input"
        if [ "$STATUS" -eq 2 ] && grep -q 'not a regular file' "$ERR"; then
            pass "$(basename "$input") as input to ${cmd%% *}: refused at once"
        else
            fail "$(basename "$input") as input to ${cmd%% *}: refused at once"
        fi
    done
done
if [ -e "$WORK/never.db" ]; then fail "no database made for an input refused"; else pass "no database made for an input refused"; fi
# 11 (round 3). A database that is a device or a FIFO is refused, and no
# journal is made beside it (as root, --db /dev/null made /dev/null-journal;
# here a device node of /dev/null's numbers in $WORK stands for it).
mkfifo "$WORK/db.fifo"
devices=("$WORK/db.fifo")
if [ "$(id -u)" -eq 0 ] && mknod "$WORK/null" c 1 3 2>/dev/null; then
    devices+=("$WORK/null")
else
    skip "--db on a device node" "mknod needs root"
fi
for db in "${devices[@]}"; do
    run timeout 20 "$FACET" optimize "$WORK/p.obj" --db "$db" --u 2:2 --v 2:2
    same "--db $(basename "$db"): refused in one line (2), no journal beside it" \
        "$STATUS $(grep -c 'not a regular file, not a database' "$ERR") $(wc -l <"$ERR") $(ls "$WORK" | grep -c "^$(basename "$db")-")" \
        "2 1 1 0"
done
cp "$WORK/r.db" "$WORK/moved.db"
sqlite3 "$WORK/moved.db" "UPDATE runs SET status = 'interrupted', surface_path = '/dev/zero'"
run timeout 20 "$FACET" optimize --db "$WORK/moved.db" --resume 1
same "--resume of a run whose surface is /dev/zero: refused, no hang" "$STATUS" 2

# 4. Write errors on stdout are failures.
for cmd in "options $WORK/r.db --csv" "options $WORK/r.db --json" "runs $WORK/r.db" \
           "info $WORK/p.obj --json" "show $WORK/r.db --run 1 --option 1 --json"; do
    # shellcheck disable=SC2086
    "$FACET" $cmd >/dev/full 2>"$ERR"
    STATUS=$?
    if [ "$STATUS" -eq 1 ] && grep -q 'writing standard output failed: No space left on device' "$ERR"; then
        pass "${cmd%% *} > /dev/full: exit 1, one line"
    else
        fail "${cmd%% *} > /dev/full: exit 1, one line"
    fi
done
"$FACET" optimize "$WORK/p.obj" --db "$WORK/full.db" --u 2:2 --v 2:2 >/dev/full 2>"$ERR"
same "the optimize table on /dev/full: exit 1" "$?" 1

# 7. Numbers as written, never wrapped or read in another base.
expect_error "--grid 4294967297x5" 'out of range' "$FACET" classify "$WORK/p.obj" --grid 4294967297x5
expect_error "--u 4294967297:4294967300" 'out of range' "$FACET" optimize "$WORK/p.obj" --db "$WORK/o.db" --u 4294967297:4294967300
expect_error "--threshold 0:1e6:1e-300: the step count" 'steps \(at most 1000000' "$FACET" optimize "$WORK/p.obj" --db "$WORK/o.db" --threshold 0:1e6:1e-300
expect_error "--threshold 0x10 (optimize)" "'0x10' is not" "$FACET" optimize "$WORK/p.obj" --db "$WORK/o.db" --threshold 0x10
expect_error "--threshold 0x10 (classify)" "'0x10' is not a number" "$FACET" classify "$WORK/p.obj" --grid 2x2 --threshold 0x10
expect_error "--seed past 2^63" 'out of range' "$FACET" optimize "$WORK/p.obj" --db "$WORK/o.db" --seed 18446744073709551617
if [ -e "$WORK/o.db" ]; then fail "no database made for a bad number"; else pass "no database made for a bad number"; fi

# 8. A negative user_version: refused, the file untouched.
cp "$WORK/r.db" "$WORK/neg.db"
sqlite3 "$WORK/neg.db" "PRAGMA user_version = -1"
sum=$(sha256sum "$WORK/neg.db")
expect_error "user_version -1 is refused" 'schema version -1' "$FACET" runs "$WORK/neg.db"
expect_error "user_version -1 is refused by a writer too" 'schema version -1' "$FACET" optimize "$WORK/p.obj" --db "$WORK/neg.db"
same "the file is untouched" "$(sha256sum "$WORK/neg.db")" "$sum"

# 10, 11. Run names: escape codes never reach the terminal; a name is kept
# whole or refused, never cut inside a character.
expect_error "a name with an escape code is refused" 'not clean UTF-8' \
    "$FACET" optimize "$WORK/p.obj" --db "$WORK/n.db" --name "$(printf 'a\033]0;pwned\007b')"
expect_error "a name of 140 bytes is refused, not cut" 'at most 127' \
    "$FACET" optimize "$WORK/p.obj" --db "$WORK/n.db" --name "$(printf 'é%.0s' $(seq 70))"
cp "$WORK/r.db" "$WORK/esc.db"
sqlite3 "$WORK/esc.db" "UPDATE runs SET name = 'x' || char(27) || '[2J' || char(7) || 'y', surface_path = '/tmp/' || char(27) || ']0;t' || char(7)"
for cmd in runs "show --run 1 --option 1"; do
    # shellcheck disable=SC2086
    run "$FACET" ${cmd%% *} "$WORK/esc.db" ${cmd#runs}
    if grep -q $'\033\|\007' "$OUT"; then fail "facet ${cmd%% *}: no escape code printed"; else pass "facet ${cmd%% *}: no escape code printed"; fi
done
run "$FACET" runs "$WORK/esc.db" --json
json_check "runs --json: the name as stored, escaped by JSON" 'j[0]["name"] == "x\x1b[2J\x07y"'
# 7 (round 3). Every byte Facet did not write (OBJ names and tokens, stored
# warnings, SQLite's and a trigger's messages) is cleaned on its way to a
# terminal, and JSON is valid UTF-8: no ESC or BEL, no byte that is not
# UTF-8, no second line forged by a newline.
shown_clean() {  # shown_clean NAME: the last run's stdout and stderr
    if /usr/bin/python3 -c '
import sys
for path in sys.argv[1:]:
    data = open(path, "rb").read()
    data.decode("utf-8")
    if b"\x1b" in data or b"\x07" in data:
        sys.exit(1)' "$OUT" "$ERR" 2>/dev/null; then
        pass "$1"
    else
        fail "$1 (an ESC, BEL or a byte that is not UTF-8 was printed)"
    fi
}
json_utf8() {  # json_utf8 NAME: the last run's stdout is JSON in strict UTF-8
    if /usr/bin/python3 -c 'import json, sys; json.loads(open(sys.argv[1], "rb").read().decode("utf-8"))' "$OUT" 2>/dev/null; then
        pass "$1"
    else
        fail "$1 (not JSON in valid UTF-8)"
    fi
}
/usr/bin/python3 - "$WORK" <<'PY'
import sys
work = sys.argv[1]
esc = b"\x1b]0;pwned\x07"
square = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
with open(work + "/names.obj", "wb") as f:
    f.write(b"o a" + esc + b"\xff\ng g" + esc + b"\xfe\nusemtl m" + esc +
            b"\xff\n" + square + b"f 1 2 3\nf 2 4 3\n")
with open(work + "/token.obj", "wb") as f:
    f.write(square + b"f 1 2 3\nv 1 x" + esc + b"\xff 0\n")
# a project: two objects on a 3 x 3 grid each, with vt
body, n = b"", 0
for k, name in enumerate([b"p" + esc + b"\xff", b"q\xff" + esc]):
    body += b"o " + name + b"\n"
    for y in range(3):
        for x in range(3):
            body += b"v %d %d 0\nvt %g %g\n" % (x + 10 * k, y, x / 2, y / 2)
    for y in range(2):
        for x in range(2):
            a = n + y * 3 + x + 1
            body += b"f %d/%d %d/%d %d/%d %d/%d\n" % (a, a, a + 1, a + 1, a + 4, a + 4, a + 3, a + 3)
    n += 9
with open(work + "/names-project.obj", "wb") as f:
    f.write(body)
PY
run "$FACET" info "$WORK/names.obj"
shown_clean "info: object, group and material names shown, not obeyed"
run "$FACET" info "$WORK/names.obj" --json
json_utf8 "info --json: names with bytes not UTF-8 still make valid JSON"
shown_clean "info --json: no ESC or BEL raw in the JSON"
expect_error "a bad token in the OBJ: quoted in one line" 'token.obj:6: number does not parse' \
    "$FACET" info "$WORK/token.obj"
shown_clean "a bad token in the OBJ: quoted, not obeyed"
run "$FACET" info "$WORK/names-project.obj"
shown_clean "info of a project: surface names shown, not obeyed"
run "$FACET" info "$WORK/names-project.obj" --json
json_utf8 "info --json of a project: valid JSON in UTF-8"
"$FACET" optimize "$WORK/names-project.obj" --db "$WORK/names.db" --module 0.5:1x0.5:1 >/dev/null 2>&1
run "$FACET" options "$WORK/names.db" --surfaces --json
json_utf8 "options --surfaces --json of a project: valid JSON in UTF-8"
run "$FACET" options "$WORK/names.db" --surfaces
shown_clean "options --surfaces of a project: names shown, not obeyed"
cp "$WORK/r.db" "$WORK/warn.db"
sqlite3 "$WORK/warn.db" "UPDATE runs SET warnings = 'w' || char(27) || ']0;pwned' || char(7) || ' ' || CAST(X'FF' AS TEXT) || char(10) || 'second'"
run "$FACET" runs "$WORK/warn.db"
shown_clean "runs: stored warnings shown, not obeyed"
run "$FACET" runs "$WORK/warn.db" --json
json_utf8 "runs --json: stored warnings make valid JSON in UTF-8"
cp "$WORK/r.db" "$WORK/trigger.db"
# A trigger is refused before it can fire (hostile_store.sh), by its name,
# which the file chose.
sqlite3 "$WORK/trigger.db" "UPDATE runs SET status = 'interrupted'; $(printf "CREATE TRIGGER \"x\033[2J\nforged\" BEFORE UPDATE ON runs BEGIN SELECT RAISE(ABORT, 'x'); END")"
run "$FACET" optimize --db "$WORK/trigger.db" --resume 1
same "a trigger's name: the error in one line (2)" \
    "$STATUS $(wc -l <"$ERR") $(grep -c 'x?\[2J?forged' "$ERR")" "2 1 1"
shown_clean "a trigger's name: shown, not obeyed"
cp "$WORK/r.db" "$WORK/path.db"
sqlite3 "$WORK/path.db" "UPDATE runs SET status = 'interrupted', surface_path = '/nonexistent/' || char(27) || ']0;t' || char(7) || CAST(X'FF' AS TEXT) || '.obj'"
run "$FACET" optimize --db "$WORK/path.db" --resume 1
shown_clean "an error naming a stored path: shown, not obeyed"
# 5. Two --resume of one run at once: one goes on, the other is refused,
# naming the first (pid, host); the run ends with all its options.
"$FACET" example roof --res 160 -o "$WORK/roof.obj" || exit 1
"$FACET" optimize "$WORK/roof.obj" --db "$WORK/two.db" --u 4:9 --v 4:9 >/dev/null 2>&1 || exit 1
total=$(sqlite3 "$WORK/two.db" "SELECT count(*) FROM options")
sqlite3 "$WORK/two.db" "DELETE FROM options WHERE number > 10; UPDATE runs SET status = 'interrupted'"
"$FACET" optimize --db "$WORK/two.db" --resume 1 >"$WORK/a.out" 2>"$WORK/a.err" & a=$!
"$FACET" optimize --db "$WORK/two.db" --resume 1 >"$WORK/b.out" 2>"$WORK/b.err" & b=$!
wait $a; sa=$?
wait $b; sb=$?
refused=$(cat "$WORK/a.err" "$WORK/b.err" | grep -c 'is being written by process [0-9]* on ')
same "two resumes at once: one goes on (0), one is refused (2), naming the other" \
    "$(printf '%s\n' $sa $sb | sort | paste -sd' ') $refused" "0 2 1"
same "the run ends done with every option" \
    "$(sqlite3 "$WORK/two.db" "SELECT status, options FROM runs")" "done|$total"
# 9 (round 3). Two --resume of a run whose writer died (still "running")
# at once: the orphan is found and marked inside the write transaction,
# so one claims it and the other is refused, every time (before: both
# went on in 14 of 20 trials here).
fixture four.obj || exit 1
"$FACET" optimize "$WORK/four.obj" --db "$WORK/orph.db" --module 1:3:0.5x1:3:0.5 \
    --threshold 3 --table 0 >/dev/null 2>&1 || exit 1
all=$(sqlite3 "$WORK/orph.db" "SELECT count(*) FROM options")
outcomes=
for trial in 1 2 3 4 5 6 7 8 9 10; do
    cp "$WORK/orph.db" "$WORK/orph-$trial.db"
    sqlite3 "$WORK/orph-$trial.db" "DELETE FROM option_surfaces WHERE option > 3; DELETE FROM options WHERE number > 3; UPDATE runs SET status = 'running', writer_pid = 2147483646, writer_host = '$(hostname)'"
    "$FACET" optimize --db "$WORK/orph-$trial.db" --resume 1 --table 0 >/dev/null 2>"$WORK/oa.err" & a=$!
    "$FACET" optimize --db "$WORK/orph-$trial.db" --resume 1 --table 0 >/dev/null 2>"$WORK/ob.err" & b=$!
    wait $a; sa=$?
    wait $b; sb=$?
    outcomes="$outcomes $(printf '%s\n' $sa $sb | sort | paste -sd,)/$(sqlite3 "$WORK/orph-$trial.db" 'SELECT status, options FROM runs')"
done
same "two resumes of an orphaned project run, 10 trials: one goes on, one is refused, the run done whole" \
    "$outcomes" "$(for _ in 1 2 3 4 5 6 7 8 9 10; do printf ' 0,2/done|%s' "$all"; done)"
# 9. A writer that ends leaves no WAL behind (truncated to 0 bytes). Any
# run will do: its last write (the run done) is in the WAL until the
# writer, leaving, truncates it (store_close), whatever the run's size.
"$FACET" optimize "$WORK/p.obj" --db "$WORK/wal.db" --u 2:4 --v 2:4 >/dev/null 2>&1
same "after a run the -wal is empty" "$(stat -c %s "$WORK/wal.db-wal")" 0

# 12. Signals in every phase: SIGHUP while evaluating, SIGINT while the
# front's panels are stored; each leaves the run resumable with 128 +
# the signal, and the resumed run is done with its panels.
wait_for() {  # wait_for SQL VALUE: until sqlite3 says VALUE (30 s at most)
    for _ in $(seq 300); do
        [ "$(sqlite3 "$WORK/sig.db" "$1" 2>/dev/null)" = "$2" ] && return 0
        sleep 0.1
    done
    return 1
}
rm -f "$WORK/sig.db"*
"$FACET" optimize "$WORK/roof.obj" --db "$WORK/sig.db" --u 20:200 --v 20:30 --jobs 1 >/dev/null 2>&1 & pid=$!
wait_for "SELECT options > 0 FROM runs" 1
kill -HUP $pid; wait $pid; status=$?
same "SIGHUP while evaluating: exit 129, the run interrupted" \
    "$status $(sqlite3 "$WORK/sig.db" 'SELECT status FROM runs')" "129 interrupted"
rm -f "$WORK/sig.db"*
# One grid at 41 thresholds: 24 Pareto options of 10,000 panels each, more
# than the run's budget of 16 (so the resume below meets the cap), to
# store in the final phase, in chunks a stop is heard between. The phase
# takes seconds in the release build (8 s on a loaded machine); the 200 x
# 200 grid at 21 thresholds it was (19 Pareto of 40,000 panels) made a
# file of 217 MB and cost three times the CPU for the same checks.
"$FACET" optimize "$WORK/roof.obj" --db "$WORK/sig.db" --u 100:100 --v 100:100 --threshold 0:10:0.25 --jobs 1 >/dev/null 2>&1 & pid=$!
if wait_for "SELECT count(*) FROM options" 41; then
    kill -INT $pid; wait $pid; status=$?
    stored=$(sqlite3 "$WORK/sig.db" "SELECT count(*) FROM panel_sets")
    pareto=$(sqlite3 "$WORK/sig.db" "SELECT count(*) FROM options WHERE rank = 1")
    same "SIGINT after the last batch: exit 130, interrupted, not every front panel stored" \
        "$status $(sqlite3 "$WORK/sig.db" 'SELECT status FROM runs') $([ "$stored" -lt "$pareto" ] && echo partial)" \
        "130 interrupted partial"
    expect "the interrupted final phase resumes" 0 "$FACET" optimize --db "$WORK/sig.db" --resume 1
    # every Pareto option's up to the run's budget, max(16, options / 40)
    same "resumed: done, the Pareto options' panels stored" \
        "$(sqlite3 "$WORK/sig.db" "SELECT status FROM runs") $(sqlite3 "$WORK/sig.db" "SELECT count(*) FROM panel_sets") " \
        "done $(sqlite3 "$WORK/sig.db" "SELECT min(count(*) FILTER (WHERE rank = 1), max(16, count(*) / 40)) FROM options") "
else
    fail "the fine run reached its final phase"
    kill $pid 2>/dev/null
fi
# 13 and a full disk: a small tmpfs (where this machine lets root mount
# one). A run that cannot fit is refused before any work, with the
# figures; a front's panels that cannot fit are not stored, and it says
# so; a disk that fills mid-run fails the run in one line, the file intact
# and resumable; an export that fills it leaves no partial file.
disk=$WORK/disk
mkdir -p "$disk"
if [ "$(id -u)" -eq 0 ] && mount -t tmpfs -o size=400k tmpfs "$disk" 2>/dev/null; then
    expect_error "a run too large for the disk is refused with the figures" \
        "the run's 1369 options need about [0-9.]+ [kM]B and its disk has [0-9.]+ kB free" \
        "$FACET" optimize "$WORK/p.obj" --db "$disk/big.db" --u 4:40 --v 4:40
    rm -f "$disk"/big.db*
    run "$FACET" optimize "$WORK/roof.obj" --db "$disk/full.db" --u 4:15 --v 4:15
    same "a disk that fills mid-run: exit 1, one line naming it" \
        "$STATUS $(grep -c 'database or disk is full' "$ERR")" "1 1"
    same "the file is intact, the run failed and resumable" \
        "$(sqlite3 "$disk/full.db" 'PRAGMA quick_check; SELECT status FROM runs')" "$(printf 'ok\nfailed')"
    rm -f "$disk"/full.db*
    "$FACET" optimize "$WORK/p.obj" --db "$WORK/ex.db" --u 60:60 --v 60:60 >/dev/null 2>&1
    run "$FACET" export "$WORK/ex.db" --run 1 --option 1 --obj "$disk/x.obj"
    same "an export that fills the disk: exit 1, no file left" \
        "$STATUS $(ls "$disk" | wc -l)" "1 0"
    umount "$disk"
    # A front of about 10 MB (3 options of 10,000 panels) on a disk of 2 MB:
    # five times what the disk holds, at a sixteenth of the panels of the
    # 154 MB on 8 MB it was.
    if mount -t tmpfs -o size=2m tmpfs "$disk" 2>/dev/null; then
        run "$FACET" optimize "$WORK/p.obj" --db "$disk/panels.db" --u 100:100 --v 100:102 --threshold 3
        same "a front too large for the disk: done, said, not stored" \
            "$STATUS $(grep -c "front's panels need about .* free: none are stored" "$ERR") $(sqlite3 "$disk/panels.db" 'SELECT status FROM runs; SELECT count(*) FROM panel_sets' | paste -sd' ')" \
            "0 1 done 0"
        umount "$disk"
    fi
    # Round 3, item 1: facet merge into a nearly full disk. Its copy's last
    # checkpoint failed unheard, the WAL that held the data was deleted and
    # the broken copy renamed over an OUT.db holding another run (exit 0,
    # quick_check failing, at 2100, 2400 and 4500 kB here). Now at every
    # size: done and whole (quick_check ok, both runs), or refused with
    # OUT.db exactly as it was, and no copy left.
    for i in 1 2 3; do
        "$FACET" optimize "$WORK/p.obj" --db "$WORK/ms$i.db" --u 2:30 --v 2:30 \
            --threshold 1:3:1 --shard $i/3 --table 0 >/dev/null 2>&1 || exit 1
    done
    "$FACET" optimize "$WORK/p.obj" --db "$WORK/mo.db" --u 2:12 --v 2:12 --table 0 >/dev/null 2>&1 || exit 1
    sum=$(sha256sum <"$WORK/mo.db")
    outcomes=
    for kb in 1200 1800 2100 2400 2700 3300 4500 5000; do
        mount -t tmpfs -o size=${kb}k tmpfs "$disk" 2>/dev/null || break
        cp "$WORK/mo.db" "$disk/out.db"
        run "$FACET" merge "$disk/out.db" "$WORK/ms1.db" "$WORK/ms2.db" "$WORK/ms3.db"
        check=$(sqlite3 "$disk/out.db" 'PRAGMA quick_check; SELECT count(*) FROM runs' 2>&1 | paste -sd' ')
        if [ "$STATUS" -eq 0 ] && [ "$check" = "ok 2" ] && [ "$(ls "$disk")" = out.db ]; then
            outcomes="$outcomes $kb:merged"
        elif [ "$STATUS" -ne 0 ] && [ "$(sha256sum <"$disk/out.db")" = "$sum" ] &&
            [ "$(ls "$disk")" = out.db ]; then
            outcomes="$outcomes $kb:refused"
        else
            outcomes="$outcomes $kb:BROKEN"
            echo "# $kb kB: status $STATUS, $(echo "$check" | cut -c1-120), left: $(ls "$disk" | paste -sd,)"
        fi
        umount "$disk"
    done
    same "merge into a nearly full disk, 8 sizes: merged whole or refused, OUT.db intact" \
        "$(echo "$outcomes" | grep -o BROKEN | wc -l) $(echo "$outcomes" | wc -w)" "0 8"
    echo "#$outcomes"
else
    skip "full-disk checks" "they need root to mount a small tmpfs"
fi
# 13. Storing fewer panels when asked: the knee's only, or none.
for keep in knee none; do
    "$FACET" optimize "$WORK/roof.obj" --db "$WORK/keep-$keep.db" --u 4:12 --v 4:12 --store-panels $keep \
        --max-panel-area 1000 >/dev/null 2>&1
    same "--store-panels $keep: recorded, and the panels stored are the knee's or none" \
        "$(sqlite3 "$WORK/keep-$keep.db" "SELECT store_panels FROM runs; SELECT count(*) FROM panel_sets; SELECT count(*) FROM panel_sets s JOIN options o ON o.run = s.run AND o.number = s.option WHERE o.knee")" \
        "$(printf '%s\n%s\n%s' $keep $([ $keep = knee ] && echo '1 1' || echo '0 0'))"
done
# 14. Absurd coordinates: a surface at 7e14 m is refused with the reason;
# one at UTM-like site coordinates (5e5, 5e6 m, 0.1 m facets) is panelized
# with its areas adding up to 1e-9.
/usr/bin/python3 - "$WORK" <<'PY'
import sys
def grid(path, x0, y0, h):
    with open(path, "w") as f:
        for j in range(11):
            for i in range(11):
                f.write("v %.17g %.17g 0\n" % (x0 + i * h, y0 + j * h))
        for j in range(10):
            for i in range(10):
                a = j * 11 + i + 1
                f.write("f %d %d %d %d\n" % (a, a + 1, a + 12, a + 11))
grid(sys.argv[1] + "/far.obj", 7e14, 7e14, 1.0)
grid(sys.argv[1] + "/site.obj", 5e5, 5e6, 0.1)
PY
expect_error "a surface at 7e14 m is refused with the reason" \
    'coordinates reach 7e\+14 m.*move the surface near the origin' "$FACET" classify "$WORK/far.obj" --grid 3x3
expect "a surface at site coordinates is panelized" 0 "$FACET" classify "$WORK/site.obj" --grid 7x7 --json
json_check "site coordinates: panel areas add up to the mesh's (1e-9)" \
    'abs(sum(p["area"] for p in j["panels"]) - j["surface"]["area"]) < 1e-9 * j["surface"]["area"]'
# Repeated kill -9 at random moments: every resume goes on, and the run
# ends with exactly the options of an uninterrupted one (compared with
# sqlite3: every column of every option but the run's id). The roof at 40
# x 40 quads: its 1,369 options take seconds, not the tens of seconds of
# the 160 x 160 roof, and the kills land as often between them.
fixture roof40.obj || exit 1
"$FACET" optimize "$WORK/roof40.obj" --db "$WORK/whole.db" --u 4:40 --v 4:40 --jobs 1 >/dev/null 2>&1
stored() { sqlite3 "$WORK/killed.db" "SELECT count(*) FROM options" 2>/dev/null || echo 0; }
kills=0
"$FACET" optimize "$WORK/roof40.obj" --db "$WORK/killed.db" --u 4:40 --v 4:40 --jobs 1 >/dev/null 2>&1 & pid=$!
for k in 1 2 3 4 5 6 7 8; do
    before=$(stored)
    for _ in $(seq 100); do [ "$(stored)" -gt "$before" ] && break; sleep 0.05; done
    sleep "0.$((RANDOM % 3))$((RANDOM % 10))"
    kill -KILL $pid 2>/dev/null && kills=$((kills + 1))
    wait $pid 2>/dev/null
    [ "$(sqlite3 "$WORK/killed.db" 'SELECT status FROM runs')" = done ] && break
    "$FACET" optimize --db "$WORK/killed.db" --resume 1 >/dev/null 2>&1 & pid=$!
done
wait $pid 2>/dev/null
[ "$(sqlite3 "$WORK/killed.db" 'SELECT status FROM runs')" = done ] ||
    "$FACET" optimize --db "$WORK/killed.db" --resume 1 >/dev/null 2>&1
dump() { sqlite3 "$1" "SELECT * FROM options ORDER BY number" | cut -d'|' -f2- | sha256sum; }
same "after $kills kill -9s and resumes the run equals an uninterrupted one" \
    "$(sqlite3 "$WORK/killed.db" 'PRAGMA quick_check; SELECT status FROM runs' | paste -sd' ') $(dump "$WORK/killed.db")" \
    "ok done $(dump "$WORK/whole.db")"

# A run of many options stores them with its indexes by metric dropped,
# and is killed with kill -9 meanwhile: the file is whole (quick_check),
# the run reads as interrupted, and resumed it ends with every option and
# every index (SQLite's own schema table counts them).
"$FACET" example roof --res 8 -o "$WORK/small.obj" || exit 1
indexes() { sqlite3 "$WORK/bulk.db" "SELECT count(*) FROM sqlite_schema WHERE type = 'index' AND tbl_name = 'options'"; }
bulk() { sqlite3 "$WORK/bulk.db" "SELECT count(*) FROM options" 2>/dev/null || echo 0; }
many=(--method random --evals 60000 --u 1:6 --v 1:6 --threshold 1:5 --jobs 1)
"$FACET" optimize "$WORK/small.obj" --db "$WORK/bulk.db" "${many[@]}" >/dev/null 2>&1 & pid=$!
for _ in $(seq 1200); do [ "$(bulk)" -gt 2000 ] && break; sleep 0.05; done
during=$(indexes)
kill -KILL $pid 2>/dev/null; wait $pid 2>/dev/null
same "a run of 60,000 options stores them with the index by rank alone" "$during" 1
same "killed meanwhile, the file is whole" "$(sqlite3 "$WORK/bulk.db" 'PRAGMA quick_check')" ok
run "$FACET" runs "$WORK/bulk.db"
stdout_has "killed meanwhile, the run reads as interrupted" interrupted
expect "the killed run resumes to its end" 0 "$FACET" optimize --db "$WORK/bulk.db" --resume 1
same "resumed, it ends done with its 60,000 options, every index and a whole file" \
    "$(sqlite3 "$WORK/bulk.db" 'SELECT status, options FROM runs; PRAGMA quick_check' | paste -sd' ') $(indexes)" \
    "done|60000 ok 14"
exit 0
