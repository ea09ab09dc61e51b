#!/usr/bin/env bash
# make demo: the main job end to end on a bundled example, no TTY needed.
# Generates the example roof with Facet itself, describes it, and classifies
# it at the paper's grid (37 x 49), then searches the paper's whole design
# space into the SQLite store examples/out/demo.db, prints its Pareto table,
# and writes the scatter (demo-pareto.svg) and the knee option as OBJ + MTL,
# CSV schedule and SVG panel map (demo-knee.*).
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
echo
echo "== facet optimize $out/roof.obj --db $out/demo.db (the paper's space: u 20:40, v 35:50, 3 mm)"
rm -f "$out/demo.db" "$out/demo.db-wal" "$out/demo.db-shm"
"$facet" optimize "$out/roof.obj" --db "$out/demo.db" --u 20:40 --v 35:50 \
    --threshold 3 --sp-as-fp --max-panel-area 1.92 --name "paper space"
echo
echo "== facet options $out/demo.db --pareto --sort cost (the Pareto table)"
"$facet" options "$out/demo.db" --pareto --sort cost
echo
knee=$("$facet" options "$out/demo.db" --run 1 --where knee --csv | sed -n 2p | cut -d, -f2)
echo "== facet plot and facet export: the run's scatter and the knee option ($knee)"
"$facet" plot "$out/demo.db" --run 1 -o "$out/demo-pareto.svg" --force
"$facet" export "$out/demo.db" --run 1 --option "$knee" --force \
    --obj "$out/demo-knee.obj" --csv "$out/demo-knee.csv" --svg "$out/demo-knee.svg"
echo
echo "Next: explore the options in the workbench (q quits, ? lists the keys):"
echo "  $facet tui $out/demo.db"
