# lib.sh: helpers for the end-to-end scripts, which run the real facet
# binary ($FACET) and print one "ok - NAME" or "not ok - NAME" line per check.
# Each script sources this file; tests/run.py counts the lines.

FACET=${FACET:?set FACET to the facet binary}
FACET_DATA=${FACET_DATA:-../shared/data}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
OUT=$WORK/stdout
ERR=$WORK/stderr

# run CMD...: runs a command, keeping its stdout, stderr and status.
run() {
    "$@" >"$OUT" 2>"$ERR"
    STATUS=$?
}

pass() { echo "ok - $1"; }
# skip NAME WHY: a check that could not run here; tests/run.py counts it
# apart, never as passed.
skip() { echo "skip - $1 ($2)"; }

# have_data FILE...: 0 when every FILE is in $FACET_DATA (the real surfaces
# of ../shared/data), else prints a skip line naming what is missing and
# returns 1. A clone of the project without ../shared runs everything else.
have_data() {
    local f
    for f in "$@"; do
        if [ ! -r "$FACET_DATA/$f" ]; then
            skip "checks on $f" "$FACET_DATA/$f is absent"
            return 1
        fi
    done
    return 0
}
fail() {
    echo "not ok - $1"
    echo "  status: $STATUS"
    sed 's/^/  stdout: /' "$OUT" | head -n 20
    sed 's/^/  stderr: /' "$ERR" | head -n 20
}

# expect NAME STATUS CMD...: the command exits with STATUS.
expect() {
    local name=$1 want=$2
    shift 2
    run "$@"
    if [ "$STATUS" -eq "$want" ]; then pass "$name"; else fail "$name (want status $want)"; fi
}

# expect_error NAME PATTERN CMD...: exits 2 with one stderr line matching
# PATTERN (grep -E) and nothing that looks like a crash.
expect_error() {
    local name=$1 pattern=$2
    shift 2
    run "$@"
    if [ "$STATUS" -eq 2 ] && [ "$(wc -l <"$ERR")" -eq 1 ] &&
        grep -qE "$pattern" "$ERR"; then
        pass "$name"
    else
        fail "$name (want status 2 and one line matching: $pattern)"
    fi
}

# stdout_has NAME PATTERN: the last run's stdout matches PATTERN.
stdout_has() {
    if grep -qE -- "$2" "$OUT"; then pass "$1"; else fail "$1 (stdout lacks: $2)"; fi
}

# json_check NAME PYTHON_EXPR: evaluates a Python expression over the last
# run's stdout parsed as JSON (bound to j); passes when it is true.
json_check() {
    if /usr/bin/python3 -c "import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if ($2) else 1)" "$OUT" 2>>"$ERR"; then
        pass "$1"
    else
        fail "$1 (false: $2)"
    fi
}

# same NAME GOT WANT: passes when the two strings are equal.
same() {
    if [ "$2" = "$3" ]; then
        pass "$1"
    else
        echo "not ok - $1"
        echo "  got:  $2" | head -n 5
        echo "  want: $3" | head -n 5
    fi
}

# fixture NAME [DEST]: copies the shared fixture NAME (tests/e2e/fixtures.sh
# says what each is) to DEST (default $WORK/NAME), so that a script may
# change its copy; a database fixture's NAME.status, NAME.out and NAME.err
# (how its command went) come with it. tests/run.py makes the fixtures once
# per run; a script run on its own makes the ones it asks for into $WORK.
fixture() {
    local name=$1 dest=${2:-$WORK/$1} part
    fixture_make "$name" || return 1
    cp "$FACET_FIXTURES/$name" "$dest" || return 1
    for part in status out err; do
        if [ -e "$FACET_FIXTURES/$name.$part" ]; then
            cp "$FACET_FIXTURES/$name.$part" "$dest.$part" || return 1
        fi
    done
}

# fixture_make NAME: makes the fixture NAME unless it is made already.
fixture_make() {
    if [ -z "${FACET_FIXTURES:-}" ]; then
        FACET_FIXTURES=$WORK/fixtures
    fi
    [ -e "$FACET_FIXTURES/$1" ] && return 0
    FACET_FIXTURES=$FACET_FIXTURES bash "$(dirname "${BASH_SOURCE[0]}")/fixtures.sh" "$1"
}

# fixture_path NAME: the shared fixture NAME's own path, for a script that
# only reads it and needs the very path a database fixture names (a run
# records its surfaces' files).
fixture_path() {
    fixture_make "$1" >&2 || return 1
    echo "$FACET_FIXTURES/$1"
}

# fixture_run NAME DB: as run, for the command that made the database
# fixture NAME, copied to DB: its status, stdout and stderr are the last
# run's, for expect-like checks of that command.
fixture_run() {
    STATUS=127
    : >"$OUT"
    echo "the fixture $1 could not be made" >"$ERR"
    fixture "$1" "$2" || return 1
    STATUS=$(cat "$2.status")
    cp "$2.out" "$OUT"
    cp "$2.err" "$ERR"
}

# expect_fixture NAME STATUS FIXTURE DB: as expect, of the command that
# made the database fixture FIXTURE (copied to DB).
expect_fixture() {
    local name=$1 want=$2
    fixture_run "$3" "$4"
    if [ "$STATUS" -eq "$want" ]; then pass "$name"; else fail "$name (want status $want)"; fi
}

# exported_again WHAT FIRST AGAIN CMD...: runs CMD, an export of what
# wrote FIRST into AGAIN, a second later, and passes when the two files
# have the same bytes: a clock that shows would show by then.
exported_again() {
    local what=$1 first=$2 again=$3
    shift 3
    sleep 1
    expect "$what exported again" 0 "$@"
    if cmp -s "$first" "$again"; then
        pass "$what twice: the same bytes"
    else
        echo "not ok - $what twice differs"
    fi
}

# four_surfaces: copies Facet's plane, cylinder, dome and hypar examples
# (--res 16) into $WORK, and $WORK/four.obj, a project of their four
# objects in one file (project_combine.py), for the project tests: the
# fixtures of those names.
four_surfaces() {
    local e
    for e in plane cylinder dome hypar four; do
        fixture "$e.obj" || return 1
    done
}
