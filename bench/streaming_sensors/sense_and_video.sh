#!/usr/bin/env bash
# Peak resident memory of the two paths that held a whole volume before
# issue 17's last part: `tofsim sense` on a saved volume (a synthetic
# 256x256x1000x3 transient.npy, 750 MiB, one Gaussian return per pixel,
# written here with the Python standard library) with the Cornell box's
# SPAD, streak and CW-ToF sensors, at the default render.memory_budget
# (512 MiB of runs) and at 64 MiB; and a render with the video (192x192x1000,
# a 422 MiB volume, nothing else written, 64 MiB budget, CPU backend).
# /usr/bin/time -v; TOFSIM=path/to/tofsim measures another build.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
tofsim="${TOFSIM:-$root/build/apps/cli/tofsim}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "commit: $(git -C "$root" rev-parse --short HEAD), binary: $tofsim, $(nproc) cores"
mkdir -p "$out/vol"
python3 - "$out/vol" <<'PY'
import array, json, math, struct, sys
H = W = 256; T = 1000
pulses = {}
def pulse(p):
    if p not in pulses:
        a = array.array('f', [0.0] * (T * 3))
        for t in range(max(0, p - 15), min(T, p + 16)):
            a[3 * t] = a[3 * t + 1] = a[3 * t + 2] = 0.02 * math.exp(-0.5 * ((t - p) / 3.0) ** 2)
        pulses[p] = a.tobytes()
    return pulses[p]
header = "{'descr': '<f4', 'fortran_order': False, 'shape': (%d, %d, %d, 3), }" % (H, W, T)
header += ' ' * ((64 - (11 + len(header)) % 64) % 64) + '\n'
with open(sys.argv[1] + '/transient.npy', 'wb') as f:
    f.write(b'\x93NUMPY\x01\x00' + struct.pack('<H', len(header)) + header.encode())
    for y in range(H):
        for x in range(W):
            f.write(pulse(200 + (x * 2 + y) % 500))
json.dump({"time": {"start_s": 5e-9, "bin_width_s": 1e-11, "bins": T},
           "channels": ["R", "G", "B"]}, open(sys.argv[1] + '/transient.json', 'w'))
PY
measure() {  # label, then the tofsim arguments
  local label="$1"; shift
  /usr/bin/time -v "$tofsim" "$@" -q 2>"$out/time.txt" >/dev/null || { cat "$out/time.txt"; exit 1; }
  echo "$label: $(grep -E 'Maximum resident set size' "$out/time.txt" | sed 's/^\s*//')," \
    "$(grep -E 'Elapsed \(wall' "$out/time.txt" | sed 's/.*: //') wall"
}
measure "sense, default budget" sense "$root/configs/cornell_box.yaml" --volume "$out/vol" -o "$out/s1"
measure "sense, 64 MiB budget" sense "$root/configs/cornell_box.yaml" --volume "$out/vol" \
  -o "$out/s2" --set render.memory_budget=64MiB
cmp -s "$out/s1/sensors/spad/spad_counts.npy" "$out/s2/sensors/spad/spad_counts.npy" &&
  echo "sensor files the same at both budgets: $(diff -r -q "$out/s1/sensors" "$out/s2/sensors" >/dev/null && echo yes || echo NO)"
rm -rf "$out/vol" "$out/s1" "$out/s2"
measure "render with video" render "$root/configs/cornell_box.yaml" -o "$out/v" --backend cpu \
  --set camera.resolution=[192,192] --set time.bins=1000 --set sensors=[] \
  --set render.shadow_map_resolution=256 --set render.indirect.rsm_resolution=8 \
  --set render.indirect.points_per_vpl=200 --set output.transient=false \
  --set output.components=[] --set output.video=true --set output.frame_pngs=false \
  --set render.memory_budget=64MiB
md5sum "$out/v/transient.mp4" | sed 's/ .*/ transient.mp4 md5/'
