#!/usr/bin/env bash
# End-to-end: make install (issue 32 item 14) installs facet as a Unix tool:
# the binary, a manual page that man renders without a warning and that
# holds every command and every flag --help names, and a bash completion
# that completes the commands, each command's flags and the columns of
# --sort and --where; PREFIX and DESTDIR are honoured and make uninstall
# removes all three. The truths are outside Facet's generators: --help's
# own text, man and groff, bash itself, and the columns of a store as
# sqlite3 reads them (pragma_table_info).
# layers: cli store core
. "$(dirname "$0")/lib.sh"

ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${BUILD:-build/release}
VARIANT=$(basename "$BUILD")
DEST=$WORK/dest
cd "$WORK" || exit 1

# make install of this build's facet, as it is (-o: not rebuilt here).
install_into() {
    make -s -C "$ROOT" VARIANT="$VARIANT" -o "$BUILD/facet" "$@" \
        >"$OUT" 2>"$ERR"
    STATUS=$?
}

install_into install DESTDIR="$DEST"
if [ "$STATUS" -eq 0 ]; then pass "make install DESTDIR=... exits 0"; else fail "make install DESTDIR=..."; fi
BIN=$DEST/usr/local/bin/facet
PAGE=$DEST/usr/local/share/man/man1/facet.1
COMPLETION=$DEST/usr/local/share/bash-completion/completions/facet
for f in "$BIN" "$PAGE" "$COMPLETION"; do
    if [ -f "$f" ]; then pass "installed ${f#"$DEST"}"; else echo "not ok - installed ${f#"$DEST"}"; fi
done
if [ -x "$BIN" ] && cmp -s "$BIN" "$FACET"; then
    pass "the installed facet is this build's, executable"
else
    echo "not ok - the installed facet is this build's, executable"
fi

install_into install DESTDIR="$DEST" PREFIX=/opt/facet
if [ "$STATUS" -eq 0 ] && [ -x "$DEST/opt/facet/bin/facet" ] &&
    [ -f "$DEST/opt/facet/share/man/man1/facet.1" ] &&
    [ -f "$DEST/opt/facet/share/bash-completion/completions/facet" ]; then
    pass "PREFIX=/opt/facet installs under it"
else
    fail "PREFIX=/opt/facet installs under it"
fi

# The page: man renders it without a warning, and `man facet` finds it.
LC_ALL=C.UTF-8 MANWIDTH=100 man --warnings -l "$PAGE" >page.txt 2>warnings.txt
STATUS=$?
same "man -l renders the page (status)" "$STATUS" 0
same "man -l renders the page without warnings" "$(head -c 400 warnings.txt)" ""
groff -man -ww -z "$PAGE" 2>groff.txt
same "groff -ww finds nothing to warn of" "$(head -c 400 groff.txt)" ""
LC_ALL=C.UTF-8 MANPATH=$DEST/usr/local/share/man man -P cat facet >found.txt 2>&1
if grep -q "facet help" found.txt; then pass "man facet finds the page on its MANPATH"; else echo "not ok - man facet finds the page on its MANPATH"; head -n 3 found.txt; fi

# Every command of facet --help has its section, with its summary and
# every flag of its own --help.
"$FACET" --help >overview.txt
commands=$(sed -n 's/^  \([a-z][a-z]*\)  .*/\1/p' overview.txt)
[ -n "$commands" ] || echo "not ok - facet --help lists the commands"
for cmd in $commands; do
    "$FACET" "$cmd" --help >"$cmd.help"
