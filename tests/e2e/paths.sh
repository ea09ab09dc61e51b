#!/usr/bin/env bash
# End-to-end: a run's surface is found from any folder and after a move,
# and read-only commands neither create nor write a database (issue 12,
# items 1 and 4): the real binary, the real SQLite file, checked with
# sqlite3.
# layers: cli study
. "$(dirname "$0")/lib.sh"

mkdir -p "$WORK/project/surfaces" "$WORK/elsewhere" "$WORK/moved"
cd "$WORK/project" || exit 1
"$FACET" example plane --res 10 -o surfaces/p.obj || exit 1
"$FACET" optimize surfaces/p.obj --db runs.db --u 2:4 --v 2:3 >/dev/null 2>&1 || exit 1
same "the surface is recorded absolute" \
    "$(sqlite3 runs.db 'SELECT surface_path FROM runs WHERE id = 1')" "$WORK/project/surfaces/p.obj"
# An option whose panels are not stored needs the surface.
unstored=$(sqlite3 runs.db "SELECT min(number) FROM options WHERE run = 1 AND rank > 1")
cd "$WORK/elsewhere" || exit 1
expect "show from another folder" 0 "$FACET" show ../project/runs.db --run 1 --option "$unstored"
expect "export --obj from another folder" 0 "$FACET" export ../project/runs.db --run 1 --option 1 --obj a.obj
# An older file recorded the path as typed: found against the database's
# folder.
sqlite3 "$WORK/project/runs.db" "UPDATE runs SET surface_path = 'surfaces/p.obj'"
expect "a relative path resolves against the database's folder" 0 \
    "$FACET" export ../project/runs.db --run 1 --option 1 --obj b.obj
# Moved: one line that says what to do, and --surface re-points the run.
mv "$WORK/project/surfaces/p.obj" "$WORK/moved/p.obj"
expect_error "a moved surface: the message says --surface" 'no such file.*--surface FILE' \
    "$FACET" export ../project/runs.db --run 1 --option 1 --obj c.obj
"$FACET" example plane --res 11 -o "$WORK/moved/other.obj" || exit 1
expect_error "--surface with another file is refused by SHA-256" 'not run 1.s surface \(SHA-256' \
    "$FACET" export ../project/runs.db --run 1 --option 1 --obj c.obj --surface "$WORK/moved/other.obj"
expect "--surface re-points the run" 0 \
    "$FACET" export ../project/runs.db --run 1 --option 1 --obj c.obj --surface ../moved/p.obj
same "the new place is recorded, absolute" \
    "$(sqlite3 "$WORK/project/runs.db" 'SELECT surface_path FROM runs WHERE id = 1')" "$WORK/moved/p.obj"
expect "show --surface" 0 "$FACET" show ../project/runs.db --run 1 --option "$unstored" --surface "$WORK/moved/p.obj"
sqlite3 "$WORK/project/runs.db" "UPDATE runs SET status = 'interrupted', surface_path = '/nowhere/p.obj'"
expect "optimize --resume --surface" 0 "$FACET" optimize --db ../project/runs.db --resume 1 --surface "$WORK/moved/p.obj"
same "the resumed run is done" "$(sqlite3 "$WORK/project/runs.db" 'SELECT status FROM runs WHERE id = 1')" done
# A database copied with its surface beside it: found by name.
mkdir -p "$WORK/colleague"
cp "$WORK/project/runs.db" "$WORK/moved/p.obj" "$WORK/colleague/"
sqlite3 "$WORK/colleague/runs.db" "UPDATE runs SET surface_path = '/nowhere/p.obj'"
expect "a copied database finds its surface beside it" 0 \
    "$FACET" show "$WORK/colleague/runs.db" --run 1 --option "$unstored"

# Read-only commands on a typo: exit 2, one line, no file left behind.
cd "$WORK/elsewhere" || exit 1
missing='typo.db: No such file or directory \(no such database'
expect_error "facet runs of a missing database" "$missing" "$FACET" runs typo.db
expect_error "facet options of a missing database" "$missing" "$FACET" options typo.db
expect_error "facet plot of a missing database" "$missing" "$FACET" plot typo.db --run 1 -o x.svg
expect_error "facet show of a missing database" "$missing" "$FACET" show typo.db --run 1 --option 1
expect_error "facet export of a missing database" "$missing" "$FACET" export typo.db --run 1 --option 1 --csv x.csv
if ls typo.db* >/dev/null 2>&1; then fail "no database file was created"; else pass "no database file was created"; fi

# A read-only database in a read-only folder can be read, by a user who
# may not write there (root may write anywhere, so the checks run as
# nobody).
if [ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null; then
    as_reader() { setpriv --reuid=nobody --regid=nogroup --clear-groups "$@"; }
    mkdir -p "$WORK/ro"
    cp "$WORK/project/runs.db" "$WORK/ro/"
    sqlite3 "$WORK/ro/runs.db" "PRAGMA wal_checkpoint(TRUNCATE)" >/dev/null
    rm -f "$WORK/ro/runs.db-wal" "$WORK/ro/runs.db-shm"
    chmod 755 "$WORK"; chmod 444 "$WORK/ro/runs.db"; chmod 555 "$WORK/ro"
    before=$(sha256sum "$WORK/ro/runs.db" | cut -d' ' -f1)
    expect "runs on a read-only folder" 0 as_reader "$FACET" runs "$WORK/ro/runs.db"
    stdout_has "runs lists the run" '^ +1 +done'
    expect "options --json on a read-only folder" 0 as_reader "$FACET" options "$WORK/ro/runs.db" --json
    json_check "options: every option is read" "len(j) == $(sqlite3 "$WORK/project/runs.db" 'SELECT count(*) FROM options')"
    expect "show of a stored option on a read-only folder" 0 as_reader "$FACET" show "$WORK/ro/runs.db" --run 1 --option 1
    same "the read-only file is unchanged" "$(sha256sum "$WORK/ro/runs.db" | cut -d' ' -f1)" "$before"
    if ls "$WORK/ro"/runs.db-* >/dev/null 2>&1; then fail "no -wal or -shm file made"; else pass "no -wal or -shm file made"; fi
    expect_error "--surface on a read-only file says why" 'read-only here' \
        as_reader "$FACET" show "$WORK/ro/runs.db" --run 1 --option 1 --surface "$WORK/moved/p.obj"
    chmod 755 "$WORK/ro"; chmod 644 "$WORK/ro/runs.db"; chmod 700 "$WORK"
else
    skip "read-only folder checks" "they need root and setpriv to act as another user"
fi
exit 0
