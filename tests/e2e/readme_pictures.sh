#!/usr/bin/env bash
# End-to-end: the README's pictures of a fabrication package (issue 30)
# can be made again from this Facet: docs/pictures.sh runs the
# walk-through's study, exports its knee and draws the files with readers
# that are not Facet's (openpyxl, ezdxf, matplotlib). Each picture must be
# a PNG that Pillow opens, of a readable size, and not blank.
# layers: cli study store core
. "$(dirname "$0")/lib.sh"
for m in openpyxl ezdxf matplotlib PIL; do
    if ! /usr/bin/python3 -c "import $m" 2>/dev/null; then
        skip "the README's pictures" "python3 module $m is not installed (make deps)"
        exit 0
    fi
done
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
expect "docs/pictures.sh draws the pictures" 0 \
    "$ROOT/docs/pictures.sh" "$FACET" "$WORK/img"
for p in schedule.png flat-patterns.png; do
    if out=$(/usr/bin/python3 - "$WORK/img/$p" <<'PY' 2>&1
import sys
from PIL import Image
im = Image.open(sys.argv[1])
im.verify()
im = Image.open(sys.argv[1]).convert("L")
w, h = im.size
lo, hi = im.getextrema()
assert w >= 400 and h >= 150, "too small: %dx%d" % (w, h)
assert hi - lo > 100, "blank: grey levels %d to %d" % (lo, hi)
dark = sum(1 for v in im.getdata() if v < 128) / (w * h)
assert dark > 0.01, "nearly nothing drawn: %.4f of the pixels dark" % dark
print("%dx%d, %.3f of it drawn" % (w, h, dark))
PY
    ); then
        pass "$p is a PNG with something drawn on it ($out)"
    else
        echo "not ok - $p is a PNG with something drawn on it"
        printf '%s\n' "$out" | sed 's/^/  /' | tail -n 5
    fi
done