done
if report=$(/usr/bin/python3 - page.txt $commands <<'PY'
import re, sys
page = open(sys.argv[1], encoding="utf-8").read().replace("\u2010", "-")
# backspace overstriking, in case a pager was not told to drop it
page = re.sub(r".\x08", "", page)
lines = page.split("\n")
start = lines.index("COMMANDS")
end = lines.index("EXIT STATUS")
sections, name = {}, None
for line in lines[start + 1:end]:
    m = re.match(r"^   (\S+)$", line)
    if m:
        name = m.group(1)
        sections[name] = []
    elif name:
        sections[name].append(line)
flat = lambda text: " ".join(text.split())
bad = []
for cmd in sys.argv[2:]:
    if cmd not in sections:
        bad.append("no section for " + cmd)
        continue
    body = flat("\n".join(sections[cmd]))
    help_text = open(cmd + ".help", encoding="utf-8").read()
    summary = flat(help_text.split("\n\n")[1])
    if summary not in body:
        bad.append(cmd + ": summary missing: " + summary)
    if "facet " + cmd + " " not in body:
        bad.append(cmd + ": usage missing")
    option_lines = help_text.split("\noptions:\n", 1)[1] if "\noptions:\n" in help_text else ""
    flags = set()
    for line in option_lines.split("\n"):
        if re.match(r"^  (-|[A-Z][A-Za-z.]*, -)", line):
            left = re.split(r"  ", line[2:])[0]
            flags.update(re.findall(r"(?:^| )(--?[a-z][a-z0-9-]*)", left))
    for flag in sorted(flags):
        if not re.search(r"(^|[\s,\[|])" + re.escape(flag) + r"([\s,=\]|]|$)", body):
            bad.append(cmd + ": flag missing: " + flag)
    print("%s: %d flags" % (cmd, len(flags)))
extra = set(sections) - set(sys.argv[2:])
if extra:
    bad.append("sections of no command: " + ", ".join(sorted(extra)))
if bad:
    print("\n".join(bad))
    sys.exit(1)
PY
); then
    pass "the page holds every command of facet --help, its summary, usage and every flag ($(echo "$report" | paste -sd' ' | cut -c1-200))"
else
    echo "not ok - the page holds every command of facet --help, its summary, usage and every flag"
    printf '%s\n' "$report" | grep -v ': [0-9]* flags$' | head -n 20 | sed 's/^/  /'
fi

# The completion, sourced into a plain bash and called as bash calls it.
# complete WORD...: what _facet offers for the last word.
complete_words() {
    bash --norc --noprofile -c '. "$1"; shift; COMP_WORDS=("$@");
        COMP_CWORD=$(($# - 1)); _facet; printf "%s\n" "${COMPREPLY[@]}"' \
        _ "$COMPLETION" "$@" | sort
}
offers() {   # offers NAME WANTED WORD...: every line of WANTED is offered
    local name=$1 wanted=$2
    shift 2
    local missing
    missing=$(comm -23 <(printf '%s\n' "$wanted" | sort -u) <(complete_words "$@"))
    same "$name" "$(echo $missing)" ""
}
offers "completion: facet op<TAB> offers optimize and options" \
    "$(printf 'optimize\noptions\n')" facet op
same "completion: facet op<TAB> offers nothing else" \
    "$(complete_words facet op | paste -sd' ')" "optimize options"
offers "completion: facet <TAB> offers every command of facet --help" \
    "$commands" facet ""
for cmd in $commands; do
    flags=$(sed -n '/^options:$/,$p' "$cmd.help" |
        grep -E -- '^  (-|[A-Z][A-Za-z.]*, -)' | sed -E 's/^  //; s/  .*//' |
        grep -oE -- '(^| )--[a-z][a-z0-9-]*' | tr -d ' ' | sort -u)
    offers "completion: facet $cmd --<TAB> offers every --flag of its --help" \
        "$flags" facet "$cmd" --
done
same "completion: facet classify --sp-<TAB>" \
    "$(complete_words facet classify --sp- | paste -sd' ')" "--sp-as-fp --sp-fit"

# A flag of a fixed set of values offers them (issue 32 item 15), and
# facet takes each: the truth is facet's own refusal of any other value.
same "completion: --sp-fit <TAB>" \
    "$(complete_words facet classify x.obj --sp-fit "" | paste -sd' ')" "no yes"
same "completion: --units <TAB>" \
    "$(complete_words facet info x.obj --units "" | paste -sd' ')" "cm ft in m mm"
same "completion: --units=c<TAB>" \
    "$(complete_words facet optimize x.obj --units = c | paste -sd' ')" "cm"
same "completion: --method n<TAB>" \
    "$(complete_words facet optimize x.obj --method n | paste -sd' ')" "nsga2"
same "completion: export --colour <TAB>" \
    "$(complete_words facet export r.db --colour "" | paste -sd' ')" "class type"
"$FACET" example plane --res 6 -o choice.obj >/dev/null 2>&1
# accepted: each value offered, given to the command, is not refused as
# a value of that flag
bad=""
for pair in "classify|--sp-fit" "classify|--units" "classify|--per-panel" \
    "classify|--uv" "info|--uv" "info|--units" "optimize|--method" \
    "optimize|--measure" "optimize|--store-panels"; do
    cmd=${pair%%|*} flag=${pair#*|}
    values=$(complete_words facet "$cmd" choice.obj "$flag" "")
    [ -n "$values" ] || bad="$bad $cmd $flag: nothing offered;"
    for value in $values; do
        case $cmd in
        classify) set -- --grid 2x2 ;;
        optimize) set -- --db "opt-$flag-$value.db" --u 2:2 --v 2:2 --table 1 ;;
        *) set -- ;;
        esac
        "$FACET" "$cmd" choice.obj "$@" "$flag" "$value" >/dev/null 2>"$ERR" ||
            bad="$bad $cmd $flag $value: $(head -c 160 "$ERR");"
    done
