#!/usr/bin/env bash
# End-to-end: the README is accurate (issue 32 item 17). Every `facet`
# command of its code blocks runs, as written, in the order written, with
# `facet` on the PATH (this build's), and exits 0; the ones that read the
# demo's store run again on a store that holds a second run, as make demo
# leaves it, and those that name --run 1 print the same there. The numbers
# it quotes (the knee, its grid and cost, the roof's area, the options of
# the paper's space, the rows of optimize's table) and the workbench's
# column count docs/manual.md quotes are checked against the real output:
# sqlite3 over the store, the OBJ's own triangles, the screen in tmux.
# readme_check.py does the work and prints the check lines.
# layers: cli study store core tui
. "$(dirname "$0")/lib.sh"

ROOT=$(cd "$(dirname "$0")/../.." && pwd)
for tool in sqlite3 tmux; do
    if ! command -v "$tool" >/dev/null; then
        echo "not ok - $tool is installed (make deps)"
        exit 0
    fi
done
mkdir -p "$WORK/bin" && ln -s "$FACET" "$WORK/bin/facet" || exit 1
PATH=$WORK/bin:$PATH /usr/bin/python3 "$(dirname "$0")/readme_check.py" \
    "$ROOT" "$WORK"
status=$?
[ "$status" -eq 0 ] || echo "not ok - readme_check.py ran to its end (status $status)"
exit 0
