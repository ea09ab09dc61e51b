#!/usr/bin/env bash
# End-to-end against a real Slurm: a single-node cluster on this machine
# (munged, slurmctld, slurmd, all in a temporary folder, on ports of their
# own), the scripts of `facet slurm` submitted with sbatch (a job array of
# 4 shards, then the merge after them), and the merged run compared by
# SQLite with the unsharded one; then the same for a project of two files
# searched over panel modules (3 shards), its surface rows compared too.
# The roof's jobs ask what a site asks (issue 32 item 15): --mem, --qos,
# --account, an extra #SBATCH line and a setup line, and Slurm's own
# record of the jobs (scontrol show job) must hold them, the setup line's
# words in every log; then a shard that fails leaves the merge pending,
# its log says so, and the scancel it gives takes the merge out of the
# queue. The daemons are stopped and everything
# removed whatever happens. Where the daemons cannot run (not root, Slurm
# or munge not installed: `make deps` installs them), every check is
# reported as skipped with the reason, never as passed.
# layers: study cli
# lock: slurm
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/shard_lib.sh"

SHARDS=4
SPACE=(--u 10:15 --v 12:17 --threshold 1:4:1)
WAIT_SECONDS=120

# skip_all WHY: the whole test skipped, said plainly.
skip_all() {
    echo "SKIPPED: the Slurm test did not run: $1"
    skip "slurm: array of $SHARDS shards and merge submitted with sbatch" "$1"
    exit 0
}

[ "$(id -u)" -eq 0 ] || skip_all "it needs root to start munged, slurmctld and slurmd"
for tool in munged slurmctld slurmd sbatch squeue sinfo scontrol; do
    command -v "$tool" >/dev/null ||
        skip_all "$tool is not installed (make deps installs slurm-wlm and munge)"
done

D=$WORK/cluster
mkdir -p "$D/state" "$D/spool" "$D/munge" "$D/results"
chmod 700 "$D/munge"
PIDS=()
stop_daemons() {
    local pid
    # Only the daemons this script started, by their process ids.
    for pid in "${PIDS[@]+"${PIDS[@]}"}"; do
        kill "$pid" 2>/dev/null
    done
    for pid in "${PIDS[@]+"${PIDS[@]}"}"; do
        for _ in $(seq 1 50); do
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.1
        done
        kill -KILL "$pid" 2>/dev/null
    done
    rm -rf "$WORK"
}
trap stop_daemons EXIT

# daemon_log NAME: the last lines of a daemon's log, for a skip or failure.
daemon_log() { tail -n 5 "$D/$1.log" 2>/dev/null | tr '\n' ' '; }

# munge: a key of its own and a socket in the temporary folder.
dd if=/dev/urandom of="$D/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$D/munge/munge.key"
munged --force --foreground --socket="$D/munge/munge.socket" \
    --key-file="$D/munge/munge.key" --pid-file="$D/munge/munged.pid" \
    --log-file="$D/munged.log" --seed-file="$D/munge/munged.seed" \
    >/dev/null 2>&1 &
PIDS+=($!)
for _ in $(seq 1 50); do
    [ -S "$D/munge/munge.socket" ] && break
    kill -0 "${PIDS[0]}" 2>/dev/null || break
    sleep 0.1
done
[ -S "$D/munge/munge.socket" ] || skip_all "munged did not start: $(daemon_log munged)"

