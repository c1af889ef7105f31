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
tofsim=./build/apps/cli/tofsim
variants=("fp_true_vpl_true:true:true" "fp_true_vpl_false:true:false" "fp_false:false:false")
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| run | variant | render s (stats.seconds) | process wall s | process CPU s | max RSS MB |"
echo "|---|---|---|---|---|---|"
for ((r = 1; r <= runs; ++r)); do
  for v in "${variants[@]}"; do
    IFS=: read -r name fp vpl <<<"$v"
    dir="$out/$name.$r"
    /usr/bin/time -f "%e %U %S %M" -o "$dir.time" "$tofsim" render configs/cornell_box.yaml -q -o "$dir" \
      --backend cpu --set output.video=false --set 'sensors=[]' \
      --set render.pixel_footprint=$fp --set render.indirect.vpl_footprint=$vpl
    seconds=$(sed -n 's/.*"seconds": *\([0-9.eE+-]*\).*/\1/p' "$dir/transient.json" | head -1)
    read -r wall user sys rss <"$dir.time"
    cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')
    printf "| %d | %s | %.3f | %.2f | %s | %.0f |\n" "$r" "$name" "$seconds" "$wall" "$cpu" "$((rss / 1024))"
    echo "$name $seconds $wall $cpu" >>"$out/samples.txt"
    rm -rf "$dir"
  done
done
median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
echo
echo "| variant | median render s | ratio | median process wall s | ratio | median process CPU s | ratio |"
echo "|---|---|---|---|---|---|---|"
col() { awk -v n="$1" -v c="$2" '$1 == n { print $c }' "$out/samples.txt" | median; }
base_r=$(col fp_false 2); base_w=$(col fp_false 3); base_c=$(col fp_false 4)
for v in "${variants[@]}"; do
  name=${v%%:*}
  r=$(col "$name" 2); w=$(col "$name" 3); c=$(col "$name" 4)
  awk -v n="$name" -v r="$r" -v w="$w" -v c="$c" -v br="$base_r" -v bw="$base_w" -v bc="$base_c" \
    'BEGIN { printf "| %s | %.3f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", n, r, r / br, w, w / bw, c, c / bc }'
done
