#!/usr/bin/env bash
# layers.sh: the house keeps its shape. Every #include of the sources is
# checked against the arrows of docs/layout.md ("Layout"):
#
#   cli -> {study, store, tui, core}   tui -> {study, store, core}
#   study -> {store, core}             store -> core       core -> nothing
#
# A quoted include is resolved as the compiler does (the including file's
# folder, then the repository root, -I.), and the floor of the file it
# names must be one the includer may use; a quoted include that names no
# file of the repository is refused too, so that no include slips past by
# its spelling. Of the system headers, <sqlite3.h> belongs to store/ and
# <curses.h> (<ncurses.h>, <term.h>) to tui/ alone.
#
# Below cli/, no string literal names a command-line flag ("--threshold"):
# the same message reaches the TUI's forms, and core/base/error.h says how
# a caller names its fields instead. Comments may name flags.
#
# Prints one "ok - ..." or "not ok - ..." line per floor, with the
# offending lines below a failure; tests/run.py counts them. Reads only the
# sources: it needs no build.
#
#   tests/e2e/layers.sh [ROOT]      (ROOT: the repository, by default this one)
# layers: core store study tui cli
set -uo pipefail
root=${1:-$(dirname "$0")/../..}
cd "$root" || exit 1

# The floors a floor's files may include, itself first.
may_use() {
    case $1 in
    core) echo "core" ;;
    store) echo "store core" ;;
    study) echo "study store core" ;;
    tui) echo "tui study store core" ;;
    cli) echo "cli tui study store core" ;;
    esac
}

# The system headers a floor may not include (an extended regex).
forbidden_system() {
    case $1 in
    store) echo '^(n?curses|term)\.h$' ;;
    tui) echo '^sqlite3\.h$' ;;
    *) echo '^(sqlite3|n?curses|term)\.h$' ;;
    esac
}

status=0
for floor in core store study tui cli; do
    if [ ! -d "$floor" ]; then
        echo "not ok - $floor/ is there"
        status=1
        continue
    fi
    allowed=" $(may_use "$floor") "
    system=$(forbidden_system "$floor")
    bad=()
    while IFS= read -r file; do
        while IFS=: read -r line text; do
            if [[ $text =~ ^[[:space:]]*#[[:space:]]*include[[:space:]]*\"([^\"]+)\" ]]; then
                name=${BASH_REMATCH[1]}
                dir=$(dirname "$file")
                if [ -f "$dir/$name" ]; then
                    target=$(realpath -m --relative-to=. "$dir/$name")
                elif [ -f "$name" ]; then
                    target=$(realpath -m --relative-to=. "$name")
                else
                    bad+=("$file:$line: \"$name\" names no file of the repository")
                    continue
                fi
                to=${target%%/*}
                [ "$to" = "$target" ] && to=.
                if [[ $allowed != *" $to "* ]]; then
                    bad+=("$file:$line: $floor/ may not include $target")
                fi
            elif [[ $text =~ ^[[:space:]]*#[[:space:]]*include[[:space:]]*\<([^\>]+)\> ]]; then
                name=${BASH_REMATCH[1]}
                if [[ $name =~ $system ]]; then
                    bad+=("$file:$line: $floor/ may not include <$name>")
                fi
            fi
        done < <(grep -n '^[[:space:]]*#[[:space:]]*include' "$file")
    done < <(find "$floor" -name '*.[ch]' | sort)
    if [ "${#bad[@]}" -eq 0 ]; then
        echo "ok - $floor/ includes only from {$(may_use "$floor")}"
    else
        echo "not ok - $floor/ includes only from {$(may_use "$floor")}"
        printf '  %s\n' "${bad[@]}"
        status=1
    fi
done
# String literals below cli/ that hold a --flag word: a C lexer that
# skips comments and reads strings, char constants and escapes as the
# compiler does (adjacent literals are checked one by one, which a flag
# split across two of them would slip past; none is written so).
flag_literals() {
    python3 - "$@" <<'PY'
import re, sys
flag = re.compile(r'(?<![-\w])--[a-z]')
for path in sys.argv[1:]:
    text = open(path, encoding='utf-8', errors='replace').read()
    i, n, line = 0, len(text), 1
    while i < n:
        c = text[i]
        if c == '\n':
            line += 1
            i += 1
        elif text.startswith('//', i):
            while i < n and text[i] != '\n':
                i += 1
        elif text.startswith('/*', i):
            end = text.find('*/', i + 2)
            end = n if end < 0 else end + 2
            line += text.count('\n', i, end)
            i = end
        elif c == '"' or c == "'":
            j, start = i + 1, line
            while j < n and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' else 1
            if c == '"' and flag.search(text[i + 1:j]):
                print('%s:%d: %s' % (path, start, text[i:j + 1]))
            i = j + 1
        else:
            i += 1
PY
}

for floor in core store study tui; do
    [ -d "$floor" ] || continue
    found=$(flag_literals $(find "$floor" -name '*.[ch]' | sort))
    if [ -z "$found" ]; then
        echo "ok - no string of $floor/ names a command-line flag"
    else
        echo "not ok - no string of $floor/ names a command-line flag"
        printf '%s\n' "$found" | sed 's/^/  /'
        status=1
    fi
done
exit $status
