#!/usr/bin/env bash
# End-to-end, without a cluster: facet slurm as an HPC user expects it
# (issue 32 item 15). It makes the results folder (mkdir -p) or says in
# one line why it cannot; it takes --mem, --account, --qos, extra #SBATCH
# lines and a setup line, refusing what would break a script, and what
# it writes is valid bash whose values read back as given (bash itself
# is the truth); it warns, a line each, of a surface, binary or results
# folder on a node's own disk; and after a failed shard, the shard's log
# and submit.sh's text give the scancel and sbatch commands, which are
# run here against stand-ins for scancel and sbatch that record what
# they are asked. e2e/slurm.sh submits to a real Slurm.
# layers: cli
. "$(dirname "$0")/lib.sh"

BUILD=${BUILD:-build/release}
"$FACET" example roof --res 12 -o "$WORK/roof.obj" >/dev/null || exit 1
ROOF=$WORK/roof.obj
SPACE=(--u 3:4 --v 3:4 --threshold 2)
# A folder that is no node's own (not /tmp, /var/tmp, /dev/shm or
# $TMPDIR): beside the build.
SHARED=$(mktemp -d "$PWD/$BUILD/e2e-slurm.XXXXXX") || exit 1
trap 'rm -rf "$WORK" "$SHARED"' EXIT
cp "$ROOF" "$SHARED/roof.obj"

# --- the results folder: made with its parents, or refused in one line
run "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/a/b/c" -- "${SPACE[@]}"
same "a results folder two levels down is made, parents too, scripts in it" \
    "$STATUS $(ls "$SHARED/a/b/c" 2>/dev/null | paste -sd' ')" \
    "0 facet-merge.sbatch facet-shards.sbatch submit.sh"
run "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/r2" -o "$SHARED/s/t" -- "${SPACE[@]}"
same "-o FOLDER is made with its parents too, the results folder as well" \
    "$STATUS $(ls "$SHARED/s/t" 2>/dev/null | wc -l) $([ -d "$SHARED/r2" ] && echo made)" "0 3 made"
run "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/a/b/c" -- "${SPACE[@]}"
same "an existing results folder is taken as it is" "$STATUS" "0"
touch "$SHARED/file"
expect_error "a file in the way of the results folder is named" \
    "^facet: --results: .*/file is a file, not a folder" \
    "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/file/sub" -- "${SPACE[@]}"
expect_error "a file where the results folder goes is named" \
    "^facet: --results: .*/file is a file, not a folder" \
    "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/file" -- "${SPACE[@]}"
# A parent that cannot be written: read-only for a user; root writes
# anywhere but on a read-only filesystem.
mkdir "$SHARED/ro"
if [ "$(id -u)" -eq 0 ]; then
    if mount -t tmpfs -o ro,size=64k tmpfs "$SHARED/ro" 2>/dev/null; then
        expect_error "a read-only parent is said, in one line" \
            "^facet: --results: cannot make the folder .*/ro/sub: Read-only file system" \
            "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/ro/sub" -- "${SPACE[@]}"
        umount "$SHARED/ro"
    else
        skip "a read-only parent is said, in one line" "no tmpfs could be mounted read-only"
    fi
else
    chmod 555 "$SHARED/ro"
    expect_error "a read-only parent is said, in one line" \
        "^facet: --results: cannot make the folder .*/ro/sub: Permission denied" \
        "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/ro/sub" -- "${SPACE[@]}"
    chmod 755 "$SHARED/ro"
fi

# --- node-local paths: a warning each, on stderr, none for shared ones
run "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/w1" -- "${SPACE[@]}"
same "shared surface, binary and results: no warning" "$STATUS $(wc -l <"$ERR")" "0 0"
run "$FACET" slurm "$ROOF" --shards 2 --results "$SHARED/w2" -- "${SPACE[@]}"
same "a surface under /tmp: one warning line naming it and /tmp" \
    "$STATUS $(wc -l <"$ERR") $(grep -c "^facet: warning: slurm: the surface $ROOF is under /tmp, " "$ERR")" "0 1 1"
