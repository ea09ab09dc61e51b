#!/usr/bin/env bash
# units.sh: no number is converted by hand between units below the display
# layer (issue 27). Facet computes in metres and radians; millimetres and
# degrees are for the designer's eyes and the store's columns, and every
# crossing goes through core/base/units.h. In core/, store/ and study/,
# outside comments, this fails on a multiplication or division by 1000
# (1e3), which turns metres into millimetres or back, and on 180 / M_PI or
# M_PI / 180, which turn radians into degrees or back. tui/ and cli/ show
# numbers and may scale them (their scales come from the quantities,
# core/quantity/quantity.h). A grid or a key of another unit names its
# step (optimize.c's THRESHOLD_STEPS_PER_MM), as it should anyway.
#
# It then checks itself: a copy of the tree with one conversion written
# out in core/ must fail, so that the check cannot pass by reading
# nothing. Prints "ok - ..." / "not ok - ..." lines; reads only sources.
#
#   tests/e2e/units.sh [ROOT]      (ROOT: the repository, by default this one)
# layers: core store study
set -uo pipefail
root=$(cd "${1:-$(dirname "$0")/../..}" && pwd)

# Conversions written out in the C sources under $1, one per line, with
# comments left out.
conversions() {
    python3 - "$1" <<'PY'
import os, re, sys
root = sys.argv[1]
pattern = re.compile(r'[*/]\s*(1000(\.0*)?|1e3)\b|\b180(\.0*)?\s*/\s*M_PI\b'
                     r'|\bM_PI\s*/\s*180\b')
for floor in ('core', 'store', 'study'):
    for folder, _, files in sorted(os.walk(os.path.join(root, floor))):
        for name in sorted(files):
            path = os.path.join(folder, name)
            rel = os.path.relpath(path, root)
            if not name.endswith(('.c', '.h')) or rel == 'core/base/units.h':
                continue
            text = open(path, encoding='utf-8', errors='replace').read()
            # Comments out, lines kept: a comment may say "x 1000".
            text = re.sub(r'/\*.*?\*/',
                          lambda m: '\n' * m.group(0).count('\n'), text,
                          flags=re.S)
            text = re.sub(r'//[^\n]*', '', text)
            for number, line in enumerate(text.split('\n'), 1):
                if pattern.search(line):
                    print('%s:%d: %s' % (rel, number, line.strip()))
PY
}

status=0
found=$(conversions "$root")
if [ -z "$found" ]; then
    echo "ok - no mm/m or deg/rad conversion written out in core/, store/, study/ (core/base/units.h has them)"
else
    echo "not ok - no mm/m or deg/rad conversion written out in core/, store/, study/ (core/base/units.h has them)"
    printf '%s\n' "$found" | sed 's/^/  /'
    status=1
fi

# The check can fail: the same tree with a gap turned into mm by hand in
# core/ and a kink into degrees in study/.
copy=$(mktemp -d /tmp/facet_units_XXXXXX)
trap 'rm -rf "$copy"' EXIT
mkdir -p "$copy/core/joint" "$copy/study"
printf 'double gap_mm(double gap)\n{\n    return gap * 1000; /* x 1000 */\n}\n' \
    >"$copy/core/joint/hand.c"
printf 'double kink(double k) { return k * 180.0 / M_PI; }\n' \
    >"$copy/study/hand.c"
printf '/* 1000 mm */ double f(double x) { return x; }\n' >"$copy/study/ok.c"
caught=$(conversions "$copy")
if [ "$(printf '%s\n' "$caught" | grep -c .)" = 2 ] &&
   printf '%s\n' "$caught" | grep -q '^core/joint/hand.c:3:' &&
   printf '%s\n' "$caught" | grep -q '^study/hand.c:1:'; then
    echo "ok - a conversion written out in core/ or study/ is caught, one in a comment is not"
else
    echo "not ok - a conversion written out in core/ or study/ is caught, one in a comment is not"
    printf '%s\n' "$caught" | sed 's/^/  got: /'
    status=1
fi
exit $status
