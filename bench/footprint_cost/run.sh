#!/usr/bin/env bash
# The cost of the pixel footprint (issue 14): the Cornell box demo
# (configs/cornell_box.yaml, 128x128, 640 bins, RSM 32^2) on the CPU backend,
# without video and sensors, rendered RUNS times per variant, the variants
# interleaved so that the machine's load hits them alike. Prints per run the
# render's stats.seconds (transient.json), the process's wall and CPU
# (user + sys) seconds and max RSS, then the medians and their ratios to
# pixel_footprint false. Usage: bench/footprint_cost/run.sh [RUNS=5] [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
source bench/timed_renders.sh
bench_args 5 "$@"
fp() { echo "--set render.pixel_footprint=$1 --set render.indirect.vpl_footprint=$2"; }
variants=("fp_true_vpl_true:$(fp true true)" "fp_true_vpl_false:$(fp true false)"
          "fp_false:$(fp false false)")
time_variants fp_false configs/cornell_box.yaml --backend cpu --set output.video=false \
  --set 'sensors=[]'
