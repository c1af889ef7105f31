#!/usr/bin/env bash
# A batch of 20 small runs (the Cornell box at 64 x 64, 40 bins, shadow
# map 64^2, RSM 4^2, 100 points per VPL, no sensors, no video, CPU backend;
# render.seed 1..20: what a run costs besides its render), rendered into a fresh
# folder under /usr/bin/time -v by each tofsim binary given, ROUNDS times in
# turn (default 3), with --jobs JOBS (default 1). Prints one line per batch:
# binary, wall seconds, user + system CPU seconds, peak memory of the
# largest process.
#   bash bench/batch_one_process/run.sh OLD_TOFSIM NEW_TOFSIM
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
seeds=$(seq -s, 1 20)
cat >"$work/batch.yaml" <<YAML
base: $root/configs/cornell_box.yaml
output: out
set:
  camera.resolution: [64, 64]
  time.bins: 40
  render.shadow_map_resolution: 64
  render.indirect.rsm_resolution: 4
  render.indirect.points_per_vpl: 100
  sensors: []
  output.video: false
  render.backend: cpu
sweep:
  zip:
    render.seed: [$seeds]
YAML
for round in $(seq "${ROUNDS:-3}"); do
  for bin in "$@"; do
    rm -rf "$work/out"
    /usr/bin/time -v "$bin" batch "$work/batch.yaml" --jobs "${JOBS:-1}" -q \
      >"$work/stdout" 2>"$work/time"
    grep -q "20 done" "$work/stdout" || { cat "$work/stdout" "$work/time"; exit 1; }
    awk -v bin="$bin" -v round="$round" '
      /Elapsed \(wall clock\)/ { n = split($NF, t, ":"); wall = (n == 3 ? t[1] * 3600 + t[2] * 60 + t[3] : t[1] * 60 + t[2]) }
      /User time/ { user = $NF } /System time/ { sys = $NF }
      /Maximum resident/ { rss = $NF }
      END { printf "round %d  %-45s wall %6.2f s  cpu %6.2f s  max RSS %6.1f MiB\n", round, bin, wall, user + sys, rss / 1024 }' "$work/time"
  done
done
