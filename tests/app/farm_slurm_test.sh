#!/usr/bin/env bash
# `veduta farm`: the scripts a dry run writes and the refusals first; then, as root with Slurm
# and MUNGE installed (Debian: slurm-wlm, munge), a single-node Slurm of its own on free ports
# renders the default scene as 4 tiles and as 2 sample ranges, which must equal a render in one
# go bit for bit (the tiles) and `veduta merge` of the same ranges (the ranges); a task requeued
# after its first checkpoint resumes from it; failed tasks show in `veduta farm status`, and
# resubmitting them as docs/farm.md says completes the job. Every daemon is stopped at the end.
# Usage: farm_slurm_test.sh VEDUTA_BINARY
set -u
veduta=$1
work=$(mktemp -d)
daemons=()
cleanup() {
    if [ -n "${SLURM_CONF:-}" ] && [ -e "$SLURM_CONF" ]; then
        squeue -h -o %A 2>/dev/null | xargs -r scancel 2>/dev/null
        sleep 1
    fi
    for pid in "${daemons[@]}"; do kill -TERM -- "-$pid" 2>/dev/null; done
    for pid in "${daemons[@]}"; do
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -KILL -- "-$pid" 2>/dev/null
    done
    rm -rf "$work"
}
trap cleanup EXIT
. "$(dirname "$0")/test_lib.sh"
# Jobs of a Slurm this test may itself run under must not leak into ours.
for variable in $(env | sed -n 's/^\(SLURM_[A-Z_]*\)=.*/\1/p'); do unset "$variable"; done

# --- Without Slurm: the scripts of a dry run, and what is refused.
run farm --help
check "farm help" out_has "submit"
run farm submit --help
check "submit help" out_has "--sample-ranges"
run farm status --help
check "status help" out_has "exit 0 merged, 1 failed, 4 still running"
dry=$work/dry
run farm submit --dry-run --tiles 4 --res 96x54 --spp 4 --max-parallel 2 --cpus-per-task 1 --partition test \
    --sbatch-arg=--nice=5 -o "$dry/it's here.exr"
check "dry run exits 0" rc_is 0
script=$dry/it\'s\ here.exr.farm/render.sbatch
check "task script written" test -s "$script"
check "merge script written" test -s "$dry/it's here.exr.farm/merge.sbatch"
check "scripts are bash" bash -n "$script"
check "array of 4, at most 2 at once" grep -qx '#SBATCH --array=0-3%2' "$script"
check "requeued when preempted" grep -qx '#SBATCH --requeue' "$script"
check "options passed to sbatch" grep -qx '#SBATCH --nice=5' "$script"
check "tasks checkpoint and resume" grep -q -- '--checkpoint-every 300 --resume -o "$part"' "$script"
check "quarters of the image" grep -qF "3) task=('--region' '48' '27' '96' '54') ;;" "$script"
check "the running program, by absolute path" grep -qF "'$(readlink -f "$veduta")' 'render'" "$script"
check "job file: not submitted" grep -qx 'array_job=' "$dry/it's here.exr.farm/farm.job"
# Each task of the script, run by hand as Slurm would, renders its part.
for task in 0 1 2 3; do SLURM_ARRAY_TASK_ID=$task bash "$script" 2>/dev/null; done
check "the tasks run without Slurm too" test -e "$dry/it's here.exr.farm/parts/part-3.exr"
bash "$dry/it's here.exr.farm/merge.sbatch" 2>/dev/null
check "the merge script merges" test -e "$dry/it's here.exr"
# What the EXR holds is the tasks' too, so the merged image has it.
run farm submit --dry-run --tiles 2 --res 96x54 --spp 2 --passes Combined,CryptoObject --half -o "$work/crypto.exr"
check "EXR options passed to the tasks, with SampleCount for the merge" \
    grep -qF "'--passes' 'Combined,CryptoObject,SampleCount' '--half'" "$work/crypto.exr.farm/render.sbatch"
