#!/usr/bin/env bash
# Issue 44 item 7's sweep: configs/kinect_v2.yaml (512 x 424, 800 bins, the
# kinect-v2 preset, a lens PSF on the CW-ToF raws, no volume saved) with its
# frequencies swept over three runs (the preset's 80/16/120 MHz, 80 MHz
# alone, 16 + 120 MHz), as `tofsim batch --jobs 1 -q` under /usr/bin/time -v
# by each tofsim binary given, one after the other, each into a fresh
# folder. Prints per binary the batch's wall and CPU (user + sys) seconds,
# the largest process's peak memory and how many runs rendered; then
# whether every run's sensors/ are the same bytes across the binaries.
#   bash bench/kinect_sweep/run.sh OLD_TOFSIM NEW_TOFSIM
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
work="$(mktemp -d -p "${TMPDIR:-/tmp}")"
trap 'rm -rf "$work"' EXIT
cat >"$work/batch.yaml" <<YAML
base: $root/configs/kinect_v2.yaml
output: out
sweep:
  product:
    sensors.0.frequencies: [[80 MHz, 16 MHz, 120 MHz], [80 MHz], [16 MHz, 120 MHz]]
YAML
n=0
for bin in "$@"; do
  n=$((n + 1))
  /usr/bin/time -v "$bin" batch "$work/batch.yaml" --jobs 1 -q >"$work/stdout.$n" 2>"$work/time.$n"
  mv "$work/out" "$work/out.$n"
  grep -q "3 done" "$work/stdout.$n" || { cat "$work/stdout.$n" "$work/time.$n"; exit 1; }
  renders=$(grep -l "renderer made" "$work"/out.$n/*/log.txt | wc -l)
  awk -v bin="$bin" -v renders="$renders" '
    /Elapsed \(wall clock\)/ { n = split($NF, t, ":"); wall = (n == 3 ? t[1] * 3600 + t[2] * 60 + t[3] : t[1] * 60 + t[2]) }
    /User time/ { user = $NF } /System time/ { sys = $NF }
    /Maximum resident/ { rss = $NF }
    END { printf "%-40s wall %7.1f s  cpu %7.1f s  max RSS %6.0f MiB  runs rendered %d of 3\n", bin, wall, user + sys, rss / 1024, renders }' "$work/time.$n"
done
for ((k = 2; k <= n; ++k)); do
  for run in "$work"/out.1/run*/; do
    name=$(basename "$run")
    diff -rq "$run/sensors" "$work/out.$k/$name/sensors" >/dev/null &&
      echo "$name: sensors/ the same bytes (binary 1 and $k)" ||
      echo "$name: sensors/ DIFFER (binary 1 and $k)"
  done
done