run "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/w3" --facet /var/tmp/bin/facet -- "${SPACE[@]}"
same "a binary under /var/tmp: one warning line naming it" \
    "$STATUS $(wc -l <"$ERR") $(grep -c '^facet: warning: slurm: the facet binary /var/tmp/bin/facet is under /var/tmp, ' "$ERR")" "0 1 1"
run "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results /dev/shm/facet-e2e-$$ --facet /opt/facet/bin/facet -- "${SPACE[@]}"
same "a results folder under /dev/shm: one warning line" \
    "$STATUS $(wc -l <"$ERR") $(grep -c "^facet: warning: slurm: the results folder /dev/shm/facet-e2e-$$ is under /dev/shm, " "$ERR")" "0 1 1"
rm -rf "/dev/shm/facet-e2e-$$"
mkdir "$SHARED/scratch"
cp "$ROOF" "$SHARED/scratch/roof.obj"
TMPDIR=$SHARED/scratch run "$FACET" slurm "$SHARED/scratch/roof.obj" --shards 2 --results "$SHARED/w4" -- "${SPACE[@]}"
same "a surface under \$TMPDIR (a job's scratch): one warning, naming \$TMPDIR" \
    "$STATUS $(wc -l <"$ERR") $(grep -c "^facet: warning: slurm: the surface $SHARED/scratch/roof.obj is under \$TMPDIR ($SHARED/scratch), " "$ERR")" "0 1 1"

# --- the site's settings, as #SBATCH lines of both scripts
S=$SHARED/site
run "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$S" --mem 16G --account proj_42 \
    --qos high.prio --sbatch '--gres=gpu:1' --sbatch '--mail-type=END' -- "${SPACE[@]}"
for f in facet-shards.sbatch facet-merge.sbatch; do
    same "$f: --mem, --account, --qos and each --sbatch line, in order, before any command" \
        "$STATUS $(sed -n '/^#SBATCH --mem/,/^#SBATCH --mail/p' "$S/$f" | paste -sd'|')" \
        "0 #SBATCH --mem=16G|#SBATCH --account=proj_42|#SBATCH --qos=high.prio|#SBATCH --gres=gpu:1|#SBATCH --mail-type=END"
    # sbatch reads #SBATCH lines up to the first command
    same "$f: no command before its last #SBATCH line" \
        "$(awk '/^#SBATCH/ {last = NR} !/^#/ && !first {first = NR} END {print (last < first)}' "$S/$f")" "1"
