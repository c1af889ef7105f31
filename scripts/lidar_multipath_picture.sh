#!/usr/bin/env bash
# The README's multipath waveform picture (configs/pictures/
# lidar_street_multipath.png): configs/lidar_street.yaml rendered twice, with
# one-bounce multipath seen by a 20 mrad receiver and without, and two beams
# drawn on a log axis by scripts/plot_lidar_multipath.py (the multipath's
# tail is ~1e-3 of the echo's peak: flat on waveforms.png's linear axis).
# Usage: bash scripts/lidar_multipath_picture.sh [TOFSIM] [OUTDIR]
#   TOFSIM: the tofsim binary (default build/apps/cli/tofsim)
#   OUTDIR: where the renders go (default out/lidar_multipath_picture)
set -euo pipefail
cd "$(dirname "$0")/.."
tofsim=${1:-build/apps/cli/tofsim}
out=${2:-out/lidar_multipath_picture}
"$tofsim" render configs/lidar_street.yaml -o "$out/direct" --quiet
"$tofsim" render configs/lidar_street.yaml -o "$out/multipath" --quiet \
  --set lidar.multipath.bounces=1 --set "lidar.multipath.receiver_fov=20 mrad"
# The beams of waveforms.png: over a post's edge (7.8 m, the asphalt at 8.9
# m) and over the kerb wall's top (8.3 m, 11.5 m).
python3 scripts/plot_lidar_multipath.py "$out/multipath/waveforms.npy" \
  configs/pictures/lidar_street_multipath.png --direct "$out/direct/waveforms.npy" \
  --beam 2 120.6 --beam 3 110.4 --range 0 20
