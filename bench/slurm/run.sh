#!/usr/bin/env bash
# A 64-run sweep through a local one-node Slurm cluster (issue 28) against
# `tofsim batch --jobs 2` on the same machine: total wall seconds from the
# submission to the last array task leaving the queue, or of the batch.
#
# The runs are tiny (the Cornell box demo on the CPU backend at 16 x 16
# pixels, 64 bins, 64 VPLs, its three sensors, no video; seeds 1..64), so the
# table shows what Slurm adds per task and per batch, not render speed. Each
# case renders into a fresh folder. The Slurm cases submit the README's script
# (scripts/slurm/tofsim-array.sbatch) with --array=0-(N-1) and N shards, with
# --cpus-per-task=1 (two tasks at once on the 2-CPU node) unless the case
# says 2 (the script's own default: one task at a time). The cluster:
# tests/cluster/slurm_cluster.sh (root, slurm-wlm and munge), default
# scheduler settings.
#
# Usage: bench/slurm/run.sh [REPS=1] [TOFSIM=build/apps/cli/tofsim]
set -euo pipefail
cd "$(dirname "$0")/../.."
src=$PWD
reps=${1:-1}
tofsim=$(realpath "${2:-build/apps/cli/tofsim}")
source tests/cluster/slurm_cluster.sh
slurm_cluster_can_run "$src" || {
  echo "bench/slurm: $slurm_cluster_why" >&2
  exit 77
}

work=$(mktemp -d /tmp/tofsim-slurm-bench.XXXXXX)
chmod 755 "$work"
trap 'slurm_cluster_down; rm -rf "$work"; echo "[$(date +%T)] done" >&2' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

seeds=$(seq -s, 1 64)
write_batch() { # FILE OUTPUT
  {
    write_batch_header "$src" "$2"
    cat <<EOF
sweep:
  zip:
    render.seed: [$seeds]
EOF
  } >"$1"
}

slurm_cluster_up "$work/cluster"
export PATH="$(dirname "$tofsim"):$PATH"
cd "$work"

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }
case_id=0
fresh_batch() { # sets $batch: a batch file with an output folder of its own
  case_id=$((case_id + 1))
  batch=$work/batch$case_id.yaml
  write_batch "$batch" "out$case_id"
}
check_done() { # BATCH: all 64 runs done, or exit
  "$tofsim" batch "$1" --dry-run | grep -q "batch: 64 of 64 run(s) in this shard: 64 done, 0 to run" || {
    echo "bench/slurm: not every run of $1 is done" >&2
    exit 1
  }
}
local_case() { # JOBS
  local t0 t1
  echo "[$(date +%T)] tofsim batch --jobs $1" >&2
  fresh_batch
  t0=$(now)
  "$tofsim" batch "$batch" --jobs "$1" -q >/dev/null
  t1=$(now)
  check_done "$batch"
  echo "| \`tofsim batch --jobs $1\` | - | $1 | $(elapsed "$t0" "$t1") | - | - |"
}
slurm_case() { # TASKS CPUS_PER_TASK
  local t0 t1 reply job
  echo "[$(date +%T)] Slurm: $1 tasks, --cpus-per-task=$2" >&2
  fresh_batch
  t0=$(now)
  reply=$(sbatch --cpus-per-task="$2" --array=0-$(($1 - 1)) \
    "$src/scripts/slurm/tofsim-array.sbatch" "$batch" "$1")
  job=${reply##* }
  slurm_wait_job "$job" 600
  t1=$(now)
  check_done "$batch"
  local ok
  ok=$(slurm_task_states "$job" | grep -c " COMPLETED$" || true)
  [ "$ok" -eq "$1" ] || {
    echo "bench/slurm: only $ok of $1 tasks completed" >&2
    exit 1
  }
  # From slurmctld's log: each task's seconds from its allocation to its
  # completion, and the share of the wall time the node's task slots
  # (2 / CPUs per task) were allocated.
  local tasks
  tasks=$(python3 - "$slurm_cluster_dir/log/slurmctld.log" "$job" "$(elapsed "$t0" "$t1")" "$2" "$1" <<'PY'
import re, sys
from datetime import datetime
log, job, wall, cpus, tasks = sys.argv[1], sys.argv[2], float(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
start, end = {}, {}
# "sched: Allocate JobId=J_K(..)" or, from the backfill scheduler,
# "sched/backfill: _start_job: Started JobId=J_K(..)"; "_job_complete: JobId=J_K(..)".
for line in open(log):
    m = re.match(r"\[([^\]]+)\] .*\b(Allocate|Started|_job_complete:) JobId=%s_(\d+)\(" % job, line)
    if not m:
        continue
    t = datetime.fromisoformat(m.group(1)).timestamp()
    (end if m.group(2) == "_job_complete:" else start).setdefault(int(m.group(3)), t)
assert len(start) == len(end) == tasks, (len(start), len(end), tasks)
spans = [end[k] - start[k] for k in start if k in end]
slots = 2 // cpus
print(f"{sum(spans) / len(spans):.2f} | {100 * sum(spans) / (wall * slots):.0f} %")
PY
  )
  echo "| Slurm array | $1 | $2 | $(elapsed "$t0" "$t1") | $tasks |"
}

echo "commit $(git -C "$src" rev-parse --short HEAD 2>/dev/null || echo ?), $(nproc) CPUs, load before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| how | array tasks | CPUs per task / jobs | wall s | task s (mean) | slots allocated |"
echo "|---|---|---|---|---|---|"
for ((r = 1; r <= reps; ++r)); do
  local_case 2
  slurm_case 2 1
  slurm_case 4 1
  slurm_case 64 1
  slurm_case 2 2
  local_case 1
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "[$(date +%T)] tearing down" >&2
