#!/usr/bin/env bash
# fixtures.sh: the surfaces and result databases that several end-to-end
# scripts start from, made once and shared, instead of made again in each
# script (and again for each build).
#
#   FACET=build/release/facet FACET_FIXTURES=DIR tests/e2e/fixtures.sh [NAME...]
#
# Makes every fixture named (default: all of them) that DIR does not hold
# yet. tests/run.py runs it once per run, with the first build's facet, into
# a fresh folder, and every suite of every build reads from there (a run of
# some suites only, --only or --changed, makes each fixture when a suite
# first asks for it); a script run on its own makes what it asks for into
# its own $WORK (lib.sh, fixture). A database fixture also keeps how its command went: NAME.status
# (the exit status), NAME.out and NAME.err, for the scripts whose checks
# are about that run. A fixture is written under a temporary name and moved
# into place whole, so a reader never sees half of one.
#
# The fixtures:
#   roof.obj       facet example roof (the paper's roof at its default res)
#   roof40.obj     facet example roof --res 40
#   plane.obj, cylinder.obj, dome.obj, hypar.obj
#                  those examples at --res 16, and four.obj, the four of them
#                  as the objects of one OBJ (project_combine.py): a building
#   paper.db       the paper's study on roof.obj: 336 options (--u 20:40
#                  --v 35:50 --threshold 3 --sp-as-fp --max-panel-area 1.92
#                  --sp-fit no --name paper)
#   four.db        four.obj searched exhaustively over modules
#                  1:4:0.25 x 1:4:0.25 and thresholds 2:6:2 (--jobs 2
#                  --table 5), the run project_run.sh checks and
#                  project_shard.sh shards
set -uo pipefail
FACET=${FACET:?set FACET to the facet binary}
DIR=${FACET_FIXTURES:?set FACET_FIXTURES to the fixtures folder}
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$DIR" || exit 1
ALL=(roof.obj roof40.obj four.obj paper.db four.db)

# keep NAME CMD...: runs CMD, which writes $DIR/.NAME.tmp, and keeps its
# status, stdout and stderr beside it; the file moves into place whole.
keep() {
    local name=$1
    shift
    "$@" >"$DIR/$name.out" 2>"$DIR/$name.err"
    local status=$?
    echo "$status" >"$DIR/$name.status"
    if [ -e "$DIR/.$name.tmp" ]; then
        mv -f "$DIR/.$name.tmp" "$DIR/$name"
    fi
    if [ "$status" -ne 0 ]; then
        echo "fixtures.sh: $name: $* exited $status:" >&2
        head -n 5 "$DIR/$name.err" >&2
    fi
    return "$status"
}

make_one() {
    local name=$1
    [ -e "$DIR/$name" ] && return 0
    case $name in
    roof.obj)
        keep "$name" "$FACET" example roof -o "$DIR/.$name.tmp" ;;
    roof40.obj)
        keep "$name" "$FACET" example roof --res 40 -o "$DIR/.$name.tmp" ;;
    plane.obj | cylinder.obj | dome.obj | hypar.obj)
        keep "$name" "$FACET" example "${name%.obj}" --res 16 -o "$DIR/.$name.tmp" ;;
    four.obj)
        local e
        for e in plane cylinder dome hypar; do make_one "$e.obj" || return 1; done
        keep "$name" /usr/bin/python3 "$HERE/project_combine.py" "$DIR/.$name.tmp" \
            "$DIR/plane.obj" "$DIR/cylinder.obj" "$DIR/dome.obj" "$DIR/hypar.obj" ;;
    paper.db)
        make_one roof.obj || return 1
        keep "$name" "$FACET" optimize "$DIR/roof.obj" --db "$DIR/.$name.tmp" \
            --u 20:40 --v 35:50 --threshold 3 --sp-as-fp --max-panel-area 1.92 \
            --sp-fit no --name paper ;;
    four.db)
        make_one four.obj || return 1
        keep "$name" "$FACET" optimize "$DIR/four.obj" --db "$DIR/.$name.tmp" \
            --module 1:4:0.25x1:4:0.25 --threshold 2:6:2 --method exhaustive \
            --jobs 2 --table 5 ;;
    *)
        echo "fixtures.sh: no fixture named '$name'" >&2
        return 2 ;;
    esac
}

# Suites that make what they need on demand share the folder: one maker
# at a time (flock), and a fixture another made meanwhile is not made twice.
exec 9>"$DIR/.lock" || exit 1
flock 9 || exit 1
status=0
[ $# -gt 0 ] || set -- "${ALL[@]}"
for name in "$@"; do
    make_one "$name" || status=1
done
exit $status
