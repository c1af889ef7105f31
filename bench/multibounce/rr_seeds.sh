#!/usr/bin/env bash
# Russian roulette (render.indirect.russian_roulette) against none on the
# Cornell box demo, CPU backend, 48x48, over seeds 1..8: per seed, bounce 2's
# VPLs and its rendered energy (energy_on_axis of a 2-bounce render minus
# that of a 1-bounce render of the same seed, whose bounce 1 is the same).
# Prints "roulette seed VPLs bounce-2-energy" lines.
# Usage: bench/multibounce/rr_seeds.sh [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:-$(mktemp -d)}
tofsim=./build/apps/cli/tofsim
field() { sed -n "s/.*\"$1\": *\([0-9.eE+-]*\).*/\1/p" "$2" | head -1; }
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
for rr in false true; do
  for seed in 1 2 3 4 5 6 7 8; do
    for n in 1 2; do
      "$tofsim" render configs/cornell_box.yaml -q -o "$out/$rr-$seed-$n" --backend cpu \
        --set output.video=false --set 'sensors=[]' --set 'output.components=[]' \
        --set output.steady=false --set output.depth=false --set camera.resolution=[48,48] \
        --set time.bin_width="30 ps" --set time.bins=1000 --set render.seed=$seed \
        --set render.indirect.bounces=$n --set render.indirect.russian_roulette=$rr
    done
    e1=$(field energy_on_axis "$out/$rr-$seed-1/transient.json")
    e2=$(field energy_on_axis "$out/$rr-$seed-2/transient.json")
    echo "$rr $seed $(field vpls "$out/$rr-$seed-2/transient.json") $(awk -v a="$e2" -v b="$e1" 'BEGIN { print a - b }')"
  done
done
