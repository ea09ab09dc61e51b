# lib.sh: helpers for the end-to-end scripts, which run the real facet
# binary ($FACET) and print one "ok - NAME" or "not ok - NAME" line per check.
# Each script sources this file; tests/run.sh counts the lines.

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
# skip NAME WHY: a check that could not run here; tests/run.sh counts it
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

# four_surfaces: writes Facet's plane, cylinder, dome and hypar examples
# (--res 16) into $WORK, and $WORK/four.obj, a project of their four
# objects in one file (project_combine.py), for the project tests.
four_surfaces() {
    local e
    for e in plane cylinder dome hypar; do
        "$FACET" example "$e" --res 16 -o "$WORK/$e.obj" >/dev/null || return 1
    done
    /usr/bin/python3 "$(dirname "${BASH_SOURCE[0]}")/project_combine.py" \
        "$WORK/four.obj" "$WORK/plane.obj" "$WORK/cylinder.obj" \
        "$WORK/dome.obj" "$WORK/hypar.obj"
}
