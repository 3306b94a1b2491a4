# shellcheck shell=bash
# A one-node Slurm cluster on this machine, for the field tests and benchmarks.
# Source it, then:
#   local_slurm_start DIR [CPUS]   munged + slurmctld + slurmd, everything under DIR, loopback only;
#                                  exports SLURM_CONF so sbatch/squeue/scontrol talk to it
#   local_slurm_stop               cancels what is left and stops the three daemons it started
#   local_slurm_wait_idle SECONDS  waits until the queue is empty (returns 1 on time-out)
#   local_slurm_logs               the tail of each daemon's log (why something did not start)
# No systemd, no cgroups, no /etc changes: the daemons run as the current user (root in our
# containers) with a generated munge key, state and spool dirs under DIR, and random ports, so
# two runs on one machine (two worktrees' `make test`) do not meet.
# Needs Debian's slurm-wlm and munge (scripts/install-deps.sh installs them).

local_slurm_dir=""

local_slurm_logs() {
  local f
  for f in "$local_slurm_dir"/log/*.log "$local_slurm_dir"/munge/munged.log; do
    [ -f "$f" ] || continue
    echo "--- tail of $f" >&2
    tail -n 25 "$f" >&2
  done
}

# A TCP port nothing listens on; Slurm wants two fixed ones in its config.
local_slurm_free_port() {
  local port
  for _ in $(seq 50); do
    port=$((20000 + RANDOM % 30000))
    if ! ss -Hltn "sport = :$port" 2>/dev/null | grep -q .; then
      echo "$port"
      return 0
    fi
  done
  echo "no free port found" >&2
  return 1
}

local_slurm_start() {
  local dir=${1:?usage: local_slurm_start DIR [CPUS]}
  local cpus=${2:-2}
  local d
  for d in slurmctld slurmd munged sbatch squeue scontrol sinfo munge; do
    command -v "$d" >/dev/null || { echo "local_slurm: $d not found (install slurm-wlm and munge)" >&2; return 1; }
  done
  mkdir -p "$dir"
  local_slurm_dir=$(cd "$dir" && pwd)
  dir=$local_slurm_dir
  # munged refuses a key or socket folder that others can write to (and /tmp is such a folder).
  mkdir -p "$dir/munge" "$dir/state" "$dir/spool" "$dir/log"
  chmod 0755 "$dir" "$dir/munge"
  dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
  chmod 0600 "$dir/munge/munge.key"
  # --force: munged otherwise stops at the first permission check it does not like on a
  # temporary folder; the key is ours and private all the same.
  if ! munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.sock" \
      --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" \
      --seed-file="$dir/munge/munged.seed"; then
    echo "local_slurm: munged did not start" >&2
    local_slurm_logs
    return 1
  fi

  local host ctld_port slurmd_port mem_mb
  host=$(hostname -s)
  ctld_port=$(local_slurm_free_port) || return 1
  slurmd_port=$(local_slurm_free_port) || return 1
  # Slurm compares a job's --mem with the node's RealMemory (default 1 MB): state most of
  # the machine's memory so that the example scripts' requests fit.
  mem_mb=$(awk '/^MemTotal:/ {printf "%d", $2 / 1024 * 0.9}' /proc/meminfo)
  cat >"$dir/slurm.conf" <<EOF
# Written by tests/cluster/local_slurm.sh: one node, loopback only.
ClusterName=caliper3d-local
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
# slurmd binds to its NodeAddr (127.0.0.1) with this; slurmctld still listens on every
# interface, but every address in this file is 127.0.0.1, so no traffic leaves the machine.
CommunicationParameters=NoInAddrAny
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.sock
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
# No cgroups in a container: track processes by /proc and bind no CPUs.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SwitchType=switch/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
# The default waits up to 3 s before starting the next batch job (tuned for floods of
# submissions); an array of short tasks then spends most of its time waiting.
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0,default_queue_depth=1000
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
# One line per finished job (state, exit code, array index): what sacct would show.
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/log/jobcomp.txt
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem_mb State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
  export SLURM_CONF="$dir/slurm.conf"
  if ! slurmctld -f "$SLURM_CONF"; then
    echo "local_slurm: slurmctld did not start" >&2
    local_slurm_logs
    return 1
  fi
  if ! slurmd -f "$SLURM_CONF" -N "$host"; then
    echo "local_slurm: slurmd did not start" >&2
    local_slurm_logs
    return 1
  fi
  # The node registers within a second or two; it must be idle before a job can run.
  local state=""
  for _ in $(seq 60); do
    state=$(timeout 5 sinfo -h -n "$host" -o %T 2>/dev/null || true)
    [ "$state" = idle ] && return 0
    sleep 0.5
  done
  echo "local_slurm: node $host is '${state:-not reported}' after 30 s, not idle" >&2
  local_slurm_logs
  return 1
}

local_slurm_wait_idle() {
  local limit=${1:-120}
  local start=$SECONDS
  # squeue under timeout: a client whose munge credential is refused retries for minutes.
  while [ -n "$(timeout 5 squeue -h -o %i 2>/dev/null || echo unknown)" ]; do
    if [ $((SECONDS - start)) -ge "$limit" ]; then
      echo "local_slurm: jobs still queued after ${limit} s:" >&2
      timeout 5 squeue >&2 || true
      return 1
    fi
    sleep 0.2
  done
}

local_slurm_stop() {
  [ -n "$local_slurm_dir" ] || return 0
  local dir=$local_slurm_dir pidfile pid
  timeout 5 scancel --user="$(id -un)" 2>/dev/null || true
  for pidfile in "$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munge/munged.pid"; do
    [ -f "$pidfile" ] || continue
    pid=$(cat "$pidfile")
    kill "$pid" 2>/dev/null || continue
    # Wait so that the folder can be removed and the ports are free again.
    for _ in $(seq 50); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -9 "$pid" 2>/dev/null || true
  done
  local_slurm_dir=""
}
