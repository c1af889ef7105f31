#!/usr/bin/env bash
# The capture loop (issue 40 item 4, apps/pipeline/src/CaptureLoop.cpp)
# against the loops it replaced: whole `tofsim render` processes of two
# binaries, interleaved RUNS times so that the machine's load hits them
# alike:
#   - nlos: configs/nlos_confocal.yaml at 16 x 16 scan points (256 laser
#     positions in parallel over captures on the CPU backend);
#   - nlos_single: configs/nlos_single.yaml (one capture of 32 x 32 points);
#   - sequence: configs/moving_block.yaml, 4 frames (CW-ToF sensor passes).
# Prints per run the process's wall and CPU seconds and max RSS, then the
# medians and the AFTER / BEFORE ratios.
# Usage: bench/capture_loop/run.sh BEFORE_TOFSIM AFTER_TOFSIM [RUNS=3] [OUTDIR]
set -euo pipefail
before=$(realpath "$1")
after=$(realpath "$2")
cd "$(dirname "$0")/../.."
source bench/timed_renders.sh
bench_args 3 "${@:3}"
cases=("nlos:configs/nlos_confocal.yaml --set nlos.sensor_grid=[16,16]"
       "nlos_single:configs/nlos_single.yaml"
       "sequence:configs/moving_block.yaml --set sequence.count=4")
runs_header
for ((r = 1; r <= runs; ++r)); do
  for c in "${cases[@]}"; do
    name=${c%%:*}
    read -r -a args <<<"${c#*:}"
    for side in before after; do
      TOFSIM=$before
      [[ $side == after ]] && TOFSIM=$after
      TOFSIM=$TOFSIM timed_render "$r" "$name-$side" "$out/$name-$side.$r" "${args[@]}"
    done
  done
done
medians_header
for c in "${cases[@]}"; do
  name=${c%%:*}
  ratio_row "$name-before" "$name-before"
  ratio_row "$name-after" "$name-before"
done
