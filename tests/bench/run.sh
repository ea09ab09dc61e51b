#!/usr/bin/env bash
# make bench: every benchmark, each reported as a ratio against a baseline
# measured in the same run, then one line per goal: met or not met.
#
#   tests/bench/run.sh BUILD_DIR
#
# Each section says how long it took, and the whole how long it took
# against its 5-minute budget (issue 18). The goal lines are the lines of
# the sections that name a target and say "met" or "not met"; they are
# collected from the sections' own output, so a goal is summed up in the
# words its benchmark measured it in.
set -euo pipefail
build=${1:?usage: tests/bench/run.sh BUILD_DIR}
cd "$(dirname "$0")/../.."
log=$(mktemp "${TMPDIR:-/tmp}/facet-bench.XXXXXX")
trap 'rm -f "$log"' EXIT
start_all=$EPOCHREALTIME

# section TITLE COMMAND...: runs one benchmark under a heading, its output
# kept for the summary, and says how long it took.
section() {
    local title=$1
    shift
    echo "== $title"
    local start=$EPOCHREALTIME
    "$@" 2>&1 | tee -a "$log"
    local status=${PIPESTATUS[0]}
    awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "   (%.0f s)\n\n", b - a }'
    return "$status"
}

section "OBJ loader: Facet's obj_load against Debian's tinyobjloader (1M triangles)" \
    tests/bench/bench_obj.sh "$build"
section "One design option: a 37x49 evaluation of the 100k-triangle roof" \
    "$build/bench/bench_classify"
section "Curvature at every vertex against the estimator of d218719 (issue 27): the 100k-triangle roof and real surfaces of ../shared/data" \
    "$build/bench/bench_curvature"
section "Panels as built: the SP fit, gaps and kinks of one 37x49 option of the 100k-triangle roof" \
    "$build/bench/bench_joint"
section "The paper's whole space (336 grids) on the 100k-triangle roof, into SQLite" \
    "$build/bench/bench_optimize"
section "The paper's study as make demo runs it, and as built by default, against d218719 (issue 27)" \
    tests/bench/bench_study.sh "$build"
section "A space beyond the lattice: u 10:120 x v 10:120 at 3 mm (12,321 grids) on the 100k-triangle roof" \
    "$build/bench/bench_space"
section "An NSGA-II run's end: storing its Pareto options' panels, against the run" \
    "$build/bench/bench_front"
section "Mould families of one design option: the 37x49 roof option at the 3 mm flatness threshold" \
    "$build/bench/bench_mould"
section "Planar panels (issue 33): the roof's 100 x 100 grid (10,000 quads) planarized within 5 mm, against libigl's figure" \
    "$build/bench/bench_planarize"
section "NSGA-II: Facet against DEAP on ZDT1 (population 100 x 250 generations)" \
    tests/bench/bench_nsga2.sh "$build"
section "A whole building: load and prepare the example skin (180 faces, 2,025,000 triangles) against a bare read of its file; one option of about 50,000 panels over it" \
    "$build/bench/bench_project" 75 3
section "A building prepared once (issue 31): a run's start on the example skin until it can evaluate, the second (its prepared building read from the cache beside the database and checked) against the first (read, prepared, kept)" \
    "$build/bench/bench_prepared" 75 5
section "A building's fabrication package: one option of the example skin (about 50,000 panels) exported as every file facet export writes, against its bare schedule" \
    tests/bench/bench_package.sh "$build"
section "The TUI's options table on 1,000,000 options: open, sort, filter, page, end" \
    "$build/bench/bench_tui"
section "The TUI's Statistics of a run of 10,000 options: every count, extreme, mean and median" \
    "$build/bench/bench_tui" --options 10000 --statistics

whole=$(awk -v a="$start_all" -v b="$EPOCHREALTIME" 'BEGIN { print b - a }')
echo "== Goals, one line each (from the sections above)"
grep -E 'target|verdict|\(issue [0-9]+\)' "$log" |
    grep -E '(^|[^a-z])(met|not met|NOT met)([^a-z]|$)' |
    sed -E 's/^ +//' | sed 's/^/  /' || true
met=$(awk -v w="$whole" 'BEGIN { print (w < 300) ? "met" : "not met" }')
printf '  make bench: %.0f s in all (goal: under 300 s: %s)\n' "$whole" "$met"
