#!/usr/bin/env bash
# `animpak sweep --submit slurm` on a real single-node Slurm (docs/sweeps.md): starts munged, slurmctld and
# slurmd from Debian's packages with a slurm.conf generated in a scratch folder (its own ports, state and
# munge socket: nothing of the system's Slurm or munge is used or touched), submits a three-run plan as one
# array job, waits for it and checks that `animpak sweep collect` finds all three runs done. Stops the daemons
# and removes the folder however it ends.
#
#   tests/sweep/slurm.sh ANIMPAK SOURCE_DIR
#
# Needs root (slurmd runs each task as its user) and the packages slurmctld, slurmd, munge and slurm-client
# (scripts/install-deps.sh installs them: tests only). Without them it reports Skipped (exit 77), and under
# CI=true, where nothing may skip, it fails instead (docs/testing.md, "Skipped tests").
set -euo pipefail
animpak=$1
source_dir=$2

skip() {
  if [ "${CI:-}" = true ]; then
    echo "slurm test: FAIL: CI=true, where nothing may skip, and this test cannot run: $*"
    exit 1
  fi
  echo "animpak-test skipped: $*"
  exit 77
}

[ "$(id -u)" -eq 0 ] || skip "not root: slurmd must run as root to start each task as its user"
for tool in munged slurmctld slurmd sbatch squeue sinfo scontrol; do
  command -v "$tool" >/dev/null ||
    skip "$tool is not installed (Debian packages munge, slurmctld, slurmd, slurm-client; bash scripts/install-deps.sh --tests)"
done

work=$(mktemp -d /tmp/animpak-slurm-XXXXXX)
chmod 755 "$work"
pids=()
cleanup() {
  local status=$?
  [ -n "${SLURM_CONF:-}" ] && scontrol shutdown >/dev/null 2>&1 || true
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$pid" 2>/dev/null || true
  done
  if [ $status -ne 0 ]; then
    for log in "$work"/*.log; do [ -f "$log" ] && { echo "--- $log"; tail -n 30 "$log"; }; done
  fi
  rm -rf "$work"
  exit $status
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# munge with a key and a socket of its own.
mkdir -p "$work/munge"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 711 "$work/munge"
chmod 400 "$work/munge/munge.key"
munged --force --foreground --key-file="$work/munge/munge.key" --socket="$work/munge/munge.socket" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/munged.log" --seed-file="$work/munge/munged.seed" \
  >"$work/munged.out.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do [ -S "$work/munge/munge.socket" ] && break; sleep 0.1; done
[ -S "$work/munge/munge.socket" ] || { echo "munged did not start"; exit 1; }

# Free ports for slurmctld and slurmd.
port=$((20000 + RANDOM % 20000))
while (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null || (exec 3<>"/dev/tcp/127.0.0.1/$((port + 1))") 2>/dev/null; do
  port=$((20000 + RANDOM % 20000))
done
node=$(hostname -s)
cpus=$(nproc)
mkdir -p "$work/state" "$work/spool"
cat >"$work/slurm.conf" <<EOF
ClusterName=animpaktest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
SwitchType=switch/none
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
ReturnToService=2
MaxArraySize=1001
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$work/slurm.conf"
slurmctld -D -i >"$work/slurmctld.out.log" 2>&1 &
pids+=($!)
slurmd -D >"$work/slurmd.out.log" 2>&1 &
pids+=($!)
for _ in $(seq 300); do
  sinfo -h -N -o '%T' 2>/dev/null | grep -qE '^(idle|mixed)' && break
  sleep 0.1
done
sinfo -h -N -o '%T' | grep -qE '^(idle|mixed)' || { echo "the node did not come up"; sinfo -N; exit 1; }
echo "slurm: node $node up ($cpus CPUs), slurmctld on port $port"

# Three runs of three stars in the heart, as one array job.
mkdir -p "$work/sweep-input"
cat >"$work/sweep-input/scene.json" <<EOF
{"container": {"art": "$source_dir/examples/shapes/heart-container.path"},
 "elements": [{"name": "star", "art": "$source_dir/examples/default/star.svg", "count": 3,
               "animation": {"preset": "rotate", "turns": 1}}],
 "slices": 6, "params": {"initial_scale": 0.15}}
EOF
sweep="$work/sweep"
job=$("$animpak" sweep "$work/sweep-input/scene.json" --out "$sweep" --seeds 1-3 --max-iterations 60 \
  --frames 4 --size 64 --cpus-per-task 1 --submit slurm 2>"$work/submit.log")
cat "$work/submit.log"
echo "slurm: submitted array job $job"
[[ $job =~ ^[0-9]+$ ]] || { echo "no job id printed: '$job'"; exit 1; }
grep -q "submitted 3 runs" "$work/submit.log"
for _ in $(seq 3000); do
  [ -z "$(squeue -h -j "$job" 2>/dev/null)" ] && break
  sleep 0.1
done
[ -z "$(squeue -h -j "$job")" ] || { echo "the array job did not finish in 300 s"; squeue; exit 1; }
for task in 0 1 2; do
  out="$sweep/logs/slurm-${job}_$task.out"
  [ -f "$out" ] || { echo "no Slurm output $out"; ls "$sweep/logs"; exit 1; }
  grep -q "sweep-task: run $task of" "$out" || { echo "task $task did not run its run"; cat "$out"; exit 1; }
done
"$animpak" sweep collect "$sweep" 2>"$work/collect.log"
cat "$work/collect.log"
grep -q "3 runs in .*: 3 done" "$work/collect.log"
[ "$(grep -c ',done,' "$sweep/runs.csv")" -eq 3 ] || { cat "$sweep/runs.csv"; exit 1; }
echo "slurm: array job $job packed all three runs; collect found them done"
