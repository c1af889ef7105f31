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
runs=${1:-5}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
source bench/timed_renders.sh
variants=("fp_true_vpl_true:true:true" "fp_true_vpl_false:true:false" "fp_false:false:false")
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| run | variant | render s (stats.seconds) | process wall s | process CPU s | max RSS MB |"
echo "|---|---|---|---|---|---|"
for ((r = 1; r <= runs; ++r)); do
  for v in "${variants[@]}"; do
    IFS=: read -r name fp vpl <<<"$v"
    timed_render "$r" "$name" "$out/$name.$r" configs/cornell_box.yaml --backend cpu \
      --set output.video=false --set 'sensors=[]' \
      --set render.pixel_footprint=$fp --set render.indirect.vpl_footprint=$vpl
  done
done
echo
echo "| variant | median render s | ratio | median process wall s | ratio | median process CPU s | ratio |"
echo "|---|---|---|---|---|---|---|"
for v in "${variants[@]}"; do ratio_row "${v%%:*}" fp_false; done
