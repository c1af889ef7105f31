#!/usr/bin/env bash
# Issue 28: a batch through a real Slurm job array, by the README's recipe
# (README.md, "On a cluster"), on a one-node cluster brought up here from
# Debian's slurm-wlm and munge (tests/cluster/slurm_cluster.sh).
#
#   slurm_array_test.sh TOFSIM_BINARY [SOURCE_DIR]
#
# 1. The README's sbatch script is scripts/slurm/tofsim-array.sbatch, as
#    written there; its submit commands are run as written, with this test's
#    batch file for configs/sweep.yaml.
# 2. An 8-run sweep (CPU backend, 16 x 16 pixels; run r3 at 128 x 128 x 640
#    bins, a few seconds) goes in as an 8-task array. While task 3 renders r3
#    it is cancelled (scancel JOB_3): the render is paused (SIGSTOP) at that
#    moment, so that it is mid-run on a machine of any speed; scancel's
#    SIGCONT + SIGTERM end it. Its batch must report r3 `interrupted`, with
#    no manifest, and `--dry-run` must show r3 not done and the other 7 done.
# 3. The README's resubmit command (--array=3) finishes it. A plain
#    `tofsim batch` over the same folder, started while the task renders r3,
#    waits for r3's lock and skips it. `tofsim batch --verify --dry-run`
#    then shows all 8 runs `done` (checksums checked), and `tofsim batch
#    --verify` skips all 8 and renders nothing.
# 4. r3's files equal those of an uninterrupted render of the same run
#    (without Slurm, into another folder), byte for byte; transient.json
#    apart from its timing stats.
# The cluster is torn down whatever happens (EXIT trap): jobs cancelled,
# slurmd, slurmctld and munged stopped by pid, the temporary folder removed.
# Exit 77 (ctest: skipped) without root or without the packages.
set -euo pipefail

