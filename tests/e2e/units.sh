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
# Core holds a quantity in one unit: in core/, outside core/out/ (files
# for people) and the quantities' display scales, a call of units.h's
# conversions that is not part of a message, and a field of a core
# header named in mm or degrees, fail too (held_twice: the design's few
# crossings are listed there with why), as the option's gaps and kinks
# were held in mm and degrees before issue 27.
#
# It then checks itself: a copy of the tree with one conversion written
# out in core/ must fail, and one with a total converted in core/ and a
# field in degrees, so that the check cannot pass by reading nothing.
# Prints "ok - ..." / "not ok - ..." lines; reads only sources.
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
            # The migrations' SQL: SQLite rescales a stored column to the
            # unit of its family, and fills the m and rad Facet keeps
            # (schema v16; test_store_older and seams.sh hold it to
            # sqlite3's own arithmetic on the old file). Their strings
            # only: C there is checked as anywhere.
            if rel == 'store/schema.c':
                text = re.sub(r'"(\\.|[^"\\\n])*"', '""', text)
            for number, line in enumerate(text.split('\n'), 1):
                if pattern.search(line):
                    print('%s:%d: %s' % (rel, number, line.strip()))
PY
}

# Quantities held in two units in core/: a call of units.h's conversions
# in core/ outside the display layer (core/out/ writes files for people,
# core/quantity/ holds the display scales) that is not part of a message
# (its statement holds no string), and a field of a core struct named in
# mm or degrees. A few crossings are the design's, each named below with
# why; any other is a number core would hold in two units.
held_twice() {
    python3 - "$1" <<'PY'
import os, re, sys
root = sys.argv[1]
call = re.compile(r'\bunits_(mm|deg|m_of_mm|rad_of_deg)\s*\(')
field = re.compile(r'^\s*(double|float|int|long|size_t)\s[^();]*'
                   r'\b\w+_(mm|deg)\b[^();]*;')
allowed = {
    # The design point's threshold is on optimize's grid in mm
    # (core/search/optimize.h, design_point_threshold_on_grid): the one
    # place it becomes classify's metres.
    ('core/evaluate/option.c', 'units_m_of_mm(threshold_mm)'),
    # A design point (struct option_row, struct design_point) and the
    # space it is searched in name their threshold in mm, the store's
    # threshold_mm, on a grid of 1/1000 mm (optimize.h).
    ('core/quantity/option_row.h', 'threshold_mm;'),
    ('core/search/optimize.h', 't_min_mm, t_max_mm;'),
    ('core/search/optimize.h', 't_step_mm;'),
    ('core/search/optimize.h', 'threshold_mm;'),
    # A welding tolerance as the designer types it, in mm: --weld and the
    # New run form's field share this one reading (seam_weld_parse), the
    # one place it becomes the seams' metres.
    ('core/project/seam.c', 'units_mm(SEAM_WELD_MIN)'),
    ('core/project/seam.c', 'units_mm(SEAM_WELD_MAX)'),
    ('core/project/seam.c', 'units_m_of_mm(mm)'),
}
for folder, _, files in sorted(os.walk(os.path.join(root, 'core'))):
    for name in sorted(files):
        path = os.path.join(folder, name)
        rel = os.path.relpath(path, root)
        if not name.endswith(('.c', '.h')) or rel == 'core/base/units.h' \
                or rel.startswith(('core/out/', 'core/quantity/quantity.')):
            continue
        text = open(path, encoding='utf-8', errors='replace').read()
        text = re.sub(r'/\*.*?\*/',
                      lambda m: '\n' * m.group(0).count('\n'), text,
                      flags=re.S)
        text = re.sub(r'//[^\n]*', '', text)
        lines = text.split('\n')
        for number, line in enumerate(lines, 1):
            if any(rel == f and w in line for f, w in allowed):
                continue
            if name.endswith('.h') and '=' not in line and \
                    field.search(line):
                print('%s:%d: %s' % (rel, number, line.strip()))
            if not call.search(line):
                continue
            # the statement the call is in: back to the last ; { or }
            # and on to the next ;
            before = '\n'.join(lines[:number - 1]) + '\n' + line
            start = max(before.rfind(';', 0, len(before) - len(line)),
                        before.rfind('{', 0, len(before) - len(line)),
                        before.rfind('}', 0, len(before) - len(line)))
            after = '\n'.join(lines[number:])
            end = after.find(';')
            statement = before[start + 1:] + after[:end if end >= 0 else 0]
            if '"' not in statement:
                print('%s:%d: %s' % (rel, number, line.strip()))
PY
}

status=0
twice=$(held_twice "$root")
if [ -z "$twice" ]; then
    echo "ok - core/ holds gaps in m and angles in rad: no conversion outside a message or the display layer, no field in mm or degrees"
else
    echo "not ok - core/ holds gaps in m and angles in rad: no conversion outside a message or the display layer, no field in mm or degrees"
    printf '%s\n' "$twice" | sed 's/^/  /'
    status=1
fi

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

# ... and it can fail too: a total turned into mm in core/evaluate/, and a
# field in degrees in a core header, are caught; a message is not.
mkdir -p "$copy/core/evaluate" "$copy/core/joint" "$copy/core/fit"
printf 'void f(struct option_totals *t, double g)\n{\n    t->max_gap =\n        units_mm(g);\n}\n' \
    >"$copy/core/evaluate/hand.c"
printf 'struct j {\n    double max_kink_deg;  /* degrees */\n};\n' \
    >"$copy/core/joint/hand.h"
printf 'void m(char *b, double x)\n{\n    snprintf(b, 9, "%%g mm",\n             units_mm(x));\n}\n' \
    >"$copy/core/fit/ok.c"
caught=$(held_twice "$copy")
if [ "$(printf '%s\n' "$caught" | grep -c .)" = 2 ] &&
   printf '%s\n' "$caught" | grep -q '^core/evaluate/hand.c:4:' &&
   printf '%s\n' "$caught" | grep -q '^core/joint/hand.h:2:'; then
    echo "ok - a total converted in core/ and a core field in degrees are caught, a message is not"
else
    echo "not ok - a total converted in core/ and a core field in degrees are caught, a message is not"
    printf '%s\n' "$caught" | sed 's/^/  got: /'
    status=1
fi
exit $status
