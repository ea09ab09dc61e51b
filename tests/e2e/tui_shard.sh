#!/usr/bin/env bash
# End-to-end: the workbench's runs list says what `facet runs` says of
# shards and merges: a shard's status carries its I/N, and a merge that
# lacks a shard reads "incomplete", not "done" (its status alone says the
# merge finished, not that the run is whole).
# layers: tui
. "$(dirname "$0")/lib.sh"

. "$(dirname "$0")/tui_lib.sh"

"$FACET" example roof --res 20 -o "$WORK/roof.obj" || exit 1
for i in 1 2 3; do
    "$FACET" optimize "$WORK/roof.obj" --db "$WORK/s$i.db" --u 4:6 --v 4:6 \
        --threshold 3 --shard "$i/3" >/dev/null 2>&1 || exit 1
done
"$FACET" merge "$WORK/part.db" "$WORK/s1.db" "$WORK/s3.db" >/dev/null 2>&1
runs_says=$(sqlite3 -batch "$WORK/part.db" \
    'SELECT shard_count, shards_merged FROM runs')
same "the merge of 2 of 3 shards is recorded as such" "$runs_says" "3|2"

start 100 24 -- part.db
check "the runs list" 'runs'
check "a merge lacking a shard reads incomplete" '^ +1 incomplete '
keys F10
check_exit "quit"

start 100 24 -- s2.db
check "the runs list of a shard" 'runs'
check "a shard reads its status and I/N" '^ +1 done 2/3 '
keys F10
check_exit "quit"
exit 0
