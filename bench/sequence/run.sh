#!/usr/bin/env bash
# The cost of a capture sequence (issue 26): configs/moving_block.yaml (the
# Cornell box with a sliding block, 128x128, 320 bins, RSM 32^2, CW-ToF) on
# the CPU backend. Variants, interleaved over RUNS:
#   static         a one-frame sequence (sequence.count 1) with the CW-ToF
#                  raws at once (integration_time 0): one render, with the
#                  process's start, scene load and renderer set-up
#   sequence_still 30 frames, one render each (integration_time 0): what a
#                  frame costs once the scene and renderer are prepared
#                  (re-baked meshes, the renderer's scene update, sensors,
#                  motion ground truth, files)
#   sequence_raws  30 frames as configured: each CW-ToF raw at its own time,
#                  5 renders per frame (the frame's time and 4 raws)
# Prints per run the process wall, CPU and max RSS, the wall per frame, the
# mean of the frames' `seconds` (frame.json: every render of the frame, its
# sensors and files) and of their render at t_k (frame.json
# render_stats.seconds), then the medians against static.
# Usage: bench/sequence/run.sh [RUNS=3] [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
runs=${1:-3}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
frames=30
still=(--set sensors.0.integration_time=0 --set sensors.0.readout_gap=0)
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| run | variant | frames | process wall s | wall per frame s | frame s (mean) | render at t_k s (mean) | CPU s | max RSS MB |"
echo "|---|---|---|---|---|---|---|---|---|"
run_one() {  # RUN NAME FRAMES ARGS...
  local run=$1 name=$2 n=$3
  shift 3
  local dir="$out/$name.$run"
  /usr/bin/time -f "%e %U %S %M" -o "$dir.time" ./build/apps/cli/tofsim render \
    configs/moving_block.yaml --backend cpu --set sequence.count="$n" "$@" -q -o "$dir"
  local wall user sys rss frame render
  read -r wall user sys rss <"$dir.time"
  read -r frame render < <(python3 -c '
import json, sys, glob
docs = [json.load(open(f)) for f in glob.glob(sys.argv[1] + "/frame_*/frame.json")]
print(sum(d["seconds"] for d in docs) / len(docs),
      sum(d["render_stats"]["seconds"] for d in docs) / len(docs))' "$dir")
  awk -v r="$run" -v n="$name" -v f="$n" -v w="$wall" -v u="$user" -v s="$sys" -v m="$rss" \
    -v a="$frame" -v g="$render" \
    'BEGIN { printf "| %d | %s | %d | %.2f | %.3f | %.3f | %.3f | %.2f | %.0f |\n", r, n, f, w, w / f, a, g, u + s, m / 1024 }'
  echo "$name $(awk -v w="$wall" -v f="$n" 'BEGIN { print w / f }') $frame $render" >>"$out/samples.txt"
  rm -rf "$dir" "$dir.time"
}
for ((r = 1; r <= runs; ++r)); do
  run_one "$r" static 1 "${still[@]}"
  run_one "$r" sequence_still "$frames" "${still[@]}"
  run_one "$r" sequence_raws "$frames"
done
median() {  # NAME COLUMN
  awk -v n="$1" -v c="$2" '$1 == n { print $c }' "$out/samples.txt" | sort -g |
    awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'
}
echo
echo "| variant | wall per frame s | vs static | frame s | vs static | render at t_k s | vs static |"
echo "|---|---|---|---|---|---|---|"
for v in static sequence_still sequence_raws; do
  awk -v n="$v" -v w="$(median "$v" 2)" -v a="$(median "$v" 3)" -v g="$(median "$v" 4)" \
    -v bw="$(median static 2)" -v ba="$(median static 3)" -v bg="$(median static 4)" \
    'BEGIN { printf "| %s | %.3f | %.2fx | %.3f | %.2fx | %.3f | %.2fx |\n", n, w, w / bw, a, a / ba, g, g / bg }'
done
