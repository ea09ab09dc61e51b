#!/usr/bin/env bash
# End-to-end: facet optimize --shard I/N and facet merge, without a
# scheduler. The truth is the unsharded run, compared by SQLite itself
# (EXCEPT both ways over every column of options but the run id; a shard
# measures every option in full, so the unsharded truth does too,
# --measure all): the
# merge of an exhaustive or random run's shards is that run, option for
# option and rank for rank; the shards partition its points; merging again
# changes nothing; a missing shard is named and the run marked incomplete;
# shards of different runs and bad files are refused in one line, with the
# output left as it was.
# layers: study store cli
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/shard_lib.sh"

fixture roof40.obj "$WORK/roof.obj" || exit 1
ROOF=$WORK/roof.obj
# 6 x 6 grids x 4 thresholds = 144 options.
SPACE=(--u 10:15 --v 12:17 --threshold 1:4:1)

# shards DB... : runs facet optimize --shard I/N of SPACE into each DB.
make_shards() {
    local n=$1 prefix=$2
    shift 2
    local i
    for i in $(seq 1 "$n"); do
        "$FACET" optimize "$ROOF" --db "$prefix$i.db" "$@" --shard "$i/$n" \
            --table 1 >/dev/null 2>"$WORK/shard.err" ||
            { echo "not ok - shard $i/$n ran"; cat "$WORK/shard.err"; }
    done
}

