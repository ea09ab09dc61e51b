# tui_lib.sh: driving facet tui in tmux, for the end-to-end scripts that
# test the terminal UI. Source it after lib.sh. Every session gets its own
# tmux server (reusing one right after kill-server races the old server's
# exit); the last one is killed, and its socket removed, on exit.

if ! command -v tmux >/dev/null; then
    echo "skip - every terminal UI check (tmux is not installed)"
    exit 0
fi

SESSIONS=0
SOCKET=
TMUX_CMD=(true)
end_session() {
    [ -n "$SOCKET" ] || return 0
    "${TMUX_CMD[@]}" kill-server 2>/dev/null
    rm -f "${TMUX_TMPDIR:-/tmp}/tmux-$(id -u)/$SOCKET"
    SOCKET=
}
trap 'end_session; rm -rf "$WORK"' EXIT
# A sanitizer build is slower: give every step up to 30 s.
POLLS=${TUI_POLLS:-600}

# start W H ENV... -- ARGS...: facet tui ARGS in a fresh W x H session in
# $WORK; its exit status goes to $WORK/exit, its stderr to $WORK/tui.err.
start() {
    local w=$1 h=$2
    shift 2
    local env=()
    while [ "$1" != -- ]; do env+=("$1"); shift; done
    shift
    rm -f "$WORK/exit" "$WORK/pid"
    end_session
    SESSIONS=$((SESSIONS + 1))
    SOCKET=facet_test_$$_$SESSIONS
    TMUX_CMD=(tmux -L "$SOCKET" -f /dev/null)
    "${TMUX_CMD[@]}" new-session -d -x "$w" -y "$h" \
        "cd '$WORK' && env TERM=xterm-256color ${env[*]} sh -c 'echo \$\$ > pid; exec \"\$0\" tui \"\$@\"' '$FACET' $* 2>'$WORK/tui.err'; echo \$? > '$WORK/exit'; echo EXITED; sleep 600"
}
screen() { "${TMUX_CMD[@]}" capture-pane -p; }
keys() { "${TMUX_CMD[@]}" send-keys "$@"; }

# wait_for PATTERN: polls the screen until it matches (grep -E).
wait_for() {
    local i=0
    while [ $i -lt $POLLS ]; do
        if screen | grep -qE -- "$1"; then return 0; fi
        sleep 0.05
        i=$((i + 1))
    done
    return 1
}
# check NAME PATTERN: passes when the screen comes to match PATTERN.
check() {
    if wait_for "$2"; then
        pass "$1"
    else
        echo "not ok - $1 (screen lacks: $2)"
        screen | sed 's/^/  screen: /'
    fi
}
# check_not NAME PATTERN: passes when the screen (already settled) lacks
# PATTERN.
check_not() {
    if screen | grep -qE -- "$2"; then
        echo "not ok - $1 (screen has: $2)"
        screen | sed 's/^/  screen: /'
    else
        pass "$1"
    fi
}
# check_line NAME N PATTERN: line N of the screen comes to match PATTERN.
check_line() {
    local i=0
    while [ $i -lt $POLLS ]; do
        if screen | sed -n "$2p" | grep -qE -- "$3"; then pass "$1"; return; fi
        sleep 0.05
        i=$((i + 1))
    done
    echo "not ok - $1 (line $2 lacks: $3)"
    screen | sed 's/^/  screen: /'
}
# check_exit NAME: facet tui ended with status 0, nothing on stderr, and
# the terminal is out of the alternate screen.
check_exit() {
    local i=0
    while [ ! -s "$WORK/exit" ] && [ $i -lt $POLLS ]; do sleep 0.05; i=$((i + 1)); done
    local alt
    alt=$("${TMUX_CMD[@]}" display -p '#{alternate_on}' 2>/dev/null)
    if [ "$(cat "$WORK/exit" 2>/dev/null)" = 0 ] && [ ! -s "$WORK/tui.err" ] &&
        [ "$alt" = 0 ]; then
        pass "$1"
    else
        echo "not ok - $1 (exit '$(cat "$WORK/exit" 2>/dev/null)', alternate screen '$alt')"
        sed 's/^/  stderr: /' "$WORK/tui.err" | head -n 20
    fi
}
