#!/usr/bin/env bash
# The README's multipath waveform picture (configs/pictures/
# lidar_street_multipath.png): configs/lidar_street.yaml rendered twice, with
# one-bounce multipath seen by a 200 mrad receiver (64 rays: it sees the
# surfaces around the spot, so the light they return arrives after the echo)
# and without, and two beams drawn on a log axis by
# scripts/plot_lidar_multipath.py (the multipath's tail is 1e-2 - 1e-4 of
# the echo's peak: flat on waveforms.png's linear axis).
# Usage: bash scripts/lidar_multipath_picture.sh [TOFSIM] [OUTDIR]
#   TOFSIM: the tofsim binary (default build/apps/cli/tofsim)
#   OUTDIR: where the renders go (default out/lidar_multipath_picture)
set -euo pipefail
cd "$(dirname "$0")/.."
tofsim=${1:-build/apps/cli/tofsim}
out=${2:-out/lidar_multipath_picture}
"$tofsim" render configs/lidar_street.yaml -o "$out/direct" --quiet
"$tofsim" render configs/lidar_street.yaml -o "$out/multipath" --quiet \
  --set lidar.multipath.bounces=1 --set "lidar.multipath.receiver_fov=200 mrad" \
  --set lidar.multipath.receiver_rays=64
# Two beams with the longest tails: ring 1 at 106.8 degrees (a wall at 8.1
# m, its tail the ground and the wall around the spot), ring 0 at 350.4
# degrees (the asphalt at 6.2 m at a grazing angle, its echo several bins).
python3 scripts/plot_lidar_multipath.py "$out/multipath/waveforms.npy" \
  configs/pictures/lidar_street_multipath.png --direct "$out/direct/waveforms.npy" \
  --beam 1 106.8 --beam 0 350.4 --range 5 10
