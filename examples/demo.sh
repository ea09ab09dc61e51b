#!/usr/bin/env bash
# make demo: the main job end to end on a bundled example, no TTY needed.
# Generates the example roof with Facet itself, describes it, and classifies
# it at the paper's grid (37 x 49).
set -euo pipefail
facet=${1:-./facet}
out=${DEMO_DIR:-examples/out}
mkdir -p "$out"
echo "== facet example roof -o $out/roof.obj"
"$facet" example roof --force -o "$out/roof.obj"
echo "== facet info $out/roof.obj"
"$facet" info "$out/roof.obj"
echo
echo "== facet classify $out/roof.obj --grid 37x49 --csv $out/roof-37x49.csv"
rm -f "$out/roof-37x49.csv"
"$facet" classify "$out/roof.obj" --grid 37x49 --csv "$out/roof-37x49.csv"
echo
echo "panel schedule: $out/roof-37x49.csv ($(($(wc -l <"$out/roof-37x49.csv") - 1)) panels)"
