#!/usr/bin/env bash
# A private Slurm cluster on this machine, for the `cluster` tests and for trying a study's job
# array before taking it to a real cluster. Needs root and Debian's slurm-wlm and munge
# (tools/bootstrap.sh test installs them); touches nothing outside DIR: its own munge key and
# socket, its own ports, state and logs.
#
#   tools/cluster/local_slurm.sh start DIR [--nodes N] [--cpus C] [--watch PID]
#       starts munged, slurmctld and N slurmd (default 1) on this machine, each a node with C
#       CPUs (default: all of them), and waits until every node is idle. With --watch, everything is stopped as
#       soon as process PID ends (a killed test leaves nothing running). Prints the line to use:
#       export SLURM_CONF=DIR/slurm.conf
#   tools/cluster/local_slurm.sh stop DIR
#       cancels the cluster's jobs, stops its daemons and waits until they are gone.
set -euo pipefail

usage() {
  echo "usage: $0 start DIR [--nodes N] [--cpus C] [--watch PID] | stop DIR" >&2
  exit 2
}
[ $# -ge 2 ] || usage
action="$1"
dir="$(mkdir -p "$2" && cd "$2" && pwd)"
shift 2
nodes=1
cpus="$(nproc)"
watch=""
while [ $# -gt 0 ]; do
  case "$1" in
    --nodes) nodes="$2"; shift 2 ;;
    --cpus) cpus="$2"; shift 2 ;;
    --watch) watch="$2"; shift 2 ;;
    *) usage ;;
  esac
done
export SLURM_CONF="$dir/slurm.conf"

# Waits up to $1 seconds for command "${@:2}" to succeed.
wait_for() {
  local limit="$1"; shift
  local end=$((SECONDS + limit))
  until "$@" >/dev/null 2>&1; do
    [ "$SECONDS" -lt "$end" ] || return 1
    sleep 0.5
  done
}

stop_cluster() {
  [ -f "$dir/pids" ] || return 0
  # Jobs first (their steps run under slurmd), then the daemons, the watcher last.
  if [ -f "$SLURM_CONF" ] && command -v scancel >/dev/null; then
    scancel --quiet --user=root 2>/dev/null || true
    wait_for 20 bash -c '[ -z "$(squeue --noheader 2>/dev/null)" ]' || true
  fi
  local pids=()
  while read -r name pid; do
    [ "$name" = watcher ] && [ "$pid" = "${BASHPID:-$$}" ] && continue
    pids+=("$pid")
  done <"$dir/pids"
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  local end=$((SECONDS + 15))
  for pid in "${pids[@]}"; do
    while kill -0 "$pid" 2>/dev/null; do
      if [ "$SECONDS" -ge "$end" ]; then kill -KILL "$pid" 2>/dev/null || true; fi
      sleep 0.2
    done
  done
  rm -f "$dir/pids"
}

if [ "$action" = stop ]; then
  stop_cluster
  exit 0
fi
[ "$action" = start ] || usage

for command in munged slurmctld slurmd sbatch squeue scancel sinfo; do
  command -v "$command" >/dev/null || {
    echo "$0: $command not found: install slurm-wlm and munge (bash tools/bootstrap.sh test)" >&2
    exit 2
  }
done
[ "$(id -u)" -eq 0 ] || { echo "$0: needs root (munged and slurmd run as root)" >&2; exit 2; }
[ ! -f "$dir/pids" ] || { echo "$0: a cluster is already running in $dir (stop it first)" >&2; exit 2; }

# munged insists on a socket folder everyone may enter and on a key only root can read.
chmod 755 "$dir"
mkdir -p "$dir/state" "$dir/spool" "$dir/log"
head -c 1024 /dev/urandom >"$dir/munge.key"
chmod 400 "$dir/munge.key"

# Free TCP ports: the controller's, then one per node.
port_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
ports=()
candidate=$((20000 + RANDOM % 20000))
while [ "${#ports[@]}" -lt $((nodes + 1)) ]; do
  if port_free "$candidate"; then ports+=("$candidate"); fi
  candidate=$((candidate + 1))
done

host="$(hostname -s)"
{
  echo "ClusterName=saltus-local"
  echo "SlurmctldHost=$host(127.0.0.1)"
  echo "SlurmctldPort=${ports[0]}"
  echo "SlurmUser=root"
  echo "SlurmdUser=root"
  echo "AuthType=auth/munge"
  echo "AuthInfo=socket=$dir/munge.socket"
  echo "CredType=cred/munge"
  echo "StateSaveLocation=$dir/state"
  echo "SlurmdSpoolDir=$dir/spool/%n"
  echo "SlurmctldPidFile=$dir/slurmctld.pid"
  echo "SlurmdPidFile=$dir/slurmd-%n.pid"
  echo "SlurmctldLogFile=$dir/log/slurmctld.log"
  echo "SlurmdLogFile=$dir/log/slurmd-%n.log"
  echo "ProctrackType=proctrack/linuxproc"
  echo "TaskPlugin=task/none"
  echo "SelectType=select/cons_tres"
  echo "SelectTypeParameters=CR_CPU"
  echo "SchedulerType=sched/backfill"
  echo "ReturnToService=2"
  echo "MpiDefault=none"
  echo "JobCompType=jobcomp/none"
  echo "AccountingStorageType=accounting_storage/none"
  for ((n = 1; n <= nodes; ++n)); do
    echo "NodeName=saltus$n NodeHostname=$host NodeAddr=127.0.0.1 Port=${ports[n]} CPUs=$cpus State=UNKNOWN"
  done
  echo "PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP"
} >"$SLURM_CONF"

: >"$dir/pids"
trap 'stop_cluster' ERR
munged --foreground --key-file="$dir/munge.key" --socket="$dir/munge.socket" \
  --pid-file="$dir/munged.pid" --log-file="$dir/log/munged.log" --seed-file="$dir/munged.seed" \
  >"$dir/log/munged.out" 2>&1 &
echo "munged $!" >>"$dir/pids"
wait_for 10 test -S "$dir/munge.socket"
slurmctld -D -f "$SLURM_CONF" >"$dir/log/slurmctld.out" 2>&1 &
echo "slurmctld $!" >>"$dir/pids"
for ((n = 1; n <= nodes; ++n)); do
  mkdir -p "$dir/spool/saltus$n"
  slurmd -D -N "saltus$n" -f "$SLURM_CONF" >"$dir/log/slurmd-saltus$n.out" 2>&1 &
  echo "slurmd $!" >>"$dir/pids"
done
if [ -n "$watch" ]; then
  # Stops the cluster when the process that asked for it ends, however it ends.
  setsid bash -c 'while kill -0 "$1" 2>/dev/null; do sleep 1; done; exec "$2" stop "$3"' \
    watcher "$watch" "$(cd "$(dirname "$0")" && pwd)/$(basename "$0")" "$dir" \
    </dev/null >"$dir/log/watcher.out" 2>&1 &
  echo "watcher $!" >>"$dir/pids"
fi
if ! wait_for 60 bash -c "[ \"\$(sinfo --noheader --responding --Node -o '%T' | grep -c idle)\" -ge $nodes ]"; then
  echo "$0: the cluster did not come up; logs in $dir/log" >&2
  tail -n 5 "$dir"/log/*.log >&2 || true
  stop_cluster
  exit 1
fi
trap - ERR
echo "export SLURM_CONF=$SLURM_CONF"
