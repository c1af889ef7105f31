#!/usr/bin/env bash
# Multi-bounce IR against the reference path tracer (issue 15), on the
# Cornell box at a small resolution on the CPU backend: for N = 1..4 indirect
# bounces, bench/equal_error's run with `bounces N` (IR with
# render.indirect.bounces N against the reference with N + 1 interactions,
# ground truth 16384 paths/pixel, axis 1.5 .. 6.5 m). Prints each run's
# tables (time, steady and transient relative L1 of every IR setting and of
# the reference per path count, and the reference's time at IR's error), and
# /usr/bin/time -v's wall clock and peak memory of each run.
# Usage: bench/multibounce/error_vs_bounces.sh [resolution, default 24] [bounces..., default 1 2 3 4]
set -euo pipefail
cd "$(dirname "$0")/../.."
resolution=${1:-24}
shift || true
bounces=${*:-1 2 3 4}
bench=./build/bench/tofsim_equal_error
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
for n in $bounces; do
  echo
  echo "## bounces $n: $bench configs/scenes/cornell_box.gltf $resolution cpu point $n"
  timing=$(mktemp)
  /usr/bin/time -v -o "$timing" "$bench" configs/scenes/cornell_box.gltf "$resolution" cpu point "$n"
  grep -E "Elapsed|Maximum resident" "$timing"
  rm -f "$timing"
done
