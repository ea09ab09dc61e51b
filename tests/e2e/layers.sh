#!/usr/bin/env bash
# layers.sh: the house keeps its shape. Every #include of the sources is
# checked against the arrows of README "Layout":
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
# Prints one "ok - ..." or "not ok - ..." line per floor, with the
# offending lines below a failure; tests/run.sh counts them. Reads only the
# sources: it needs no build.
#
#   tests/e2e/layers.sh [ROOT]      (ROOT: the repository, by default this one)
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
exit $status