for task in 0 1; do SLURM_ARRAY_TASK_ID=$task bash "$work/crypto.exr.farm/render.sbatch" 2>/dev/null; done
bash "$work/crypto.exr.farm/merge.sbatch" 2>/dev/null
check "the merged image has the Crypto layers" grep -qa "ViewLayer.CryptoObject00.R" "$work/crypto.exr"
run farm submit --dry-run --tiles 2 --compression dwaa -o "$work/lossy.exr"
check "a lossy codec with data passes exits 2" rc_is 2
run farm submit --dry-run --tiles 5185 --res 96x54 -o "$work/big.exr"
check "more tiles than pixels exit 2" rc_is 2
check "more tiles than pixels named" err_has "5185 tiles do not fit a 96x54 image: give 1 to 5184"
run farm submit --dry-run --sample-ranges 5 --spp 4 -o "$work/big.exr"
check "more ranges than samples exit 2" rc_is 2
check "more ranges than samples named" err_has "5 sample ranges do not fit 4 samples per pixel"
check "nothing written for them" test ! -e "$work/big.exr.farm"
run farm submit --dry-run -o "$work/none.exr"
check "no split exits 2" rc_is 2
run farm submit --dry-run --sample-ranges 2 --noise-threshold 0.01 -o "$work/none.exr"
check "adaptive sample ranges exit 2" rc_is 2
mkdir "$work/nobin"
PATH=$work/nobin run farm submit --tiles 2 -o "$work/none.exr"
check "no sbatch exits 2" rc_is 2
check "no sbatch: what to install" err_has "Debian: slurm-client"
run farm status "$work"
check "status of a folder without a job exits 1" rc_is 1
check "status says what is missing" err_has "farm.job is missing"

# --- A Slurm of our own.
missing=""
for tool in slurmctld slurmd munged sbatch squeue sinfo scontrol scancel idiff python3; do
    command -v "$tool" >/dev/null || missing="$missing $tool"
done
if [ -n "$missing" ] || [ "$(id -u)" != 0 ]; then
    [ -n "$missing" ] && echo "SKIP the cluster part: missing$missing (Debian: slurm-wlm munge openimageio-tools)"
    [ "$(id -u)" != 0 ] && echo "SKIP the cluster part: starting slurmd needs root"
    summary farm_slurm_without_cluster || exit 1
    exit 77
fi
cluster=$work/cluster
mkdir -p "$cluster/state" "$cluster/spool"
dd if=/dev/urandom bs=1 count=1024 of="$cluster/munge.key" 2>/dev/null
chmod 0400 "$cluster/munge.key"
setsid munged -F -f --socket="$cluster/munge.socket" --key-file="$cluster/munge.key" \
    --pid-file="$cluster/munged.pid" --log-file="$cluster/munged.log" --seed-file="$cluster/munged.seed" \
    >"$cluster/munged.out" 2>&1 &
