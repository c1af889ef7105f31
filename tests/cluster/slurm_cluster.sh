# A throw-away single-node Slurm cluster on this machine, for
# tests/cluster/slurm_array_test.sh and bench/slurm/run.sh (source this file).
#
#   slurm_cluster_can_run || exit 77        # why not: $slurm_cluster_why
#   slurm_cluster_up DIR                    # munged + slurmctld + slurmd
#   ... sbatch / squeue / scancel (SLURM_CONF points at DIR/slurm.conf) ...
#   slurm_cluster_down                      # also from an EXIT trap
#   write_batch_header SRC OUTPUT >FILE     # the batch both run; append runs
#
# Debian's packages (slurm-wlm, munge: scripts/install-cluster-deps.sh), run
# as root: munged with a generated key and its own socket, slurmctld and one
# slurmd (node `tofsim1`, CPUs=2, RealMemory of this machine) on free
# localhost ports, every state, spool, log and pid file under DIR. No cgroups
# (a container has none to give): ProctrackType=proctrack/linuxproc,
# TaskPlugin=task/none. The cluster writes nothing outside DIR; teardown ends
# only the processes it started: the daemons by their pids, then whatever of
# the cluster is left (_slurm_marked_pids: the daemons alone are started with
# TOFSIM_SLURM_CLUSTER=DIR in their environment; the jobs' processes carry
# SLURM_JOB_ID and this SLURM_CONF), by pid.

slurm_cluster_dir=""
slurm_cluster_why=""
slurm_cluster_pids=()   # munged slurmctld slurmd, in start order
slurm_cluster_commands=(munged munge slurmctld slurmd sbatch squeue scancel scontrol sinfo)

