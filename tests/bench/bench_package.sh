#!/usr/bin/env bash
# bench_package.sh: a building's fabrication package out of Facet (issue
# 30): one option of the example skin at its default resolution (180
# faces, 2,025,000 triangles; the module 1.0 m x 1.1 m, about 50,000
# panels), exported as every file a fabricator takes.
#
#   tests/bench/bench_package.sh BUILD_DIR [RUNS]
#
# The baseline, in the same run, is the bare schedule (--csv): the export
# that reads and prepares the building again and evaluates the option
# over it, as the whole package must too. RUNS rounds alternate (schedule,
# package, ...); each one's median wall time is printed, the package's
# ratio to the schedule's, and whether the package is written within the
# issue's 30 s on this machine's cores.
set -euo pipefail
build=${1:?usage: tests/bench/bench_package.sh BUILD_DIR [RUNS]}
runs=${2:-3}
cd "$(dirname "$0")/../.."
facet=$PWD/$build/facet
[ -x "$facet" ] || { echo "bench_package: no $facet (run make)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$facet" example skin -o "$work/skin.obj" >/dev/null
"$facet" optimize "$work/skin.obj" --db "$work/skin.db" --module 1x1.1 \
    --threshold 3 --method exhaustive --table 0 >/dev/null 2>&1
panels=$(sqlite3 "$work/skin.db" 'SELECT panels FROM options WHERE run = 1 AND number = 1')
# Every format facet export writes for a building's option.
package=(--csv "$work/p.csv" --xlsx "$work/p.xlsx" --dxf "$work/p.dxf"
         --ifc "$work/p.ifc")
formats="csv xlsx dxf ifc"
time_one() {
    rm -f "$work"/p.* "$work"/p-*
    local start=$EPOCHREALTIME
    "$facet" export "$work/skin.db" --run 1 --option 1 "$@" >/dev/null 2>&1 ||
        { echo "bench_package: facet export $* failed" >&2; exit 1; }
    awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.3f\n", b - a }'
}
: >"$work/times"
for _ in $(seq 1 "$runs"); do
    echo "schedule $(time_one --csv "$work/p.csv")" >>"$work/times"
    echo "package $(time_one "${package[@]}")" >>"$work/times"
done
median() { awk -v k="$1" '$1 == k { print $2 }' "$work/times" | sort -n |
    awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
m_schedule=$(median schedule)
m_package=$(median package)
awk -v s="$m_schedule" -v p="$m_package" -v n="$runs" -v panels="$panels" \
    -v formats="$formats" -v cores="$(nproc)" 'BEGIN {
    printf "   %d panels; the schedule (--csv): %.2f s; the package (%s): %.2f s, %.2fx (medians of %d alternating runs)\n", panels, s, formats, p, p / s, n
    printf "   target (issue 30): the package of a 45,000-panel building option in at most 30 s on %d cores: %s\n", cores, p <= 30 ? "met" : "not met"
}'