done
same "every value completion offers for a fixed-choice flag is taken" "${bad# }" ""
# facet slurm passes the words after -- to optimize: they complete as
# optimize's flags and values.
offers "completion: facet slurm x.obj -- --<TAB> offers optimize's flags" \
    "$(printf -- '--module\n--threshold\n--objectives\n--method\n')" facet slurm x.obj --shards 2 -- --
same "completion: facet slurm x.obj -- --method <TAB> offers optimize's methods" \
    "$(complete_words facet slurm x.obj -- --method "" | paste -sd' ')" "auto exhaustive nsga2 random"
same "completion: before --, facet slurm's own flags" \
    "$(complete_words facet slurm x.obj --se | paste -sd' ')" "--setup"

# The columns: every column of a store's options table, as sqlite3 reads it.
"$FACET" example plane --res 6 -o p.obj >/dev/null 2>&1
"$FACET" optimize p.obj --db p.db --u 2:3 --v 2:3 >/dev/null 2>&1
columns=$(sqlite3 p.db "SELECT name FROM pragma_table_info('options')")
if [ "$(echo "$columns" | wc -l)" -gt 40 ]; then
    pass "the store has its options columns ($(echo "$columns" | wc -l))"
else
    echo "not ok - the store has its options columns"
fi
offers "completion: --sort <TAB> offers every column of the options table" \
    "$columns" facet options p.db --sort ""
same "completion: --sort dp_a<TAB>" \
    "$(complete_words facet options p.db --sort dp_a)" "dp_area"
same "completion: --sort=cost,dp_a<TAB>" \
    "$(complete_words facet options p.db --sort = cost,dp_a)" "cost,dp_area"
same "completion: --where 'knee and max_g<TAB>'" \
    "$(complete_words facet options p.db --where "knee and max_g")" \
    "knee and max_gap"
offers "completion: --where <TAB> offers every column too" \
    "$columns" facet options p.db --where ""
same "completion: --run <TAB> offers no flag" \
    "$(complete_words facet options p.db --run "")" ""
# each column offered works as a --sort key (ten keys a call: a sanitizer
# build starts slowly)
bad=""
offered=$(complete_words facet options p.db --sort "" | paste -sd' ')
set -- $offered
while [ $# -gt 0 ]; do
    keys=$(echo "${@:1:10}" | tr ' ' ,)
    "$FACET" options p.db --sort "$keys" --limit 1 >/dev/null 2>"$ERR" ||
        bad="$bad $keys: $(head -c 200 "$ERR")"
    shift $(($# < 10 ? $# : 10))
done
same "every column completion offers is a --sort key facet takes" "${bad# }" ""

# make uninstall takes the three away.
install_into uninstall DESTDIR="$DEST"
left=$(find "$DEST/usr/local" -type f | sed "s|^$DEST||")
if [ "$STATUS" -eq 0 ] && [ -z "$left" ]; then
    pass "make uninstall removes them"
else
    fail "make uninstall removes them (left: $left)"
fi
exit 0
