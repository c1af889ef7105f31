#!/usr/bin/env bash
# What render.indirect.rsm_edge_samples buys and costs (issue 27): the Cornell
# box demo scene at 32 x 32 point pixels (pixel_footprint false), exact
# visibility, clamp 0, one bounce, on the CPU backend; IR's indirect light at
# RSM 32^2 .. 256^2 with one VPL per texel (N = 1) and with N x N sub-texels
# at the RSM's edges, against IR at RSM 1024^2 with N = 1 (converged: it is
# within 0.05 % of the reference path tracer at 16384 paths per pixel, the
# tracer's own noise). Per run: VPLs, the indirect light's total and its
# steady relative L1 over the pixels, and the render's seconds
# (stats.seconds).
# Usage: bench/rsm_edges/run.sh [N=4] [OUTDIR]  (PYTHON: a python3 with numpy)
set -euo pipefail
cd "$(dirname "$0")/../.."
n=${1:-4}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
tofsim=./build/apps/cli/tofsim
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
render() {  # render DIR RSM N
  "$tofsim" render configs/cornell_box.yaml --backend cpu -q -o "$1" \
    --set camera.resolution=[32,32] --set time.bin_width="100 ps" --set time.bins=100 \
    --set render.pixel_footprint=false --set render.indirect.visibility=exact \
    --set render.indirect.geometry_clamp=0 --set render.indirect.rsm_resolution="$2" \
    --set render.indirect.rsm_edge_samples="$3" --set output.components=[indirect] \
    --set output.video=false --set output.steady=false --set output.depth=false --set 'sensors=[]'
}
render "$out/truth" 1024 1
echo "| RSM | N | VPLs | indirect total / converged | steady L1 | render s |"
echo "|---|---|---|---|---|---|"
for rsm in 32 64 128 256; do
  for edge in 1 "$n"; do
    dir="$out/rsm$rsm.n$edge"
    render "$dir" "$rsm" "$edge"
    "${PYTHON:-python3}" - "$dir" "$out/truth" "$rsm" "$edge" <<'PY'
import json, sys
import numpy as np
run, truth, rsm, n = sys.argv[1:5]
a = np.load(f"{run}/indirect.npy").astype(np.float64).sum(axis=(2, 3))
t = np.load(f"{truth}/indirect.npy").astype(np.float64).sum(axis=(2, 3))
stats = json.load(open(f"{run}/transient.json"))["stats"]
print(f"| {rsm}^2 | {n} | {stats['vpls']} | {a.sum() / t.sum():.4f} | "
      f"{np.abs(a - t).sum() / t.sum():.2%} | {stats['seconds']:.2f} |")
PY
  done
done
