#!/usr/bin/env bash
# Peak resident memory of a sensors-only render at dataset scale (issue 17
# part 3): streaming_sensors.yaml (512x512, 2000 bins, SPAD + streak +
# 3-frequency CW-ToF, no volume written) on the CPU backend, measured with
# /usr/bin/time -v. TOFSIM=path/to/tofsim measures another build (e.g. one
# from before the sensors streamed). Writes into a temporary folder (the
# SPAD's counts alone are 2 GB) and removes it.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
tofsim="${TOFSIM:-$root/build/apps/cli/tofsim}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "commit: $(git -C "$root" rev-parse --short HEAD), binary: $tofsim, $(nproc) cores"
/usr/bin/time -v "$tofsim" render "$here/streaming_sensors.yaml" -o "$out/run" --backend cpu \
  2>"$out/time.txt" >/dev/null || { cat "$out/time.txt"; exit 1; }
grep -E "sensor '|Maximum resident set size|Elapsed \(wall|Percent of CPU" "$out/time.txt"
du -sh "$out/run/sensors" | sed 's/^/sensors on disk: /'
