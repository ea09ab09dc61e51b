#!/usr/bin/env bash
# End-to-end: every fuzz target of tests/fuzz replays its seed corpus and
# every input that once crashed it (tests/fuzz/crashes/NAME), in the
# build's own variant (ASan + UBSan in build/san): a crash found by
# `make fuzz` stays a regression test.
# layers: core store
. "$(dirname "$0")/lib.sh"
root=$(cd "$(dirname "$0")/../.." && pwd)
for replay in "$root/$BUILD"/fuzz/replay_*; do
    [ -x "$replay" ] || continue
    name=${replay##*/replay_}
    run "$replay" "$root/tests/fuzz/corpus/$name" "$root/tests/fuzz/crashes/$name"
    if [ "$STATUS" -eq 0 ] && grep -q "corpus/$name: [1-9][0-9]* inputs replayed" "$OUT"; then
        pass "fuzz_$name: its corpus and crash inputs replay ($(grep -o '[0-9]* inputs' "$OUT" | paste -sd+ -))"
    else
        fail "fuzz_$name: its corpus and crash inputs replay"
    fi
done
exit 0
