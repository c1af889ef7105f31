#!/usr/bin/env bash
# A device's effects (issue 24), two builds back to back: the rows of
# bench/README.md's table "A device's effects", each configuration of
# tofsim_spad_throughput (64x64, 1000 bins, 10^5 cycles, one thread) run by
# binary A then binary B, RUNS times (the engine's rows ENGINE_RUNS times:
# ~11 s each), so that the machine's load hits both alike. Prints the
# median CPU seconds (std::clock, the bench's own figure; each call times
# two runs, both counted) of A and B and B's ratio to its own ideal detector.
# Usage: bench/spad_throughput/ab.sh A_BINARY B_BINARY [RUNS=5] [ENGINE_RUNS=2]
set -euo pipefail
a=$1
b=$2
runs=${3:-5}
engineRuns=${4:-2}
samples=$(mktemp)
# mode;effects;engine (as the table names them);runs;the bench's arguments
rows=(
  "synchronous;none (today);auto;$runs;synchronous 0 none auto"
  "synchronous;device + crosstalk;auto (engine: afterpulses);$engineRuns;synchronous 0.05 device auto"
  "synchronous;device + crosstalk;fast;$engineRuns;synchronous 0.05 device fast"
  "free-running;none (today);auto;$runs;free-running 0 none auto"
  "free-running;device + crosstalk;auto (engine);$engineRuns;free-running 0.05 device auto"
  "free-running;device + crosstalk;fast;$runs;free-running 0.05 device fast"
  "free-running;device, no crosstalk;fast;$runs;free-running 0 device fast"
  "free-running;crosstalk only;fast;$runs;free-running 0.05 none fast"
)
echo "load: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) CPUs"
for row in "${rows[@]}"; do
  IFS=';' read -r mode effects engine n args <<<"$row"
  for ((r = 1; r <= n; ++r)); do
    for which in A B; do
      exe=$a
      [ "$which" = B ] && exe=$b
      # shellcheck disable=SC2086
      "$exe" 64 1000 100000 1 $args | awk -F'|' -v k="$mode $effects $engine|$which" '
        /^\| (sync|free)/ { gsub(/ /, "", $5); print k "|" $5 }' >>"$samples"
    done
  done
done
median() { { grep -F "$1|$2|" "$samples" || true; } | cut -d'|' -f3 | sort -g | awk '{ v[NR] = $1 }
  END { print (NR == 0 ? "-" : NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }
echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| mode | effects | engine | A CPU s | B CPU s | B / A | B vs B's today |"
echo "|---|---|---|---|---|---|---|"
for row in "${rows[@]}"; do
  IFS=';' read -r mode effects engine _ _ <<<"$row"
  ma=$(median "$mode $effects $engine" A)
  [ "$ma" = - ] && continue  # not run (RUNS or ENGINE_RUNS 0)
  mb=$(median "$mode $effects $engine" B)
  mt=$(median "$mode none (today) auto" B)
  awk -v m="$mode" -v e="$effects" -v g="$engine" -v a="$ma" -v b="$mb" -v t="$mt" \
    'BEGIN { printf "| %s | %s | %s | %.2f | %.2f | %.2f | %.2fx |\n", m, e, g, a, b, b / a, b / t }'
done
rm -f "$samples"
