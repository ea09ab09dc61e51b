#!/usr/bin/env bash
# make demo: the main job end to end on a bundled example, no TTY needed.
# Generates the example roof with Facet itself and describes it.
set -euo pipefail
facet=${1:-./facet}
out=${DEMO_DIR:-examples/out}
mkdir -p "$out"
echo "== facet example roof -o $out/roof.obj"
"$facet" example roof --force -o "$out/roof.obj"
echo "== facet info $out/roof.obj"
"$facet" info "$out/roof.obj"
