#!/usr/bin/env bash
# Scattering delays (issue 41) on the demo (configs/cornell_box.yaml, cpu
# backend): whole `tofsim render` processes, interleaved RUNS times so that
# the machine's load hits them alike:
#   - before: the BEFORE binary (no delays exist there);
#   - none: the AFTER binary, no material delayed (the same bytes: checked
#     here with cmp);
#   - shared: every material delayed by one kernel (exponential 2.5 ns,
#     fraction 0.6): classes {}, {k}, {k, k};
#   - distinct: each material its own kernel (exponential 1.2 ns and 3.5 ns,
#     Gaussian 50 ps / 20 ps): 10 classes.
# Prints per run the process's wall and CPU seconds and max RSS, then the
# medians and the ratios to `none`.
# Usage: bench/scattering_delay/run.sh BEFORE_TOFSIM AFTER_TOFSIM [RUNS=3] [OUTDIR]
set -euo pipefail
before=$(realpath "$1")
after=$(realpath "$2")
cd "$(dirname "$0")/../.."
source bench/timed_renders.sh
bench_args 3 "${@:3}"
base="configs/cornell_box.yaml --set render.backend=cpu"
delay() {  # delay MATERIAL KEY=VALUE...: --set arguments of one material's delay
  local m=$1
  shift
  for kv in "$@"; do printf -- "--set materials.%s.scattering_delay.%s " "$m" "$kv"; done
}
shared="$(for m in white red green; do delay "$m" model=exponential 'lifetime=2.5ns' fraction=0.6; done)"
distinct="$(delay white model=exponential 'lifetime=1.2ns' fraction=0.6)"
distinct+="$(delay red model=exponential 'lifetime=3.5ns' fraction=0.6)"
distinct+="$(delay green model=gaussian 'mean=50ps' 'sigma=20ps' fraction=1)"
cases=("before:$before:$base" "none:$after:$base" "shared:$after:$base $shared"
       "distinct:$after:$base $distinct")

# Same bytes without delays, once.
"$before" render $base -q -o "$out/bytes-before"
"$after" render $base -q -o "$out/bytes-after"
for f in transient.npy direct.npy indirect.npy; do
  cmp "$out/bytes-before/$f" "$out/bytes-after/$f" && echo "none vs before: $f same bytes"
done
rm -rf "$out/bytes-before" "$out/bytes-after"

runs_header
for ((r = 1; r <= runs; ++r)); do
  for c in "${cases[@]}"; do
    IFS=: read -r name binary args <<<"$c"
    read -r -a argv <<<"$args"
    TOFSIM=$binary timed_render "$r" "$name" "$out/$name.$r" "${argv[@]}"
  done
done
medians_header
for c in "${cases[@]}"; do ratio_row "${c%%:*}" none; done
