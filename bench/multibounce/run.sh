#!/usr/bin/env bash
# Multi-bounce IR (issue 15) on the Cornell box demo (configs/cornell_box.yaml,
# 128x128, RSM 32^2 = 1024 VPLs per bounce, ISM visibility) on the CPU
# backend, without video, sensors or .npy files, and with a time axis long
# enough for 4 bounces (1.5 .. 7.5 m in 30 ps bins). For 1..4 bounces: the
# render's stats.seconds, its VPLs, and the indirect energy (energy_on_axis
# minus that of a direct-only render, so no volume has to be read).
# Usage: bench/multibounce/run.sh [OUTDIR [--set key=value ...]]
# (the --set overrides go to every render, e.g.
#  --set render.indirect.russian_roulette=true)
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:-$(mktemp -d)}
shift || true
extra=("$@")
mkdir -p "$out"
tofsim=./build/apps/cli/tofsim
field() { sed -n "s/.*\"$1\": *\([0-9.eE+-]*\).*/\1/p" "$2" | head -1; }
render() {  # name, then --set overrides
  local dir="$out/$1"
  shift
  "$tofsim" render configs/cornell_box.yaml -q -o "$dir" --backend cpu \
    --set output.video=false --set 'sensors=[]' --set 'output.components=[]' \
    --set time.bin_width="30 ps" --set time.bins=1000 "$@" ${extra[@]+"${extra[@]}"}
}
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
render direct --set render.indirect.enabled=false
direct=$(field energy_on_axis "$out/direct/transient.json")
echo "| bounces | VPLs | render s (stats.seconds) | indirect energy | vs bounces - 1 | after axis |"
echo "|---|---|---|---|---|---|"
previous=""
for n in 1 2 3 4; do
  render "b$n" --set render.indirect.bounces=$n
  json="$out/b$n/transient.json"
  indirect=$(awk -v a="$(field energy_on_axis "$json")" -v d="$direct" 'BEGIN { printf "%.2f", a - d }')
  ratio=$([ -n "$previous" ] && awk -v a="$indirect" -v b="$previous" 'BEGIN { printf "+%.1f %%", 100 * (a - b) / b }' || echo "-")
  printf "| %d | %s | %.2f | %s | %s | %s |\n" "$n" "$(field vpls "$json")" "$(field seconds "$json")" \
    "$indirect" "$ratio" "$(field fraction_after_axis "$json")"
  previous=$indirect
done
