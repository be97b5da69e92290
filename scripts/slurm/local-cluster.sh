#!/bin/bash
# A one-node Slurm on this machine, for trying the job-array scripts without a cluster (and for
# pvscope's test of them): Debian's munged, slurmctld and slurmd (packages slurmctld slurmd
# slurm-client munge), a node with this machine's CPUs, no cgroups, no accounting, everything in
# DIR (a short path: Slurm's socket and state paths must stay under about 64 characters).
#   local-cluster.sh start DIR   starts the daemons (as root: slurmd must be), waits until the node
#                                is idle, and writes DIR/env to source: SLURM_CONF for sbatch etc.
#   local-cluster.sh stop DIR    stops every daemon start started, by the pids in DIR/pids
# Its munge key and socket are its own, and its ports are not Slurm's usual 6817/6818: a system
# Slurm or munge on the machine is not touched.
set -euo pipefail
command=${1:-}
dir=${2:-}
if [ -z "$command" ] || [ -z "$dir" ]; then
  sed -n '2,11p' "$0" >&2
  exit 2
fi
export PATH="$PATH:/usr/sbin"

stop() {
  [ -f "$dir/pids" ] || return 0
  local pids
  pids=$(cat "$dir/pids")
  for pid in $pids; do kill "$pid" 2> /dev/null || true; done
  for pid in $pids; do
    for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2> /dev/null || true
  done
  rm -f "$dir/pids"
}

start() {
  mkdir -p "$dir/munge" "$dir/state" "$dir/spool"
  dir=$(realpath "$dir")
  chmod 700 "$dir/munge"
  : > "$dir/pids"
  dd if=/dev/urandom of="$dir/munge/key" bs=1024 count=1 status=none
  chmod 400 "$dir/munge/key"
  munged --force --key-file="$dir/munge/key" --socket="$dir/munge/sock" --pid-file="$dir/munge/pid" \
    --log-file="$dir/munge.log" --seed-file="$dir/munge/seed"
  for _ in $(seq 50); do [ -s "$dir/munge/pid" ] && break; sleep 0.1; done
  [ -s "$dir/munge/pid" ] || { echo "local-cluster: munged did not start ($dir/munge.log)" >&2; return 1; }
  cat "$dir/munge/pid" >> "$dir/pids"
  local port=$((20000 + RANDOM % 20000)) host cpus
  host=$(hostname -s)
  cpus=$(nproc)
  cat > "$dir/slurm.conf" <<CONF
ClusterName=local
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/sock
CredType=cred/munge
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
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
  echo "export SLURM_CONF=$dir/slurm.conf" > "$dir/env"
  export SLURM_CONF="$dir/slurm.conf"
  slurmctld -D -f "$SLURM_CONF" > "$dir/slurmctld.out" 2>&1 &
  echo $! >> "$dir/pids"
  slurmd -D -f "$SLURM_CONF" > "$dir/slurmd.out" 2>&1 &
  echo $! >> "$dir/pids"
  local state=""
  for _ in $(seq 150); do
    state=$(sinfo -h -N -o %t 2> /dev/null || true)
    [ "$state" = idle ] && break
    sleep 0.2
  done
  if [ "$state" != idle ]; then
    echo "local-cluster: the node is '$state', not idle, after 30 s ($dir/slurmctld.log, $dir/slurmd.log)" >&2
    return 1
  fi
  echo "local-cluster: node $host ($cpus CPUs) idle; source $dir/env to use it"
}

case "$command" in
  start) start || { stop; exit 1; } ;;
  stop) stop ;;
  *) sed -n '2,11p' "$0" >&2; exit 2 ;;
esac