# Ports of its own, away from a system Slurm's 6817/6818.
port=$((20000 + RANDOM % 20000))
HOST=$(hostname -s)
CONF=$D/slurm.conf
cat >"$CONF" <<EOF
ClusterName=facettest
SlurmctldHost=$HOST(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$D/munge/munge.socket
StateSaveLocation=$D/state
SlurmdSpoolDir=$D/spool
SlurmctldPidFile=$D/slurmctld.pid
SlurmdPidFile=$D/slurmd.pid
SlurmctldLogFile=$D/slurmctld.log
SlurmdLogFile=$D/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
SlurmdTimeout=30
NodeName=$HOST NodeAddr=127.0.0.1 CPUs=2 RealMemory=256 State=UNKNOWN
PartitionName=facet Nodes=$HOST Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$CONF

slurmctld -D -i -f "$CONF" >"$D/slurmctld.out" 2>&1 &
PIDS+=($!)
slurmd -D -f "$CONF" >"$D/slurmd.out" 2>&1 &
PIDS+=($!)
state=""
for _ in $(seq 1 150); do
    state=$(sinfo -h -o %T 2>/dev/null | head -n 1)
    [ "$state" = idle ] && break
    kill -0 "${PIDS[1]}" 2>/dev/null || break
    kill -0 "${PIDS[2]}" 2>/dev/null || break
    sleep 0.2
done
[ "$state" = idle ] ||
    skip_all "the node did not come up (state '${state:-none}'): slurmctld: $(daemon_log slurmctld) slurmd: $(daemon_log slurmd)"
echo "# cluster: node $HOST idle ($(sinfo -h -o '%P %c CPUs %T'))"

# submit_and_compare NAME SHARDS RESULTS WHOLE.db SLURM ARGS...: writes the
# scripts with facet slurm SLURM ARGS (--shards SHARDS --results RESULTS
# given here), submits them with sbatch, waits for the array and the merge,
# and compares the merged run with the unsharded WHOLE.db by SQLite.
submit_and_compare() {
    local name=$1 shards=$2 results=$3 whole=$4
    shift 4
    local facet_args=() optimize_args=()
    while [ "$1" != "--" ]; do facet_args+=("$1"); shift; done
    shift
    optimize_args=("$@")
    expect "$name: facet slurm writes the scripts" 0 "$FACET" slurm "${facet_args[@]}" \
        --shards "$shards" --results "$results" --cpus 1 -- "${optimize_args[@]}"
    sed 's/^/# /' "$OUT"
    run bash "$results/submit.sh"
    if [ "$STATUS" -eq 0 ]; then pass "$name: submit.sh submits the array and the merge"; else fail "$name: submit.sh submits the array and the merge"; fi
    sed 's/^/# /' "$OUT"
    local merge_job array_job
    merge_job=$(sed -n 's/.*merge: job \([0-9]*\).*/\1/p' "$OUT")
    array_job=$(sed -n 's/.*shards: job \([0-9]*\).*/\1/p' "$OUT")
    same "$name: the merge depends on the array (afterok)" \
        "$(scontrol show job "$merge_job" 2>/dev/null | grep -o "Dependency=afterok:${array_job}[^ ]*" | head -n 1 | cut -d'(' -f1)" \
        "Dependency=afterok:${array_job}_*"

    # Waits, bounded, for every job of the two to leave the queue.
    local waited=0
    while [ "$waited" -lt $((WAIT_SECONDS * 5)) ]; do
        [ -z "$(squeue -h -j "$array_job,$merge_job" 2>/dev/null)" ] && break
        sleep 0.2
        waited=$((waited + 1))
    done
    echo "# $name: jobs done after $((waited / 5)) s"
    same "$name: the jobs finished within $WAIT_SECONDS s" "$(squeue -h -j "$array_job,$merge_job" 2>/dev/null | wc -l)" "0"
    # What Slurm says of them (kept by slurmctld for MinJobAge, 300 s).
    scontrol -o show job "$array_job" 2>/dev/null >"$WORK/jobs"
    scontrol -o show job "$merge_job" 2>/dev/null >>"$WORK/jobs"
    sed -n 's/^JobId=\([0-9]*\) \(ArrayJobId=[0-9]* ArrayTaskId=[0-9]* \)\{0,1\}JobName=\([^ ]*\).* JobState=\([A-Z]*\).*/# job \1 \2\3 \4/p' "$WORK/jobs" | sort -u
    same "$name: Slurm ran the $shards shard tasks and the merge to completion" \
        "$(grep -o 'JobState=[A-Z]*' "$WORK/jobs" | sort | uniq -c | sed 's/^ *//')" \
        "$((shards + 1)) JobState=COMPLETED"
    same "$name: every shard was copied to the results" \
        "$(ls "$results" | grep -c '^shard-[0-9]*\.db$')" "$shards"
    same "$name: only finished files are in the results (no partial copies)" \
        "$(ls -A "$results" | grep -c '\.part$')" "0"
    local log
    for log in "$results"/*.log; do
        echo "# --- $(basename "$log")"
        sed 's/^/#   /' "$log" | head -n 12
    done
    if [ -f "$results/merged.db" ]; then
        pass "$name: the merge job wrote the merged run"
        same_options "$name: merged run from Slurm = unsharded run, option for option and rank for rank" \
            "$whole" "$results/merged.db"
        run "$FACET" runs "$results/merged.db"
        sed 's/^/# /' "$OUT"
    else
        echo "not ok - $name: the merge job wrote the merged run"
        daemon_log slurmctld
    fi
}

fixture roof40.obj "$WORK/roof.obj" || exit 1
expect "unsharded run" 0 "$FACET" optimize "$WORK/roof.obj" --db "$WORK/whole.db" "${SPACE[@]}" --measure all --table 1
# The results folder is made by facet slurm, two levels down.
SITE=(--mem 100M --qos normal --account facetlab --sbatch '--comment=facet-e2e'
      --setup 'echo "setup ran: $SLURM_JOB_NAME"')
submit_and_compare "roof" "$SHARDS" "$D/results/roof" "$WORK/whole.db" "$WORK/roof.obj" "${SITE[@]}" -- "${SPACE[@]}"
for f in facet-shards.sbatch facet-merge.sbatch; do
    same "roof: $f asks --mem, --account, --qos and the extra line" \
        "$(grep -E '^#SBATCH --(mem|account|qos|comment)=' "$D/results/roof/$f" | paste -sd' ')" \
        "#SBATCH --mem=100M #SBATCH --account=facetlab #SBATCH --qos=normal #SBATCH --comment=facet-e2e"
done
# Slurm's own record: every job of the two (4 tasks and the merge).
same "roof: Slurm gave every job the memory asked (MinMemoryNode=100M)" \
    "$(grep -o 'MinMemoryNode=[^ ]*' "$WORK/jobs" | sort | uniq -c | sed 's/^ *//')" "$((SHARDS + 1)) MinMemoryNode=100M"
# (A cluster without accounting, as this one, keeps no QOS: scontrol
# shows QOS=(null); that the jobs ran with --qos in their scripts is
# what is checked of it.)
echo "# roof: $(grep -o 'QOS=[^ ]*' "$WORK/jobs" | sort | uniq -c | sed 's/^ *//') (no accounting here)"
same "roof: Slurm charged every job to the account asked" \
    "$(grep -o 'Account=[^ ]*' "$WORK/jobs" | sort | uniq -c | sed 's/^ *//')" "$((SHARDS + 1)) Account=facetlab"
same "roof: Slurm took the extra #SBATCH line (Comment=facet-e2e)" \
    "$(grep -o 'Comment=[^ ]*' "$WORK/jobs" | sort | uniq -c | sed 's/^ *//')" "$((SHARDS + 1)) Comment=facet-e2e"
same "roof: every job ran the setup line first (its log's first line)" \
    "$(for log in "$D/results/roof"/*.log; do head -n 1 "$log"; done | sort | uniq -c | sed 's/^ *//' | paste -sd' ')" \
    "1 setup ran: facet-merge $SHARDS setup ran: facet-shard"

# A shard that fails (its surface gone from the node): the merge stays
# pending, never to start; the shard's log says so and gives the
# scancel, which takes the merge out of the queue.
cp "$WORK/roof.obj" "$WORK/gone.obj"
F=$D/failing
run "$FACET" slurm "$WORK/gone.obj" --shards 2 --results "$F" -- "${SPACE[@]}"
rm "$WORK/gone.obj"
run bash "$F/submit.sh"
sed 's/^/# /' "$OUT"
array_job=$(sed -n 's/.*shards: job \([0-9]*\).*/\1/p' "$OUT")
merge_job=$(sed -n 's/.*merge: job \([0-9]*\).*/\1/p' "$OUT")
same "failing: submit.sh's text gives the scancel of the merge" \
    "$(grep -c "^  scancel $merge_job\$" "$OUT")" "1"
waited=0
while [ "$waited" -lt $((WAIT_SECONDS * 5)) ]; do
    [ -z "$(squeue -h -j "$array_job" 2>/dev/null)" ] && break
    sleep 0.2
    waited=$((waited + 1))
done
sed 's/^/#   /' "$F/shard-1.log" | tail -n 5
echo "# failing: the merge: $(squeue -h -j "$merge_job" -o '%T %r' 2>/dev/null)"
same "failing: with every shard failed, Slurm keeps the merge pending" \
    "$(squeue -h -j "$merge_job" -o '%T' 2>/dev/null)" "PENDING"
same "failing: each shard's log says the merge will never start and names it" \
    "$(cat "$F"/shard-*.log | grep -c "^facet: shard [12] of 2 failed .*will never start\.$") $(cat "$F"/shard-*.log | grep -c "^facet: cancel the merge: scancel $merge_job\$")" "2 2"
cancel=$(sed -n 's/^facet: cancel the merge: \(scancel [0-9]*\)$/\1/p' "$F/shard-1.log")
$cancel
for _ in $(seq 1 50); do
    [ -z "$(squeue -h -j "$merge_job" 2>/dev/null)" ] && break
    sleep 0.2
done
same "failing: the log's scancel takes the merge out of the queue" \
    "$(squeue -h -j "$merge_job" 2>/dev/null | wc -l)" "0"

# A project of two files (one of four objects, one of a fifth), searched
# over panel modules: its shards, their merge, and each option's surface
# rows as the unsharded run's.
four_surfaces || exit 1
"$FACET" example wave --res 16 -o "$WORK/wave.obj" >/dev/null || exit 1
PROJECT_SPACE=(--module 1:4:0.25x1:4:0.25 --threshold 2:6:2 --method exhaustive)
expect "unsharded project run" 0 "$FACET" optimize "$WORK/four.obj" "$WORK/wave.obj" \
    --db "$WORK/project.db" "${PROJECT_SPACE[@]}" --table 1
submit_and_compare "project" 3 "$D/project" "$WORK/project.db" \
    "$WORK/four.obj" "$WORK/wave.obj" -- "${PROJECT_SPACE[@]}"
if [ -f "$D/project/merged.db" ]; then
    same_rows "project: every surface row of every option as the unsharded run's" \
        "$WORK/project.db" "$D/project/merged.db" option_surfaces
    same_rows "project: its five surfaces as the unsharded run's" \
        "$WORK/project.db" "$D/project/merged.db" surfaces
fi
