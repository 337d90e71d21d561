#!/bin/bash
# Runs the Slurm job files of docs/farm/ through a real, private, single-node Slurm: munged,
# slurmctld and slurmd started in a temporary folder on free ports, a sample-split job array
# with its merge job, and a frame-range job array. The merged picture must agree with the same
# render made in one piece.
#   run_job_array.sh RTVK_EXECUTABLE DOCS_FARM_FOLDER
# Exits 77 (ctest: skipped) without Slurm or root -- but fails instead when CI is set.
set -euo pipefail
rtvk=$(realpath "$1") farm=$(realpath "$2")

skip() {
  if [[ -n ${CI:-} ]]; then
    echo "FAIL: $* (CI must run this test)"
    exit 1
  fi
  echo "SKIP: $*"
  exit 77
}
for tool in munged slurmctld slurmd sbatch sinfo scontrol; do
  command -v "$tool" >/dev/null || skip "$tool not found (Debian: apt install slurm-wlm)"
done
[[ $(id -u) == 0 ]] || skip "a private slurmd needs root"

dir=$(mktemp -d /tmp/rtvk-slurm-XXXXXX)
stop_daemons() {
  for pidfile in "$dir"/slurmd.pid "$dir"/slurmctld.pid "$dir"/munged.pid; do
    [[ -f $pidfile ]] || continue
    pid=$(cat "$pidfile")
    kill "$pid" 2>/dev/null || true
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  done
  rm -rf "$dir"
}
trap stop_daemons EXIT
on_error() {
  echo "FAIL: line $1 of run_job_array.sh exited $2; Slurm's logs:"
  tail -n 15 "$dir"/*.log 2>/dev/null || true
}
trap 'on_error $LINENO $?' ERR

host=$(hostname -s)
port=$((20000 + RANDOM % 20000))
head -c 1024 /dev/urandom >"$dir/munge.key"
chmod 400 "$dir/munge.key"
mkdir -p "$dir/state" "$dir/spool"
cat >"$dir/slurm.conf" <<CONF
ClusterName=rtvk-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=30 State=UP
CONF
export SLURM_CONF=$dir/slurm.conf

munged --socket="$dir/munge.socket" --key-file="$dir/munge.key" --pid-file="$dir/munged.pid" \
  --log-file="$dir/munged.log" --seed-file="$dir/munged.seed" --force 2>/dev/null
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
for _ in $(seq 60); do
  [[ $(timeout 5 sinfo -h -o %t 2>/dev/null) == idle ]] && break
  sleep 0.5
done
[[ $(timeout 5 sinfo -h -o %t 2>/dev/null) == idle ]] || {
  echo "FAIL: the Slurm node did not come up"
  tail -n 20 "$dir"/*.log
  exit 1
}
echo "slurm: node $host idle (slurmctld port $port)"

cd "$dir"
export RTVK=$rtvk SCENE=materials SPP=8 BACKEND=cpu RTVK_ARGS="--width 48 --depth 8 -q"
export OUT=$dir/pieces
array=$(sbatch --parsable --array=0-3 "$farm/slurm-samples.sbatch")
echo "slurm: sample-split array job $array submitted"
timeout 300 sbatch --wait --kill-on-invalid-dep=yes --dependency="afterok:$array" \
  "$farm/slurm-merge.sbatch" || {
  echo "FAIL: the merge job did not succeed"
  tail -n 20 "$dir"/*.log
  exit 1
}
ls "$OUT"
for i in 0 1 2 3; do [[ -s $OUT/part_$i.exr ]] || { echo "FAIL: no part_$i.exr"; exit 1; }; done

"$rtvk" render --scene materials --spp 8 --backend cpu --width 48 --depth 8 -q -o "$dir/whole.exr"
"$rtvk" merge -q "$dir/whole.exr" -o "$dir/whole.png"
"$rtvk" compare "$OUT/final.png" "$dir/whole.png" --tolerance 1 --max-share 0.001

FRAMES=5 RTVK_ARGS="--width 32 --spp 2 --depth 4 --orbit 4 -q" OUT=$dir/frames \
  timeout 300 sbatch --wait --array=0-1 "$farm/slurm-frames.sbatch"
for f in 0 1 2 3 4; do
  [[ -s $dir/frames/frame_000$f.png ]] || { echo "FAIL: no frame_000$f.png"; exit 1; }
done
echo "PASS: 4 sample pieces merged through Slurm agree with the whole render; 5 frames by 2 tasks"
