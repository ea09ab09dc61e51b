#!/usr/bin/env bash
# End-to-end: every option a command takes is in its --help, and every
# option its --help names is one it takes. The truth is the binary itself:
# a flag is taken when `facet CMD --flag` is not refused as an unknown
# option. The flags tried are every one the README and docs/*.md name and
# every one a table in cli/ spells (`{"name", ...`), so that a flag the
# help forgets is tried whatever the help says.
# layers: cli
. "$(dirname "$0")/lib.sh"

# The commands, from the overview.
commands=$("$FACET" --help | sed -n 's/^  \([a-z][a-z]*\)  .*/\1/p')
[ -n "$commands" ] || { echo "not ok - facet --help lists the commands"; exit 0; }

# Every candidate: --name words of the README, of docs/*.md and of cli/'s
# tables, and the one-letter aliases the tables give.
{
    grep -ohE -- '--[a-z][a-z0-9-]*' README.md docs/*.md
    grep -ohE '\{"[a-z][a-z0-9-]*", ' cli/*.c | sed -E 's/\{"([^"]*)", /--\1/'
} | sort -u >"$WORK/long"
grep -ohE "\{\"[a-z][a-z0-9-]*\", '[a-z]'" cli/*.c | sed -E "s/.*'(.)'/-\1/" |
    sort -u >"$WORK/short"

# refused CMD FLAG...: prints the FLAGs that facet CMD refuses as unknown
# options, one a line, from one call per twenty: the parser names every
# unknown option of a command line in its one error (cli/args.h). Each
# flag is given twice, so that a flag that takes a value takes its twin and
# the next flag is read as an option again; a flag of no value is merely
# given twice. Each call ends with a flag no command takes, which must be
# refused: the call went through the parser, not past it, and nothing runs.
# A list the error cannot hold whole ("and N more") is a failure.
SENTINEL=--help-sh-no-such-flag
refused() {
    local cmd=$1 said list
    shift
    local -a words=()
    while [ $# -gt 0 ]; do
        words=()
        while [ $# -gt 0 ] && [ ${#words[@]} -lt 40 ]; do
            words+=("$1" "$1")
            shift
        done
        said=$("$FACET" "$cmd" "${words[@]}" "$SENTINEL" 2>&1 </dev/null >/dev/null)
        # "CMD: unknown option(s) '--a', '-b' (see ...)": the quoted list
        list=${said#*unknown option}
        list=${list#s }
        list=${list%% (*}
        list=${list//,/}
        list=${list//\'/}
        if [[ $said != *"unknown option"* || $list == *" more" ||
            " $list " != *" $SENTINEL "* ]]; then
            echo "not ok - facet $cmd names every unknown option of one line"
            echo "  said: ${said:0:2000}"
            return 1
        fi
        for flag in $list; do
            [ "$flag" = "$SENTINEL" ] || printf "%s\n" "$flag"
        done
    done
    return 0
}

for cmd in $commands; do
    "$FACET" "$cmd" --help >"$WORK/$cmd.help"
    # the option lines: from "options:" on, the lines that start with a
    # flag (or a word and a flag, "DB, --db FILE"); the flags of their
    # left column, up to two blanks
    sed -n '/^options:$/,$p' "$WORK/$cmd.help" |
        grep -E -- '^  (-|[A-Z][A-Za-z.]*, -)' | sed -E 's/^  //; s/  .*//' |
        grep -oE -- '(^| )--?[a-z][a-z0-9-]*' | tr -d ' ' |
        sort -u >"$WORK/$cmd.named"
    missing="" stale=""
    grep -vxF -- --help "$WORK/long" | cat - "$WORK/short" >"$WORK/$cmd.tried"
    # every flag tried, then every flag the help names
    refused "$cmd" $(cat "$WORK/$cmd.tried") >"$WORK/$cmd.refused" || continue
    refused "$cmd" $(cat "$WORK/$cmd.named") >"$WORK/$cmd.named_refused" || continue
    # taken (not refused) and not named
    missing=$(cat "$WORK/$cmd.refused" "$WORK/$cmd.named" |
        grep -vxF -f - "$WORK/$cmd.tried" | tr '\n' ' ')
    missing=${missing% }
    stale=$(tr '\n' ' ' <"$WORK/$cmd.named_refused")
    stale=${stale% }
    same "$cmd --help names every option $cmd takes" "${missing# }" ""
    same "$cmd --help names no option $cmd refuses" "${stale# }" ""
done
exit 0