# 0 when this machine can bring the cluster up; else 1 with the reason in
# $slurm_cluster_why. Installs the packages (scripts/install-cluster-deps.sh)
# when they are missing and this is root.
slurm_cluster_can_run() {
  local source_dir=${1:-}
  if [ "$(uname -s)" != Linux ]; then
    slurm_cluster_why="needs Linux (it starts munged, slurmctld and slurmd here)"
    return 1
  fi
  if [ "$(id -u)" -ne 0 ]; then
    slurm_cluster_why="needs root: it starts munged, slurmctld and slurmd (SlurmUser=root) on this machine"
    return 1
  fi
  local missing=() c
  for c in "${slurm_cluster_commands[@]}"; do
    PATH="$PATH:/usr/sbin:/sbin" command -v "$c" >/dev/null || missing+=("$c")
  done
  if [ ${#missing[@]} -gt 0 ] && [ -n "$source_dir" ] && command -v apt-get >/dev/null; then
    echo "slurm cluster: ${missing[*]} missing; installing slurm-wlm munge" >&2
    timeout 300 bash "$source_dir/scripts/install-cluster-deps.sh" >&2 || true
    missing=()
    for c in "${slurm_cluster_commands[@]}"; do
      PATH="$PATH:/usr/sbin:/sbin" command -v "$c" >/dev/null || missing+=("$c")
    done
  fi
  if [ ${#missing[@]} -gt 0 ]; then
    slurm_cluster_why="Slurm/munge not installed and not installable here (missing: ${missing[*]}; Debian packages slurm-wlm munge, scripts/install-cluster-deps.sh)"
    return 1
  fi
  return 0
}

# The start of the batch file that both the test and the bench submit, on
# stdout: the Cornell box demo of SRC (the source folder) made tiny (CPU
# backend, 16 x 16 pixels, 64 bins, 64 VPLs, no video, the sensors' plotted
# pixel and rows inside the image) into OUTPUT. The caller appends its runs
# (`sweep:` or `runs:`).
write_batch_header() { # SRC OUTPUT
  cat <<EOF
base: $1/configs/cornell_box.yaml
output: $2
set:
  render.backend: cpu
  camera.resolution: [16, 16]
  time.bins: 64
  render.indirect.rsm_resolution: 8
  output.video: false
  sensors.0.plot_pixels: [[8, 8]]
  sensors.1.rows: [8]
EOF
}

# A free TCP port on localhost (none listening on it, v4 or v6), from a
# random start: two clusters on one machine (a test beside a bench) take
# different ports.
_slurm_free_port() {
  local port=$((20000 + RANDOM % 30000)) hex
  for _ in $(seq 200); do
    hex=$(printf '%04X' "$port")
    if ! awk -v h=":$hex" 'NR > 1 && substr($2, length($2) - 4) == h { found = 1 } END { exit !found }' \
      /proc/net/tcp /proc/net/tcp6 2>/dev/null; then
      echo "$port"
      return 0
    fi
    port=$((port + 2))
  done
  return 1
}

_slurm_log_tail() {
  local f
  for f in "$slurm_cluster_dir"/log/*.log "$slurm_cluster_dir"/log/*.out; do
    [ -f "$f" ] || continue
    echo "--- last lines of $f" >&2
    tail -n 15 "$f" >&2
  done
}

# Starts the cluster with every file under DIR (created, empty or absent).
# Exports SLURM_CONF for the client commands. Returns 1 (with the daemons'
# logs on stderr) if it is not up in 60 s.
slurm_cluster_up() {
  local dir=$1
  export PATH="$PATH:/usr/sbin:/sbin"
  mkdir -p "$dir"
  slurm_cluster_dir=$(cd "$dir" && pwd)
  dir=$slurm_cluster_dir
  # munged's checks: the socket's folders searchable by all (DIR's parents
  # too: a mktemp -d parent needs chmod 755), the key readable by its owner
  # only.
  mkdir -p "$dir/munge" "$dir/key" "$dir/state" "$dir/spool" "$dir/log"
  chmod 755 "$dir" "$dir/munge"
  chmod 700 "$dir/key"
  dd if=/dev/urandom of="$dir/key/munge.key" bs=1024 count=1 status=none
  chmod 400 "$dir/key/munge.key"
  TOFSIM_SLURM_CLUSTER=$dir munged -F --key-file="$dir/key/munge.key" --socket="$dir/munge/munge.socket" \
    --pid-file="$dir/munge/munged.pid" --log-file="$dir/log/munged.log" \
    --seed-file="$dir/key/munged.seed" >"$dir/log/munged.out" 2>&1 </dev/null &
  slurm_cluster_pids+=($!)
  local deadline=$((SECONDS + 20))
  until munge -S "$dir/munge/munge.socket" -n </dev/null 2>/dev/null |
    unmunge -S "$dir/munge/munge.socket" >/dev/null 2>&1; do
    if [ $SECONDS -ge $deadline ]; then
      echo "slurm cluster: munged did not come up" >&2
      _slurm_log_tail
      return 1
    fi
    sleep 0.2
  done

  local memory ctld_port slurmd_port
  memory=$(slurmd -C 2>/dev/null | sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p' | head -n1)
  [ -n "$memory" ] || memory=$(awk '/^MemTotal:/ { print int($2 / 1024) }' /proc/meminfo)
  ctld_port=$(_slurm_free_port) && slurmd_port=$(_slurm_free_port) || {
    echo "slurm cluster: no free port" >&2
    return 1
  }
  [ "$slurmd_port" != "$ctld_port" ] || slurmd_port=$((ctld_port + 1))
  cat >"$dir/slurm.conf" <<EOF
# Generated by tests/cluster/slurm_cluster.sh: a one-node cluster in $dir
ClusterName=tofsimtest
SlurmctldHost=localhost
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool/slurmd-%n
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
# No cgroups in a container: processes tracked by parentage, no binding.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
# The node as configured here, whatever this machine's core count.
SlurmdParameters=config_overrides
ReturnToService=2
# scancel: SIGTERM, then SIGKILL after KillWait seconds.
KillWait=15
# Finished jobs stay visible to scontrol for 10 minutes.
MinJobAge=600
SlurmctldDebug=info
SlurmdDebug=info
NodeName=tofsim1 NodeHostname=$(hostname) NodeAddr=127.0.0.1 CPUs=2 RealMemory=$memory State=UNKNOWN
PartitionName=tofsim Nodes=tofsim1 Default=YES MaxTime=INFINITE State=UP
EOF
  export SLURM_CONF="$dir/slurm.conf"
  # In the foreground (-D), so that $! is the daemon itself.
  TOFSIM_SLURM_CLUSTER=$dir slurmctld -D -i -f "$SLURM_CONF" >"$dir/log/slurmctld.out" 2>&1 </dev/null &
  slurm_cluster_pids+=($!)
  TOFSIM_SLURM_CLUSTER=$dir slurmd -D -f "$SLURM_CONF" -N tofsim1 >"$dir/log/slurmd.out" 2>&1 </dev/null &
  slurm_cluster_pids+=($!)
  deadline=$((SECONDS + 60))
  local state=""
  while :; do
    state=$(sinfo -h -n tofsim1 -o %T 2>/dev/null || true)
    case $state in idle | mixed | allocated) break ;; esac
    if [ $SECONDS -ge $deadline ]; then
      echo "slurm cluster: node tofsim1 not idle after 60 s (state '${state}')" >&2
      _slurm_log_tail
      return 1
    fi
    sleep 0.5
  done
  return 0
}

# Waits until job JOBID (every array task of it) has left the queue, at most
# LIMIT seconds (default 300); 1 on timeout.
slurm_wait_job() {
  local job=$1 limit=${2:-300}
  local deadline=$((SECONDS + limit))
  while [ -n "$(squeue -h -j "$job" -o %i 2>/dev/null)" ]; do
    if [ $SECONDS -ge $deadline ]; then
      echo "slurm cluster: job $job still queued after $limit s" >&2
      squeue >&2 || true
      return 1
    fi
    sleep 0.3
  done
}

# "TASK STATE" for each array task of JOBID, sorted by task id.
slurm_task_states() {
  scontrol -o show job "$1" 2>/dev/null |
    sed -n 's/.*ArrayTaskId=\([0-9]*\) .*JobState=\([A-Z_]*\) .*/\1 \2/p' | sort -n
}

# The processes of this cluster that are still there: those with its marker
# in their environment (the daemons), its jobs' processes (SLURM_JOB_ID and
# this cluster's SLURM_CONF in their environment), the slurmstepd above
# those, and every descendant of these.
_slurm_marked_pids() {
  [ -n "$slurm_cluster_dir" ] || return 0
  local marker="TOFSIM_SLURM_CLUSTER=$slurm_cluster_dir"
  local conf="SLURM_CONF=$slurm_cluster_dir/slurm.conf"
  local s pid rest ppid e ours job
  local -a envs
  local -A parent=() marked=()
  for s in /proc/[0-9]*/stat; do
    pid=${s#/proc/}
    pid=${pid%/stat}
    { read -r rest <"$s"; } 2>/dev/null || continue
    rest=${rest##*) } # after the command name: state ppid ...
    ppid=${rest#* }
    parent[$pid]=${ppid%% *}
    envs=()
    { mapfile -d '' -t envs <"/proc/$pid/environ"; } 2>/dev/null || continue
    ours=0 job=0
    for e in "${envs[@]}"; do
      case $e in
        "$marker") ours=2 ;;
        "$conf") ours=$((ours > 0 ? ours : 1)) ;;
        SLURM_JOB_ID=*) job=1 ;;
      esac
    done
    if [ $ours -eq 2 ] || { [ $ours -eq 1 ] && [ $job -eq 1 ]; }; then marked[$pid]=1; fi
  done
  local cmd
  for pid in "${!marked[@]}"; do
    ppid=${parent[$pid]:-}
    [ -n "$ppid" ] && [ -z "${marked[$ppid]:-}" ] || continue
    { read -r -d '' cmd <"/proc/$ppid/cmdline"; } 2>/dev/null || true
    case $cmd in slurmstepd:*) marked[$ppid]=1 ;; esac
  done
  local changed=1
  while [ $changed -eq 1 ]; do
    changed=0
    for pid in "${!parent[@]}"; do
      if [ -z "${marked[$pid]:-}" ] && [ -n "${marked[${parent[$pid]}]:-}" ]; then
        marked[$pid]=1
        changed=1
      fi
    done
  done
  for pid in "${!marked[@]}"; do
    [ "$pid" != "$$" ] && [ "$pid" != "$BASHPID" ] && [ -d "/proc/$pid" ] && echo "$pid"
  done
  return 0
}

_slurm_wait_gone() {
  local deadline=$((SECONDS + $1)) pid
  shift
  for pid in "$@"; do
    while kill -0 "$pid" 2>/dev/null && [ $SECONDS -lt $deadline ]; do sleep 0.1; done
  done
}

# Stops everything slurm_cluster_up started and removes its folder (unless
# KEEP is given). Safe to call twice, and when the cluster never came up.
slurm_cluster_down() {
  local keep=${1:-}
  [ -n "$slurm_cluster_dir" ] || return 0
  if [ -n "${SLURM_CONF:-}" ] && [ ${#slurm_cluster_pids[@]} -ge 2 ] &&
    kill -0 "${slurm_cluster_pids[1]}" 2>/dev/null; then
    # Our cluster's jobs only: this SLURM_CONF reaches no other controller.
    timeout 10 scancel --quiet --partition=tofsim --user=root 2>/dev/null || true
    local deadline=$((SECONDS + 20))
    while [ -n "$(squeue -h -o %i 2>/dev/null)" ] && [ $SECONDS -lt $deadline ]; do sleep 0.3; done
  fi
  # slurmd, slurmctld, then munged (the others need it to the end).
  local i pid
  for ((i = ${#slurm_cluster_pids[@]} - 1; i >= 1; i--)); do
    kill -TERM "${slurm_cluster_pids[i]}" 2>/dev/null || true
  done
  _slurm_wait_gone 15 "${slurm_cluster_pids[@]:1}"
  # Steps and job processes that outlived their daemons.
  local left
  left=$(_slurm_marked_pids)
  for pid in $left; do
    case " ${slurm_cluster_pids[*]:0:1} " in *" $pid "*) continue ;; esac
    kill -KILL "$pid" 2>/dev/null || true
  done
  for pid in "${slurm_cluster_pids[@]:1}"; do kill -KILL "$pid" 2>/dev/null || true; done
  if [ ${#slurm_cluster_pids[@]} -ge 1 ]; then
    kill -TERM "${slurm_cluster_pids[0]}" 2>/dev/null || true
    _slurm_wait_gone 10 "${slurm_cluster_pids[0]}"
    kill -KILL "${slurm_cluster_pids[0]}" 2>/dev/null || true
  fi
  for pid in "${slurm_cluster_pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  left=$(_slurm_marked_pids)
  if [ -n "$left" ]; then
    echo "slurm cluster: processes left after teardown: $left" >&2
    for pid in $left; do kill -KILL "$pid" 2>/dev/null || true; done
  fi
  [ -n "$keep" ] || rm -rf "$slurm_cluster_dir"
  slurm_cluster_pids=()
  slurm_cluster_dir=""
  unset SLURM_CONF
}
