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

# taken CMD FLAG: 0 when CMD does not refuse FLAG as unknown.
taken() {
    local said
    said=$("$FACET" "$1" "$2" 2>&1 </dev/null >/dev/null)
    [[ $said != *"unknown option '$2'"* && $said != *"unknown command '$2'"* ]]
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
    for flag in $(cat "$WORK/long" "$WORK/short"); do
        [ "$flag" = "--help" ] && continue   # every command's, said once
        if taken "$cmd" "$flag" && ! grep -qxF -- "$flag" "$WORK/$cmd.named"; then
            missing="$missing $flag"
        fi
    done
    for flag in $(cat "$WORK/$cmd.named"); do
        taken "$cmd" "$flag" || stale="$stale $flag"
    done
    same "$cmd --help names every option $cmd takes" "${missing# }" ""
    same "$cmd --help names no option $cmd refuses" "${stale# }" ""
done
exit 0
