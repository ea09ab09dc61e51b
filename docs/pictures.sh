#!/usr/bin/env bash
# pictures.sh: the README's pictures of a fabrication package, made by
# Facet from its own example and drawn by readers that are not Facet's
# (docs/render.py: openpyxl, ezdxf, matplotlib).
#
#   docs/pictures.sh FACET [OUT_DIR]     (default OUT_DIR: docs/img)
#
# The roof, the paper's space as the README's walk-through runs it, and
# its knee exported as a schedule (XLSX) and flat patterns (DXF), then:
#   OUT_DIR/schedule.png        rows of the panels sheet;
#   OUT_DIR/flat-patterns.png   the DXF's first sheet of patterns (4 m x
#                               2 m sheets, so that a few panels share one).
set -euo pipefail
facet=$(realpath "${1:?usage: docs/pictures.sh FACET [OUT_DIR]}")
here=$(cd "$(dirname "$0")" && pwd)
out=$(realpath -m "${2:-$here/img}")
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$facet" example roof -o roof.obj >/dev/null
"$facet" optimize roof.obj --db demo.db --u 20:40 --v 35:50 --threshold 3 \
    --sp-as-fp --max-panel-area 1.92 --sp-fit no --name "paper space" \
    --table 0 >/dev/null 2>&1
knee=$(sqlite3 demo.db 'SELECT number FROM options WHERE run = 1 AND knee')
"$facet" export demo.db --run 1 --option "$knee" --xlsx knee.xlsx \
    --dxf knee.dxf --sheet 4000x2000 >/dev/null
/usr/bin/python3 "$here/render.py" xlsx knee.xlsx "$out/schedule.png"
/usr/bin/python3 "$here/render.py" dxf knee.dxf "$out/flat-patterns.png"
echo "wrote $out/schedule.png and $out/flat-patterns.png (run 1, option $knee)"