# --- exhaustive: 3 shards (dealt by grid) merge into the unsharded run
expect "unsharded exhaustive run" 0 "$FACET" optimize "$ROOF" --db "$WORK/whole.db" "${SPACE[@]}" --measure all --table 1
make_shards 3 "$WORK/ex" "${SPACE[@]}" --jobs 1
# A partition: every number once, 1..144, none in two shards.
got=$(sqlite3 -batch "$WORK/ex1.db" "ATTACH '$WORK/ex2.db' AS b;
    ATTACH '$WORK/ex3.db' AS c;
    SELECT count(*), count(DISTINCT number), min(number), max(number) FROM
    (SELECT number FROM main.options UNION ALL SELECT number FROM b.options
     UNION ALL SELECT number FROM c.options)")
same "exhaustive shards partition the points" "$got" "144|144|1|144"
same "each shard holds a third of the grids" \
    "$(for i in 1 2 3; do sqlite3 -batch "$WORK/ex$i.db" 'SELECT count(*) FROM options'; done | tr '\n' ' ')" \
    "48 48 48 "
same "a shard records I/N with its run" \
    "$(sqlite3 -batch "$WORK/ex2.db" 'SELECT shard_index || "/" || shard_count FROM runs')" "2/3"
expect "runs shows a shard" 0 "$FACET" runs "$WORK/ex2.db"
stdout_has "runs names the shard" "done 2/3"

expect "merge of 3 shards" 0 "$FACET" merge "$WORK/merged.db" "$WORK/ex1.db" "$WORK/ex3.db" "$WORK/ex2.db"
stdout_has "merge says what it made" "run 1 merged from 3 of 3 shards: 144 options"
same_options "merged exhaustive run = unsharded, option for option and rank for rank" "$WORK/whole.db" "$WORK/merged.db"
same "the merged front's panels are stored as a run's are" \
    "$(sqlite3 -batch "$WORK/merged.db" 'SELECT count(*) FROM panel_sets')" \
    "$(sqlite3 -batch "$WORK/whole.db" 'SELECT count(*) FROM panel_sets')"

# Merging twice changes nothing: the same run, the same rows.
dump() { sqlite3 -batch "$1" "SELECT $(cols "$1") FROM options ORDER BY number" | md5sum; }
before=$(dump "$WORK/merged.db")
expect "merging again" 0 "$FACET" merge "$WORK/merged.db" "$WORK/ex1.db" "$WORK/ex2.db" "$WORK/ex3.db"
same "merging again changes nothing" \
    "$(dump "$WORK/merged.db") $(sqlite3 -batch "$WORK/merged.db" 'SELECT count(*) FROM runs')" "$before 1"
same "no temporary file is left" "$(ls "$WORK" | grep -c merge-)" "0"
# A complete merged run is not made less complete unasked (hardening round
# 3, item 4): merging again after two shard files were cleaned up is
# refused, the file untouched; --fewer asks for it.
sum=$(sha256sum <"$WORK/merged.db")
expect_error "merging 1 shard over a run of 3 of 3 is refused, naming both" \
    "run 1 there holds 3 of 3 shards merged; these 1 would replace it with fewer.*--fewer" \
    "$FACET" merge "$WORK/merged.db" "$WORK/ex2.db"
same "the complete run's file is untouched, no temporary file left" \
    "$(sha256sum <"$WORK/merged.db") $(ls "$WORK" | grep -c merge-)" "$sum 0"
# Nor is a file another Facet is writing replaced (round 3, item 2): the
# writer would go on into the file the merge renamed over, its options
# lost (before: both exited 0, the writer's run was left "running" with
# 192 of its options, beside the merged run). The writer is held
# (SIGSTOP) from its first option stored until the merge has answered: it
# is alive and its run running however long the merge takes, so its run
# needs no size that would outlast a merge on a loaded machine (it was
# 4,107 options, evaluated to the end below).
"$FACET" optimize "$ROOF" --db "$WORK/live.db" --u 4:40 --v 4:40 --threshold 2 \
    --jobs 1 --table 0 >/dev/null 2>&1 & writer=$!
for _ in $(seq 600); do
    [ "$(sqlite3 -batch "$WORK/live.db" 'SELECT count(*) FROM options' 2>/dev/null)" -gt 0 ] 2>/dev/null && break
    sleep 0.05
done
kill -STOP $writer
expect_error "merge into a file another facet is writing: refused, naming it" \
    "live\.db: run 1 in it is being written by process $writer on " \
    "$FACET" merge "$WORK/live.db" "$WORK/ex1.db" "$WORK/ex2.db" "$WORK/ex3.db"
kill -CONT $writer
wait $writer
same "the writer's run ends done with every option (SQLite counts them)" \
    "$(sqlite3 -batch "$WORK/live.db" "SELECT status, options, (SELECT count(*) FROM options) FROM runs")" \
    "done|1369|1369"
# Edited shards are refused, naming the shard and the option (round 3,
# item 3): before, a deleted option merged as 143 of 144, text 'NaN' read
# as a cost of 0, and +Inf, nu = 2e9, nv = -7 or shard 7 of 3 went through.
for edit in "DELETE FROM options WHERE number = 4|holds 47 options, and its run recorded 48" \
    "UPDATE options SET cost = 'NaN' WHERE number = 4|option 4: cost is 'NaN'" \
    "UPDATE options SET cost = 9e999 WHERE number = 4|option 4: cost is " \
    "UPDATE options SET planarity = -1 WHERE number = 4|option 4: planarity is -1" \
    "UPDATE options SET nu = 2e9 WHERE number = 4|option 4: nu is 2000000000" \
    "UPDATE options SET nv = -7 WHERE number = 4|option 4: nv is -7" \
    "UPDATE runs SET shard_index = 7|shard 7 of 3 is no shard"; do
    sql=${edit%%|*} pattern=${edit#*|}
    cp "$WORK/ex1.db" "$WORK/edited.db"
    sqlite3 -batch "$WORK/edited.db" "$sql"
    rm -f "$WORK/edited-out.db"
    run "$FACET" merge "$WORK/edited-out.db" "$WORK/edited.db" "$WORK/ex2.db" "$WORK/ex3.db"
    same "an edited shard ($sql): refused in one line, naming it, nothing written" \
        "$STATUS $(wc -l <"$ERR") $(grep -c "edited\.db: .*$pattern" "$ERR") $([ -e "$WORK/edited-out.db" ] && echo written)" "2 1 1 "
done
cp "$WORK/merged.db" "$WORK/fewer.db"
expect "--fewer replaces it with the one shard's options" 0 \
    "$FACET" merge "$WORK/fewer.db" "$WORK/ex2.db" --fewer
same "--fewer: 48 options, incomplete, 1 of 3" \
    "$(sqlite3 -batch "$WORK/fewer.db" 'SELECT options, shards_merged, shard_count FROM runs')" "48|1|3"

# --- 4 shards of 4 threshold steps on 2 grids: fewer grids than shards,
# dealt point by point
SMALL=(--u 10 --v 12:13 --threshold 1:4:1)
expect "unsharded small run" 0 "$FACET" optimize "$ROOF" --db "$WORK/small.db" "${SMALL[@]}" --measure all --table 1
make_shards 4 "$WORK/sm" "${SMALL[@]}"
expect "merge of 4 shards of 2 grids" 0 "$FACET" merge "$WORK/small-merged.db" "$WORK"/sm{1,2,3,4}.db
same_options "fewer grids than shards: merged = unsharded" "$WORK/small.db" "$WORK/small-merged.db"

# --- random: the unsharded run's draws dealt out
RANDOM_SPACE=(--u 10:30 --v 12:30 --threshold 1:6 --method random --evals 90 --seed 5)
expect "unsharded random run" 0 "$FACET" optimize "$ROOF" --db "$WORK/rand.db" "${RANDOM_SPACE[@]}" --measure all --table 1
make_shards 4 "$WORK/rs" "${RANDOM_SPACE[@]}"
expect "merge of 4 random shards" 0 "$FACET" merge "$WORK/rand-merged.db" "$WORK"/rs{1,2,3,4}.db
same_options "merged random run = unsharded" "$WORK/rand.db" "$WORK/rand-merged.db"

# --- NSGA-II: islands; island 1 keeps the run's seed, island 2 has its own
NSGA=(--u 10:20 --v 12:24 --threshold 1:20 --method nsga2 --pop 12 --gens 4 --seed 3)
expect "unsharded nsga2 run" 0 "$FACET" optimize "$ROOF" --db "$WORK/nsga.db" "${NSGA[@]}" --measure all --table 1
make_shards 2 "$WORK/ns" "${NSGA[@]}"
same_options "island 1 is the run with the run's seed" "$WORK/nsga.db" "$WORK/ns1.db"
same "island 2 searches other points (its own seed)" \
    "$(sqlite3 -batch "$WORK/ns1.db" "ATTACH '$WORK/ns2.db' AS b; SELECT count(*) = (SELECT count(*) FROM options) FROM (SELECT nu, nv, threshold_mm FROM main.options INTERSECT SELECT nu, nv, threshold_mm FROM b.options)")" "0"
expect "merge of 2 islands" 0 "$FACET" merge "$WORK/nsga-merged.db" "$WORK/ns1.db" "$WORK/ns2.db"
same "the merged islands hold each point of either once" \
    "$(sqlite3 -batch "$WORK/nsga-merged.db" 'SELECT count(*) FROM options')" \
    "$(sqlite3 -batch "$WORK/ns1.db" "ATTACH '$WORK/ns2.db' AS b; SELECT count(*) FROM (SELECT nu, nv, threshold_mm FROM main.options UNION SELECT nu, nv, threshold_mm FROM b.options)")"
same "the merged islands are ranked as one run" \
    "$(sqlite3 -batch "$WORK/nsga-merged.db" 'SELECT count(*) > 0, count(*) = (SELECT pareto_options FROM runs) FROM options WHERE rank = 1')" "1|1"

# --- a missing shard: named, the run marked incomplete, completed later
run "$FACET" merge "$WORK/part.db" "$WORK/ex1.db" "$WORK/ex3.db"
if [ "$STATUS" -eq 0 ] && grep -q "shard 2 of 3 missing" "$ERR"; then
    pass "a missing shard is named"
else
    fail "a missing shard is named"
fi
expect "runs of an incomplete merge" 0 "$FACET" runs "$WORK/part.db"
stdout_has "runs marks it incomplete" "incomplete"
expect "runs --json of an incomplete merge" 0 "$FACET" runs "$WORK/part.db" --json
json_check "runs --json says incomplete" 'j[0]["incomplete"] is True and j[0]["shards"] == 3'
expect "merging the missing shard in" 0 "$FACET" merge "$WORK/part.db" "$WORK/ex2.db" "$WORK/ex1.db" "$WORK/ex3.db"
same_options "completed later, the run is the unsharded one" "$WORK/whole.db" "$WORK/part.db"
expect "runs --json of the completed merge" 0 "$FACET" runs "$WORK/part.db" --json
json_check "no longer incomplete" 'len(j) == 1 and j[0]["incomplete"] is False'

# --- a shard stopped halfway: refused by the merge until resumed; resumed,
# it evaluates the rest of its share and the merge is the unsharded run
BIG=(--u 10:15 --v 12:17 --threshold 1:20:0.25)
expect "unsharded run of 2772 options" 0 "$FACET" optimize "$ROOF" --db "$WORK/big.db" "${BIG[@]}" --measure all --table 1
"$FACET" optimize "$ROOF" --db "$WORK/bs2.db" "${BIG[@]}" --shard 2/2 --table 1 >/dev/null 2>&1
"$FACET" optimize "$ROOF" --db "$WORK/bs1.db" "${BIG[@]}" --shard 1/2 --jobs 1 --table 1 >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 2000); do
    n=$(sqlite3 -batch "$WORK/bs1.db" 'SELECT count(*) FROM options' 2>/dev/null)
    [ "${n:-0}" -ge 1 ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.01
done
kill -INT "$pid" 2>/dev/null
wait "$pid"
stored=$(sqlite3 -batch "$WORK/bs1.db" 'SELECT count(*) FROM options')
if [ "$stored" -lt 1386 ]; then
    expect_error "a shard that is not done is refused" "shard 1/2 \(run 1\) is interrupted, not done" \
        "$FACET" merge "$WORK/big-merged.db" "$WORK/bs1.db" "$WORK/bs2.db"
else
    skip "a shard that is not done is refused" "the shard finished before it could be stopped"
fi
expect "the stopped shard resumes" 0 "$FACET" optimize --db "$WORK/bs1.db" --resume 1 --table 1
same "the resumed shard holds its share" \
    "$(sqlite3 -batch "$WORK/bs1.db" 'SELECT count(*), shard_index || "/" || shard_count FROM options, runs')" "1386|1/2"
expect "merge of a resumed shard" 0 "$FACET" merge "$WORK/big-merged.db" "$WORK/bs1.db" "$WORK/bs2.db"
same_options "merged with a resumed shard = unsharded" "$WORK/big.db" "$WORK/big-merged.db"

# --- the surface gone when the shards are merged: the run is merged and
# ranked all the same, its front's panels left to be computed when shown
mkdir "$WORK/away"
cp "$WORK"/ex{1,2,3}.db "$WORK/away/"
mv "$ROOF" "$WORK/roof.moved"
run "$FACET" merge "$WORK/away/merged.db" "$WORK"/away/ex{1,2,3}.db
if [ "$STATUS" -eq 0 ] && grep -q "panels are not stored" "$ERR"; then
    pass "a surface not found leaves the panels out, said"
else
    fail "a surface not found leaves the panels out, said"
fi
same_options "merged without its surface = unsharded" "$WORK/whole.db" "$WORK/away/merged.db"
mv "$WORK/roof.moved" "$ROOF"

# --- facet slurm's scripts, run by bash as Slurm would run them (the
# array's tasks one by one, then the merge): e2e/slurm.sh runs them
# under a real Slurm
expect "facet slurm writes its scripts" 0 "$FACET" slurm "$ROOF" --shards 3 \
    --results "$WORK/cluster" -- "${SPACE[@]}"
same "three scripts, each valid bash" \
    "$(for f in facet-shards.sbatch facet-merge.sbatch submit.sh; do bash -n "$WORK/cluster/$f" && echo ok; done | tr '\n' ' ')" "ok ok ok "
same "the array has a task per shard, the merge waits for all (afterok)" \
    "$(grep -c '^#SBATCH --array=1-3$' "$WORK/cluster/facet-shards.sbatch") $(grep -c '^merge=$(sbatch --parsable --dependency=afterok:' "$WORK/cluster/submit.sh")" "1 1"
same "each task works on node-local scratch" \
    "$(grep -c 'TMPDIR:-/tmp' "$WORK/cluster/facet-shards.sbatch")" "1"
for i in 1 2 3; do
    SLURM_ARRAY_TASK_ID=$i SLURM_CPUS_PER_TASK=1 TMPDIR=$WORK \
        bash "$WORK/cluster/facet-shards.sbatch" >/dev/null 2>&1 ||
        echo "not ok - shard task $i ran"
done
run bash "$WORK/cluster/facet-merge.sbatch"
if [ "$STATUS" -eq 0 ]; then pass "the merge script runs"; else fail "the merge script runs"; fi
same_options "the scripts' merged run = unsharded" "$WORK/whole.db" "$WORK/cluster/merged.db"
same "the results folder holds the finished files only" \
    "$(ls -A "$WORK/cluster" | grep -Ec '\.part$|-wal$|-shm$')" "0"
expect_error "facet slurm leaves the shard's own flags to its scripts" "slurm: .-db is the scripts' to set" \
    "$FACET" slurm "$ROOF" --shards 3 --results "$WORK/cluster" -- --db x.db
expect_error "facet slurm needs --shards and --results" "give --shards N and --results DIR" \
    "$FACET" slurm "$ROOF" --shards 3

# Values written into the scripts' #SBATCH lines are Slurm's words or
# refused (hardening round 3, item 5): a newline in --partition or --time
# put a shell command before "set -euo pipefail" in both scripts, a blank
# let options into the #SBATCH line. Nothing is written when refused.
marker=$WORK/injected
for bad in "--partition|$(printf 'x\ntouch %s' "$marker")" "--partition|gpu --qos=high" \
    "--partition|," "--time|$(printf '1:00\ntouch %s' "$marker")" "--time|1:00 --x" \
    "--time|1::00" "--time|-1"; do
    flag=${bad%%|*} value=${bad#*|}
    rm -rf "$WORK/inj"
    run "$FACET" slurm "$ROOF" --shards 2 --results "$WORK/inj" "$flag" "$value" -- "${SPACE[@]}"
    same "slurm $flag $(printf '%q' "$value"): refused in one line (2), no script written" \
        "$STATUS $(wc -l <"$ERR") $(grep -c "^facet: $flag: '.*' is not a Slurm" "$ERR") $(ls "$WORK/inj" 2>/dev/null | wc -l)" "2 1 1 0"
done
[ -e "$marker" ] && fail "no injected command ran" || pass "no injected command ran"
for good in "--partition|gpu" "--partition|gpu,cpu_1.a-b" "--time|30" "--time|30:00" \
    "--time|02:00:00" "--time|1-12" "--time|1-12:30" "--time|7-00:00:00" "--time|UNLIMITED"; do
    flag=${good%%|*} value=${good#*|}
    rm -rf "$WORK/ok"
    run "$FACET" slurm "$ROOF" --shards 2 --results "$WORK/ok" "$flag" "$value" -- "${SPACE[@]}"
    same "slurm $flag $value: written as given, valid bash" \
        "$STATUS $(grep -c "^#SBATCH $flag=$value\$" "$WORK/ok/facet-shards.sbatch") $(bash -n "$WORK/ok/facet-shards.sbatch" && bash -n "$WORK/ok/facet-merge.sbatch" && echo bash)" \
        "0 1 bash"
done
# The options after -- are checked by optimize's own parser, in the call
# the shard script makes: what every array task would refuse is refused
# here, in optimize's words, and no script is written.
for bad in "--modul 1x1|unknown option '--modul' \(did you mean --module\?\)" \
    "--threshold banana|--threshold: 'banana' is not" "-j4|unknown option '-j4'" \
    "--u 0:5|--u: '0:5' is out of range" "--objectives nosuch|nosuch"; do
    args=${bad%%|*} pattern=${bad#*|}
    rm -rf "$WORK/inj"
    # shellcheck disable=SC2086
    run "$FACET" slurm "$ROOF" --shards 2 --results "$WORK/inj" -- $args
    same "slurm -- $args: refused as optimize refuses it, no script written" \
        "$STATUS $(wc -l <"$ERR") $(grep -cE "^facet: slurm: facet optimize would refuse the options after --, on every node: .*$pattern" "$ERR") $(ls "$WORK/inj" 2>/dev/null | wc -l)" "2 1 1 0"
done

# --- refusals: one line, status 2, the output as it was
out_sum=$(sha256sum "$WORK/merged.db" | cut -d' ' -f1)
"$FACET" optimize "$ROOF" --db "$WORK/other.db" --u 10:15 --v 12:17 --threshold 1:5:1 --shard 2/3 --table 1 >/dev/null 2>&1
expect_error "shards of other settings are refused, naming the setting" \
    "other\.db \(shard 2/3\) differs from .*ex1\.db in its threshold" \
    "$FACET" merge "$WORK/merged.db" "$WORK/ex1.db" "$WORK/other.db"
# Panels as built are settings too: a shard typed by class alone, or held
# to a kink limit, prices other options than one built as the default.
"$FACET" optimize "$ROOF" --db "$WORK/byclass.db" "${SPACE[@]}" --sp-fit no --shard 2/3 --table 1 >/dev/null 2>&1
expect_error "a shard of another SP typing is refused, naming it" \
    "byclass\.db \(shard 2/3\) differs from .*ex1\.db in its panels as built" \
    "$FACET" merge "$WORK/merged.db" "$WORK/ex1.db" "$WORK/byclass.db"
"$FACET" optimize "$ROOF" --db "$WORK/kink.db" "${SPACE[@]}" --max-kink 5 --shard 2/3 --table 1 >/dev/null 2>&1
expect_error "a shard of another kink limit is refused, naming it" \
    "kink\.db \(shard 2/3\) differs from .*ex1\.db in its panels as built" \
    "$FACET" merge "$WORK/merged.db" "$WORK/ex1.db" "$WORK/kink.db"
"$FACET" example roof --res 30 -o "$WORK/roof2.obj" >/dev/null
"$FACET" optimize "$WORK/roof2.obj" --db "$WORK/surf.db" "${SPACE[@]}" --shard 2/3 --table 1 >/dev/null 2>&1
expect_error "shards of another surface are refused" "made from another surface" \
    "$FACET" merge "$WORK/merged.db" "$WORK/ex1.db" "$WORK/surf.db"
expect_error "a shard given twice is refused" "both shard 1/3" \
    "$FACET" merge "$WORK/merged.db" "$WORK/ex1.db" "$WORK/ex1.db"
expect_error "an unsharded run is not a shard" "holds no shard" \
    "$FACET" merge "$WORK/merged.db" "$WORK/whole.db"
in_sum=$(sha256sum "$WORK/ex1.db" | cut -d' ' -f1)
expect_error "the output being a shard is refused" "is one of the shards" \
    "$FACET" merge "$WORK/ex1.db" "$WORK/ex1.db" "$WORK/ex2.db"
same "that shard is untouched" "$(sha256sum "$WORK/ex1.db" | cut -d' ' -f1)" "$in_sum"
head -c 4096 /dev/urandom >"$WORK/noise.db"
expect_error "a file that is no database is refused" "noise\.db" \
    "$FACET" merge "$WORK/merged.db" "$WORK/ex1.db" "$WORK/noise.db"
# A shard damaged on its way (a b-tree page's header overwritten): every
# page is read before anything is merged.
cp "$WORK/ex2.db" "$WORK/damaged.db"
printf '\x0d\xff\xff\xff\xff\xff\xff\xff' |
    dd of="$WORK/damaged.db" bs=1 seek=$((4096 * 4)) conv=notrunc status=none
expect_error "a damaged shard is refused" "damaged\.db: the database is damaged" \
    "$FACET" merge "$WORK/merged.db" "$WORK/ex1.db" "$WORK/damaged.db" "$WORK/ex3.db"
sqlite3 -batch "$WORK/foreign.db" "CREATE TABLE t(x); INSERT INTO t VALUES (1);"
expect_error "another application's database is refused" "another application" \
    "$FACET" merge "$WORK/merged.db" "$WORK/ex1.db" "$WORK/foreign.db"
expect_error "an output of another application is refused" "another application" \
    "$FACET" merge "$WORK/foreign.db" "$WORK/ex1.db" "$WORK/ex2.db" "$WORK/ex3.db"
same "the output is as it was after every refusal" \
    "$(sha256sum "$WORK/merged.db" | cut -d' ' -f1)" "$out_sum"
same "no temporary file is left after the refusals" "$(ls "$WORK" | grep -c merge-)" "0"
expect_error "--shard out of range" "shard: '4/3' is not I/N" \
    "$FACET" optimize "$ROOF" --db "$WORK/bad.db" --shard 4/3
expect_error "--shard not I/N" "shard: 'two' is not I/N" \
    "$FACET" optimize "$ROOF" --db "$WORK/bad.db" --shard two
expect_error "merge without shards" "name the output and the shards" "$FACET" merge "$WORK/x.db"

# A read-only folder: refused in one line, nothing written there.
if [ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null; then
    as_user() { setpriv --reuid=nobody --regid=nogroup --clear-groups "$@"; }
    mkdir "$WORK/ro"
    cp "$WORK"/ex{1,2,3}.db "$WORK/ro/"
    chmod 755 "$WORK"; chmod 644 "$WORK"/ro/*.db; chmod 555 "$WORK/ro"
    expect_error "a read-only folder is refused in one line" "cannot write beside it" \
        as_user "$FACET" merge "$WORK/ro/out.db" "$WORK/ro/ex1.db" "$WORK/ro/ex2.db" "$WORK/ro/ex3.db"
    same "nothing was written in it" "$(ls "$WORK/ro" | grep -vc '^ex[123]\.db')" "0"
    chmod 755 "$WORK/ro"; chmod 700 "$WORK"
else
    skip "read-only folder check" "it needs root and setpriv to act as another user"
fi