daemons+=($!)
read -r ctld_port node_port < <(python3 -c '
import socket
sockets = [socket.socket() for _ in range(2)]
for s in sockets: s.bind(("127.0.0.1", 0))
print(*[s.getsockname()[1] for s in sockets])')
host=$(hostname -s)
cat >"$cluster/slurm.conf" <<CONF
ClusterName=vedutatest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$node_port
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$cluster/munge.socket
CredType=cred/munge
StateSaveLocation=$cluster/state
SlurmdSpoolDir=$cluster/spool
SlurmctldPidFile=$cluster/slurmctld.pid
SlurmdPidFile=$cluster/slurmd.pid
SlurmctldLogFile=$cluster/slurmctld.log
SlurmdLogFile=$cluster/slurmd.log
MailProg=/bin/true
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$(awk '/MemTotal/ { print int($2 / 2048) }' /proc/meminfo)
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$cluster/slurm.conf
for _ in $(seq 50); do [ -S "$cluster/munge.socket" ] && break; sleep 0.1; done
setsid slurmctld -D -f "$SLURM_CONF" >"$cluster/slurmctld.out" 2>&1 &
daemons+=($!)
setsid slurmd -D -f "$SLURM_CONF" >"$cluster/slurmd.out" 2>&1 &
daemons+=($!)
for _ in $(seq 60); do [ "$(sinfo -h -o %t 2>/dev/null)" = idle ] && break; sleep 1; done
if ! check "the node is idle" test "$(sinfo -h -o %t 2>/dev/null)" = idle; then
    tail -n 20 "$cluster"/*.log "$cluster"/*.out
    summary farm_slurm
    exit 1
fi

# wait_for JOBDIR: polls `veduta farm status` until it stops saying "still running" (4) or
# 300 s pass; leaves its last output in $work/out and exit code in $work/rc.
wait_for() {
    for _ in $(seq 300); do
        run farm status "$1"
        [ "$(cat "$work/rc")" = 4 ] || return 0
        sleep 1
    done
}
same_pixels() { idiff -fail 0 -failpercent 0 -warn 0 "$1" "$2" >"$work/idiff" || { cat "$work/idiff"; false; }; }
render() { "$veduta" render -q "$@" || echo "render $* failed"; }

run farm submit --tiles 4 --res 96x54 --spp 4 -o "$work/tiles.exr"
check "tiles submitted" rc_is 0
check "submission named" out_has "(4 tasks) and merge job"
run farm submit --tiles 4 --res 96x54 --spp 4 -o "$work/tiles.exr"
check "a folder with a submitted job exits 1" rc_is 1
check "the job is kept" err_has "holds a submitted farm job already"
run farm submit --sample-ranges 2 --res 96x54 --spp 4 -o "$work/ranges.exr"
check "sample ranges submitted" rc_is 0
wait_for "$work/tiles.exr.farm"
echo "tiles:"; cat "$work/out"
check "tiles: status exits 0" rc_is 0
check "tiles: summary line" out_line "4 tasks: 4 done, 0 failed, 0 queued or running; merge done"
wait_for "$work/ranges.exr.farm"
echo "sample ranges:"; cat "$work/out"
check "ranges: status exits 0" rc_is 0
render --res 96x54 --spp 4 -o "$work/whole.exr"
check "tiles: bit-identical to one render" same_pixels "$work/tiles.exr" "$work/whole.exr"
render --res 96x54 --spp 2 -o "$work/r0.exr"
render --res 96x54 --spp 2 --sample-offset 2 -o "$work/r1.exr"
"$veduta" merge -q "$work/ranges-here.exr" "$work/r0.exr" "$work/r1.exr"
check "ranges: bit-identical to their merge here" same_pixels "$work/ranges.exr" "$work/ranges-here.exr"
"$veduta" diff "$work/ranges.exr" "$work/whole.exr" --fail 1e-5 --failpercent 0 >"$work/diff"
check "ranges: Combined as one render's (docs/output.md: within 1 ulp)" test $? = 0

# Requeued after its first checkpoint (as preemption does), the task resumes from it.
run farm submit --tiles 1 --res 160x90 --spp 512 --cpus-per-task 1 --checkpoint-every 1 -o "$work/slow.exr"
check "slow job submitted" rc_is 0
for _ in $(seq 600); do [ -e "$work/slow.exr.farm/parts/part-0.exr.checkpoint" ] && break; sleep 0.1; done
task=$(sed -n 's/^array_job=//p' "$work/slow.exr.farm/farm.job")_0
check "requeued after a checkpoint" scontrol requeue "$task"
run farm status "$work/slow.exr.farm"
check "requeued task: still running" rc_is 4
scontrol update JobId="$task" StartTime=now  # Slurm holds a requeued job back for a while
wait_for "$work/slow.exr.farm"
check "requeued task: done" rc_is 0
check "requeued task resumed" grep -q "resuming from .*part-0.exr.checkpoint after" "$work/slow.exr.farm/logs/task-0.log"
render --res 160x90 --spp 512 -o "$work/slow-whole.exr"
check "requeued task: bit-identical to one render" same_pixels "$work/slow.exr" "$work/slow-whole.exr"

# Tasks that fail, then resubmitted as docs/farm.md says.
cat >"$work/box.xml" <<'XML'
<scene>
  <camera position="0 -3 1" look_at="0 0 0.5" resolution="64 36"/>
  <box/>
</scene>
XML
cp "$work/box.xml" "$work/good.xml"
# The tasks start 5 s after submission: the scene is broken by then.
run farm submit "$work/box.xml" --tiles 2 --spp 4 --sbatch-arg=--begin=now+5 -o "$work/box.exr"
check "delayed job submitted" rc_is 0
echo "<scene><bad/></scene>" >"$work/box.xml"
wait_for "$work/box.exr.farm"
echo "failed tasks:"; cat "$work/out"
check "failed tasks: status exits 1" rc_is 1
check "failed task: exit status and log" out_has "task 0: --region 0 0 32 36: failed with exit status 1, log $work/box.exr.farm/logs/task-0.log"
check "failed tasks counted" out_has "2 tasks: 0 done, 2 failed"
check "the log says why" grep -q "box.xml:1:8: " "$work/box.exr.farm/logs/task-0.log"
cp "$work/good.xml" "$work/box.xml"
id=$(sbatch --parsable --array=0-1 "$work/box.exr.farm/render.sbatch")
sbatch --parsable --dependency=afterok:"$id" "$work/box.exr.farm/merge.sbatch" >/dev/null
wait_for "$work/box.exr.farm"
echo "resubmitted:"; cat "$work/out"
check "resubmitted: status exits 0" rc_is 0
render "$work/box.xml" --spp 4 -o "$work/box-whole.exr"
check "resubmitted: bit-identical to one render" same_pixels "$work/box.exr" "$work/box-whole.exr"

summary farm_slurm
