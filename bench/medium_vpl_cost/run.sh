#!/usr/bin/env bash
# The cost of the VPLs' light scattered by the medium into the camera rays
# (issue 42, item 4: core/physics/medium_vpl_scattering.md) on
# configs/fog_lidar.yaml (64 x 64, 1100 bins, 136 VPLs), without sensors, on
# BACKEND (cpu or gl), RUNS times per variant, interleaved:
#   fog           the fog as shipped: single scattering, VPLs, the pass
#   fog_albedo0   the same extinction without scattering (medium.albedo 0):
#                 the VPLs' surface gather without the pass (and without
#                 single scattering, which costs ~1 s)
#   fog_no_vpls   render.indirect.enabled false: direct light and single
#                 scattering only
# Prints each run's render seconds (stats.seconds), process wall and CPU
# seconds, max RSS, then the medians and their ratios to fog_albedo0. On a
# loaded machine read the CPU column. Usage:
#   bench/medium_vpl_cost/run.sh [BACKEND=cpu] [RUNS=3] [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
backend=${1:-cpu}
source bench/timed_renders.sh
bench_args 3 "${@:2}"
echo "backend: $backend"
variants=("fog:" "fog_albedo0:--set medium.albedo=0" "fog_no_vpls:--set render.indirect.enabled=false")
time_variants fog_albedo0 configs/fog_lidar.yaml --backend "$backend" --set 'sensors=[]'
