#!/usr/bin/env bash
# make bench: every benchmark, each reported as a ratio against a baseline
# measured in the same run.
#
#   tests/bench/run.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: tests/bench/run.sh BUILD_DIR}
cd "$(dirname "$0")/../.."
echo "== OBJ loader: Facet's obj_load against Debian's tinyobjloader (1M triangles)"
tests/bench/bench_obj.sh "$build"
echo
echo "== One design option: a 37x49 evaluation of the 100k-triangle roof"
"$build/bench/bench_classify"
echo
echo "== Panels as built: the SP fit, gaps and kinks of one 37x49 option of the 100k-triangle roof"
"$build/bench/bench_joint"
echo
echo "== The paper's whole space (336 grids) on the 100k-triangle roof, into SQLite"
"$build/bench/bench_optimize"
echo
echo "== Mould families of one design option: the 37x49 roof option at the 3 mm flatness threshold"
"$build/bench/bench_mould"
echo
echo "== NSGA-II: Facet against DEAP on ZDT1 (population 100 x 250 generations)"
tests/bench/bench_nsga2.sh "$build"
echo
echo "== A whole building: load and prepare the example skin (180 faces, 2,025,000 triangles) against a bare read of its file; one option of about 50,000 panels over it"
"$build/bench/bench_project"
echo
echo "== The TUI's options table on 1,000,000 options: open, sort, filter, page, end"
"$build/bench/bench_tui"
