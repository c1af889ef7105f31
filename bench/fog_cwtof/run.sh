#!/usr/bin/env bash
# CW-ToF in fog by bounce order (issue 42, item 6): configs/fog_cwtof.yaml
# (the corner through fog, 3 frequencies, multipath_by_order) at several
# visibilities, each rendered twice: in the fog (its direct light = the
# walls' direct return + the fog's single scattering) and with the same
# extinction all absorbed (sigma_a = 3.912 / V, sigma_s = 0: the same
# attenuation on every leg, no light scattered by the fog, so its order 0 is
# the walls' direct return alone). IR's bounces are the walls' (attenuated);
# multiple scattering in the fog is not rendered by IR yet. Per visibility:
# the noise-free depth error against the true depth
# (sensors/cwtof/cwtof_multipath_error_by_order.npy, median and percentiles
# over the pixels) of the surface's direct light, + the fog's single
# scattering, + bounce 1, + bounce 2; and the light's share: the fog's
# single scattering in the direct volume.
# FREQUENCIES: the sensor's (default one, 20 MHz: 7.5 m unambiguous, so the
# error is the phasors' pull alone; the config's three unwrap, and a strong
# pull makes them pick a wrong wrap count: bench/README.md).
# Usage: bench/fog_cwtof/run.sh [OUTDIR] [VISIBILITIES (m)="100 50 20 10"]
#        [FREQUENCIES='["20 MHz"]']
#        (PYTHON: a python3 with numpy, /usr/bin/python3 unless set)
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:-$(mktemp -d)}
visibilities=${2:-"100 50 20 10"}
frequencies=${3:-'["20 MHz"]'}
py=${PYTHON:-/usr/bin/python3}
tofsim=${TOFSIM:-./build/apps/cli/tofsim}
mkdir -p "$out"
echo "commit: $(git rev-parse --short HEAD), load: $(cut -d' ' -f1-3 /proc/loadavg), frequencies: $frequencies"
render() {  # NAME MEDIUM
  "$tofsim" render configs/fog_cwtof.yaml --backend cpu --set "$2" --set "sensors.0.frequencies=$frequencies" \
    --set 'output.components=[direct, bounce1, bounce2]' -q -o "$out/$1" >/dev/null 2>&1
}
render vacuum 'medium={}'
for v in $visibilities; do
  st=$(awk -v v="$v" 'BEGIN { printf "%.6g", 3.912 / v }')
  render "fog$v" "medium={visibility: $v m}"
  render "absorbing$v" "medium={sigma_a: $st, sigma_s: 0}"
done
"$py" - "$out" $visibilities <<'PY'
import sys
import numpy as np
out, vis = sys.argv[1], sys.argv[2:]
def orders(run):
    return np.load(f"{out}/{run}/sensors/cwtof/cwtof_multipath_error_by_order.npy")
def cell(e):
    e = e[np.isfinite(e)]
    p1, p50, p99 = np.percentile(e, [1, 50, 99])
    return f"{p50:+.3f} ({p1:+.3f} .. {p99:+.3f})"
def fog_share(run, surface_run):
    d = np.load(f"{out}/{run}/direct.npy").sum()
    s = np.load(f"{out}/{surface_run}/direct.npy").sum()
    return (d - s) / d
print("median depth error over the pixels, m (1st .. 99th percentile)\n")
print("| visibility | sigma_t /m | fog's share of the direct light | surface direct | + single scattering | + bounce 1 | + bounce 2 | surface direct + bounces 1, 2 (no fog light) |")
print("|---|---|---|---|---|---|---|---|")
v = orders("vacuum")
print(f"| vacuum | 0 | 0 | {cell(v[0])} | - | {cell(v[1])} | {cell(v[2])} | {cell(v[2])} |")
for V in vis:
    f, a = orders(f"fog{V}"), orders(f"absorbing{V}")
    print(f"| {V} m | {3.912 / float(V):.3f} | {fog_share(f'fog{V}', f'absorbing{V}'):.3f} | {cell(a[0])} | "
          f"{cell(f[0])} | {cell(f[1])} | {cell(f[2])} | {cell(a[2])} |")
PY