done
for good in "--mem|4000" "--mem|512M" "--mem|2g" "--account|a.b-c_1" "--qos|normal"; do
    flag=${good%%|*} value=${good#*|}
    run "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/ok" "$flag" "$value" -- "${SPACE[@]}"
    same "slurm $flag $value: written as given" \
        "$STATUS $(grep -c "^#SBATCH $flag=$value\$" "$SHARED/ok/facet-shards.sbatch")" "0 1"
done
marker=$WORK/injected
for bad in "--mem|4 GB|is not a Slurm memory size" "--mem|$(printf '4G\ntouch %s' "$marker")|is not a Slurm memory size" \
    "--mem|G|is not a Slurm memory size" "--account|a b|is not a Slurm name" \
    "--qos|high --partition=x|is not a Slurm name" "--qos|\$(touch $marker)|is not a Slurm name" \
    "--sbatch|$(printf -- '--gres=gpu:1\ntouch %s' "$marker")|holds a line break" \
    "--sbatch|--time=1:00|sets --time, which facet slurm writes from its own flag: give --time T" \
    "--sbatch|-c 4|sets --cpus-per-task, .*give --cpus C" \
    "--sbatch|--part=gpu|sets --partition" "--sbatch|--array=1-9|sets --array, which the scripts set" \
    "--sbatch|--output /x/%j.log|sets --output" "--sbatch|-d afterok:1|sets --dependency" \
    "--sbatch|gres=gpu:1|is not an sbatch option" \
    "--setup|$(printf 'module load x\ntouch %s' "$marker")|--setup: .* holds a line break"; do
    flag=${bad%%|*} rest=${bad#*|}
    value=${rest%|*} pattern=${rest##*|}
    rm -rf "$SHARED/inj"
    run "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/inj" "$flag" "$value" -- "${SPACE[@]}"
    same "slurm $flag $(printf '%q' "$value"): refused in one line (2), no script written" \
        "$STATUS $(wc -l <"$ERR") $(grep -cE -- "^facet: .*$pattern" "$ERR") $(ls "$SHARED/inj" 2>/dev/null | wc -l)" "2 1 1 0"
done
expect_error "--sbatch --mem-per-cpu beside --mem is refused" "cannot both be given" \
    "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/inj" --mem 4G --sbatch '--mem-per-cpu=1G' -- "${SPACE[@]}"
run "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/inj" --sbatch '--mem-per-cpu=1G' -- "${SPACE[@]}"
same "--sbatch --mem-per-cpu without --mem is written" \
    "$STATUS $(grep -c '^#SBATCH --mem-per-cpu=1G$' "$SHARED/inj/facet-shards.sbatch")" "0 1"

# A hostile --sbatch value stays a comment, a hostile --setup a value:
# the scripts are valid bash, the setup reads back byte for byte, and
# it runs, before facet, in every job.
H=$SHARED/hostile
setup_line="echo \"it's \$HOME\" 'a\"b' \`true\` \$(true) ; x='\\' ; echo setup >>'$WORK/order'"
cat >"$WORK/facet-wrapper" <<EOF
#!/bin/bash
echo facet >>'$WORK/order'
exec '$(realpath "$FACET")' "\$@"
EOF
chmod +x "$WORK/facet-wrapper"
run "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$H" --facet "$WORK/facet-wrapper" \
    --sbatch "--comment=\$(touch $marker) 'x\" \`y\`" --setup "$setup_line" -- "${SPACE[@]}"
same "hostile values: written (0), every script valid bash" \
    "$STATUS $(for f in facet-shards.sbatch facet-merge.sbatch submit.sh; do bash -n "$H/$f" && echo ok; done | paste -sd' ')" "0 ok ok ok"
for f in facet-shards.sbatch facet-merge.sbatch; do
    got=$(bash -c 'eval "$(grep "^SETUP=" "$1")"; printf "%s" "$SETUP"' _ "$H/$f")
    same "$f: the setup line reads back byte for byte" "$got" "$setup_line"
done
: >"$WORK/order"
SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_JOB_ID=500 SLURM_CPUS_PER_TASK=1 TMPDIR=$WORK \
    bash "$H/facet-shards.sbatch" >"$OUT" 2>"$ERR"
STATUS=$?
same "a shard task runs the setup line, then facet" \
    "$STATUS $(paste -sd' ' "$WORK/order") $(grep -c "it's $HOME a\"b" "$OUT")" "0 setup facet 1"
[ -e "$marker" ] && fail "no injected command ran" || pass "no injected command ran"
SLURM_ARRAY_TASK_ID=2 TMPDIR=$WORK bash "$H/facet-shards.sbatch" >/dev/null 2>&1
: >"$WORK/order"
run env TMPDIR="$WORK" bash "$H/facet-merge.sbatch"
same "the merge runs the setup line, then facet" "$STATUS $(paste -sd' ' "$WORK/order")" "0 setup facet"
run "$FACET" slurm "$SHARED/roof.obj" --shards 2 --results "$SHARED/setupfail" --setup "false" -- "${SPACE[@]}"
SLURM_ARRAY_TASK_ID=1 TMPDIR=$WORK bash "$SHARED/setupfail/facet-shards.sbatch" >"$OUT" 2>"$ERR"
STATUS=$?
same "a failing setup line stops the job, said in its log" \
    "$STATUS $(grep -c '^facet: the setup line failed (status 1): false$' "$ERR") $(ls "$SHARED/setupfail" | grep -c '^shard-')" "1 1 0"

# --- a failed shard: its log and submit.sh's text say that the merge will
# never start, with the commands to cancel it or run shard and merge
# again. Stand-ins for sbatch and scancel record what they are given.
mkdir "$WORK/bin"
cat >"$WORK/bin/sbatch" <<EOF
#!/bin/bash
n=\$(( \$(cat '$WORK/next' 2>/dev/null || echo 100) + 1 ))
echo "\$n" >'$WORK/next'
echo "sbatch \$*" >>'$WORK/calls'
echo "\$n;cluster"
EOF
cat >"$WORK/bin/scancel" <<EOF
#!/bin/bash
echo "scancel \$*" >>'$WORK/calls'
EOF
chmod +x "$WORK/bin/sbatch" "$WORK/bin/scancel"
R=$SHARED/failing
cp "$SHARED/roof.obj" "$SHARED/gone.obj"
run "$FACET" slurm "$SHARED/gone.obj" --shards 3 --results "$R" -o "$SHARED/failing scripts" -- "${SPACE[@]}"
same "scripts in a folder with a blank in its name are written" "$STATUS" "0"
SC="$SHARED/failing scripts"
run env PATH="$WORK/bin:$PATH" bash "$SC/submit.sh"
same "submit.sh submits the array, then the merge after it, and records both" \
    "$STATUS $(cat "$R/jobs") $(sed -n 2p "$WORK/calls")" \
    "0 101 102 sbatch --parsable --dependency=afterok:101 $SC/facet-merge.sbatch"
stdout_has "submit.sh says the merge waits for every shard" "^shards: job 101; merge: job 102 \(after every shard succeeds\)$"
stdout_has "submit.sh says a failed shard leaves the merge pending, and how to cancel it" "^  scancel 102$"
# the printed line, with the shard's number put in, run as a user would
rerun=$(sed -n 's/^  \(scancel 102; .*\)$/\1/p' "$OUT" | sed 's/--array=I /--array=2 /')
: >"$WORK/calls"
PATH="$WORK/bin:$PATH" bash -c "$rerun" >/dev/null 2>&1
same "submit.sh's rerun line cancels the merge, reruns the shard, then the merge after it" \
    "$(paste -sd'|' "$WORK/calls")" \
    "scancel 102|sbatch --parsable --array=2 $SC/facet-shards.sbatch|sbatch --dependency=afterok:103 $SC/facet-merge.sbatch"
rm "$SHARED/gone.obj"
SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_JOB_ID=101 TMPDIR=$WORK bash "$SC/facet-shards.sbatch" >"$OUT" 2>"$ERR"
STATUS=$?
same "the failed shard fails its task" "$([ "$STATUS" -ne 0 ] && echo failed)" "failed"
same "its log says the merge, job 102, will never start" \
    "$(grep -c '^facet: shard 2 of 3 failed (status [0-9]*): the merge waits for every shard (afterok) and will never start\.$' "$ERR") $(grep -c '^facet: cancel the merge: scancel 102$' "$ERR")" "1 1"
rerun=$(sed -n 's/^facet:   \(scancel 102; .*\)$/\1/p' "$ERR")
: >"$WORK/calls"
PATH="$WORK/bin:$PATH" bash -c "$rerun" >/dev/null 2>&1
same "its log's rerun line cancels the merge, reruns shard 2, then the merge after it" \
    "$(paste -sd'|' "$WORK/calls")" \
    "scancel 102|sbatch --parsable --array=2 $SC/facet-shards.sbatch|sbatch --dependency=afterok:105 $SC/facet-merge.sbatch"
# A shard of another submission (or before submit.sh's record) does not
# name a merge it cannot know.
SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_JOB_ID=999 TMPDIR=$WORK bash "$SC/facet-shards.sbatch" >"$OUT" 2>"$ERR"
same "a shard of another array names no merge job, and says where to find it" \
    "$(grep -c 'scancel 102' "$ERR") $(grep -c '^facet: cancel the merge: scancel MERGE$' "$ERR") $(grep -c 'squeue --me -n facet-merge' "$ERR")" "0 1 1"
exit 0