if [ $# -lt 1 ]; then
  echo "usage: $0 TOFSIM_BINARY [SOURCE_DIR]" >&2
  exit 2
fi
tofsim=$(realpath "$1")
src=$(realpath "${2:-$(dirname "$0")/../..}")
# shellcheck source=slurm_cluster.sh
source "$src/tests/cluster/slurm_cluster.sh"

if ! slurm_cluster_can_run "$src"; then
  echo "SKIP: $slurm_cluster_why"
  exit 77
fi
[ -x "$tofsim" ] || {
  echo "FAIL: no tofsim binary at $tofsim" >&2
  exit 1
}

work=$(mktemp -d /tmp/tofsim-slurm-test.XXXXXX)
chmod 755 "$work" # munged's socket below it must be reachable by all
failed=0
cleanup() {
  local rc=$?
  trap - EXIT INT TERM
  if [ $rc -ne 0 ] && [ $rc -ne 77 ]; then
    echo "--- cluster state at the failure" >&2
    squeue >&2 2>/dev/null || true
    for f in "$work"/slurm-*.out; do
      [ -f "$f" ] && { echo "--- $f" >&2; cat "$f" >&2; }
    done
    [ -n "$slurm_cluster_dir" ] && _slurm_log_tail
  fi
  slurm_cluster_down
  rm -rf "$work"
  exit $rc
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

fail() {
  echo "FAIL: $*" >&2
  failed=1
}
step() { echo "[$(date +%T)] $*"; }

script=scripts/slurm/tofsim-array.sbatch

# --- 1. The README shows the script and the commands this test runs ---------
# The first ```bash block after the line naming the script is the script.
readme_script=$(awk -v name="$script" '
  index($0, name) && !seen { seen = 1 }
  seen && /^```bash$/ && !inside && !done { inside = 1; next }
  inside && /^```$/ { inside = 0; done = 1 }
  inside { print }' "$src/README.md")
if [ "$readme_script" != "$(cat "$src/$script")" ]; then
  fail "README.md's cluster section does not show $script as it is:"
  diff <(echo "$readme_script") "$src/$script" >&2 || true
fi
submit_all=$(grep -m1 -E "^sbatch --array=0-7 $script configs/sweep.yaml 8( |$)" "$src/README.md" || true)
submit_one=$(grep -m1 -E "^sbatch --array=3 $script configs/sweep.yaml 8( |$)" "$src/README.md" || true)
[ -n "$submit_all" ] || fail "README.md has no line 'sbatch --array=0-7 $script configs/sweep.yaml 8'"
[ -n "$submit_one" ] || fail "README.md has no line 'sbatch --array=3 $script configs/sweep.yaml 8'"
[ $failed -eq 0 ] || exit 1
# The README's command, comment dropped, with this test's batch file.
readme_command() {
  local line=${1%%#*}
  line=${line//configs\/sweep.yaml/$work\/sweep.yaml}
  echo "${line//$script/$src/$script}"
}

# --- the batch: 8 runs, r3 slow --------------------------------------------
write_batch() { # FILE OUTPUT
  {
    write_batch_header "$src" "$2"
    cat <<EOF
runs:
  - {name: r0, set: {render.seed: 1}}
  - {name: r1, set: {render.seed: 2}}
  - {name: r2, set: {render.seed: 3}}
  - {name: r3, set: {render.seed: 4, camera.resolution: [128, 128], time.bins: 640}}
  - {name: r4, set: {render.seed: 5}}
  - {name: r5, set: {render.seed: 6}}
  - {name: r6, set: {render.seed: 7}}
  - {name: r7, set: {render.seed: 8}}
EOF
  } >"$1"
}
write_batch "$work/sweep.yaml" out
write_batch "$work/reference.yaml" reference
out=$work/out

step "bringing up slurmctld + slurmd + munged in $work/cluster"
slurm_cluster_up "$work/cluster"
export PATH="$(dirname "$tofsim"):$PATH" # the script runs `tofsim` from PATH
cd "$work"                               # slurm-JOB_TASK.out files land here

submit() { # the README's command line; prints the job id
  local reply
  reply=$(eval "$(readme_command "$1")")
  echo "$reply" >&2
  [[ $reply =~ ^Submitted\ batch\ job\ ([0-9]+) ]] || return 1
  echo "${BASH_REMATCH[1]}"
}

# The pid of the process that renders r3, if one does: a batch renders its
# runs on worker processes it forks (tofsim batch, "Batch files"); the worker
# that renders r3 holds r3's folder lock (out/r3/.tofsim.lock), and
# /proc/locks names a lock's holder by the lock file's inode.
render_pid() {
  local lock="$out/r3/.tofsim.lock" ino
  [ -e "$lock" ] || return 0
  ino=$(stat -c %i "$lock" 2>/dev/null) || return 0
  awk -v ino="$ino" '{ for (i = 1; i <= NF; i++) if ($i ~ /^[0-9a-f]+:[0-9a-f]+:[0-9]+$/) {
         split($i, d, ":"); if (d[3] == ino && $(i - 1) ~ /^[0-9]+$/) print $(i - 1) } }' \
    /proc/locks | head -n1
}

# --- 2. the array, task 3 cancelled while r3 renders -------------------------
step "submitting: $(readme_command "$submit_all")"
job=$(submit "$submit_all")
pid=""
deadline=$((SECONDS + 120))
while [ -z "$pid" ]; do
  [ $SECONDS -lt $deadline ] || {
    fail "r3's render did not start within 120 s"
    exit 1
  }
  sleep 0.1
  pid=$(render_pid)
done
sleep 0.5 # into the render
[ ! -e "$out/r3/manifest.json" ] || fail "r3 finished before it could be cancelled"
kill -STOP "$pid" 2>/dev/null || fail "r3's render (pid $pid) ended before it could be cancelled"
step "cancelling task 3 (job ${job}_3) while r3 renders (render pid $pid paused)"
scancel "${job}_3"
slurm_wait_job "$job" 240 || exit 1

states=$(slurm_task_states "$job")
expected=$(printf '%s\n' "0 COMPLETED" "1 COMPLETED" "2 COMPLETED" "3 CANCELLED" \
  "4 COMPLETED" "5 COMPLETED" "6 COMPLETED" "7 COMPLETED")
[ "$states" = "$expected" ] || fail "array task states (task state):"$'\n'"$states"
log3=$work/slurm-${job}_3.out
cat "$log3"
grep -qE "^r3 +interrupted " "$log3" || fail "task 3's batch did not report r3 interrupted ($log3)"
grep -q "interrupted by SIGTERM" "$log3" || fail "task 3's batch was not stopped by SIGTERM"
[ ! -e "$out/r3/manifest.json" ] || fail "the cancelled r3 has a manifest"
kill -0 "$pid" 2>/dev/null && fail "r3's render (pid $pid) outlived its cancelled task"
dry=$("$tofsim" batch "$work/sweep.yaml" --dry-run --verify)
echo "$dry"
for r in r0 r1 r2 r4 r5 r6 r7; do
  echo "$dry" | grep -qE "^$r +done " || fail "$r is not done after the array"
done
echo "$dry" | grep -qE "^r3 +incomplete" || fail "the cancelled r3 is not incomplete"
[ $failed -eq 0 ] || exit 1

# --- 3. task 3 resubmitted ----------------------------------------------------
step "resubmitting: $(readme_command "$submit_one")"
job2=$(submit "$submit_one")
# Beside it, a plain batch over the same folder (no shard: an overlap). It
# finds r3 locked by the task, waits, and skips r3 once the task is done.
pid=""
deadline=$((SECONDS + 120))
while [ -z "$pid" ] && [ $SECONDS -lt $deadline ]; do
  sleep 0.1
  pid=$(render_pid)
done
[ -n "$pid" ] || fail "the resubmitted task did not start r3's render within 120 s"
step "a plain tofsim batch beside the task, which renders r3 (pid $pid)"
beside=$("$tofsim" batch "$work/sweep.yaml" -q) || fail "the batch beside the task exited $?"
echo "$beside"
echo "$beside" | grep -q "batch: 8 of 8 run(s) in this shard: 0 done, 8 skipped, 0 failed" ||
  fail "the batch beside the task did not wait for r3 and skip it"
slurm_wait_job "$job2" 240 || exit 1
[ "$(slurm_task_states "$job2")" = "3 COMPLETED" ] || fail "the resubmitted task 3 did not complete"
log3b=$work/slurm-${job2}_3.out
cat "$log3b"
grep -qE "^r3 +done " "$log3b" || fail "the resubmitted task did not render r3"
grep -q "batch: 1 of 8 run(s) in this shard: 1 done" "$log3b" || fail "the resubmitted task ran more than r3"

dry=$("$tofsim" batch "$work/sweep.yaml" --dry-run --verify)
echo "$dry"
[ "$(echo "$dry" | grep -cE "^r[0-7] +done ")" -eq 8 ] || fail "not every run is done (--verify --dry-run)"
echo "$dry" | grep -q "batch: 8 of 8 run(s) in this shard: 8 done, 0 to run" || fail "--dry-run summary"
verify=$("$tofsim" batch "$work/sweep.yaml" --verify -q) || fail "tofsim batch --verify exited $?"
echo "$verify"
echo "$verify" | grep -q "batch: 8 of 8 run(s) in this shard: 0 done, 8 skipped, 0 failed" ||
  fail "tofsim batch --verify rendered something"

# --- 4. the resumed r3 against an uninterrupted one --------------------------
step "rendering r3 again without Slurm and without interruption"
"$tofsim" batch "$work/reference.yaml" --shard 4/8 -q >/dev/null
ref=$work/reference/r3
n=0
while IFS= read -r -d '' f; do
  rel=${f#"$ref"/}
  case $rel in
    log.txt | manifest.json) continue ;;
    transient.json)
      # Equal but for the render's timing (stats.seconds, stats.pass_seconds).
      python3 - "$f" "$out/r3/$rel" <<'EOF' || fail "r3/transient.json differs beyond its timing stats"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
for d in (a, b):
    d.get("stats", {}).pop("seconds", None)
    d.get("stats", {}).pop("pass_seconds", None)
sys.exit(a != b)
EOF
      ;;
    *) cmp -s "$f" "$out/r3/$rel" || fail "r3/$rel differs from an uninterrupted render" ;;
  esac
  n=$((n + 1))
done < <(find "$ref" -type f ! -name '.*' -print0)
[ -d "$out/r3" ] && [ "$(find "$out/r3" -type f ! -name '.*' | wc -l)" -eq "$(find "$ref" -type f ! -name '.*' | wc -l)" ] ||
  fail "the resumed r3 and the uninterrupted one have different file lists"
[ $n -gt 10 ] || fail "only $n files compared"
step "r3: $n files equal to an uninterrupted render"

[ $failed -eq 0 ] || exit 1
step "PASS"
