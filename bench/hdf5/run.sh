#!/usr/bin/env bash
# npy against hdf5 (issue 28, part 2): bytes and seconds of writing the same
# arrays as .npy files or as one compressed capture.h5.
#  - the demo (configs/cornell_box.yaml: 128x128, 640 bins, direct and
#    indirect components; CPU backend, no video, no sensors) with
#    output.format npy and hdf5: the bytes of the volume files (transient,
#    direct, indirect .npy against capture.h5, which also holds depth and
#    steady), the run's wall and CPU (user + system) seconds and its "other"
#    pass (transient.json pass_seconds.other: everything but the gathers, so
#    the files' writing); on a shared machine the CPU seconds are the steadier
#    figure;
#  - the 64x64 confocal NLOS capture (configs/nlos_confocal.yaml, 512 bins,
#    no sensor), which writes y-tal's layout whatever output.format says:
#    H.npy alone (nlos.hdf5: false) against H.npy + capture.hdf5 (shuffle +
#    gzip), the bytes of each and the wall seconds.
# Then, where Debian's python3-h5py is installed, h5py's time to read one
# pixel's histogram, one time slice and the whole transient from capture.h5.
# Each row is the median of RUNS runs. Usage: bench/hdf5/run.sh [RUNS=3] [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
runs=${1:-3}
out=${2:-$(mktemp -d)}
tofsim=${TOFSIM:-./build/apps/cli/tofsim}
mkdir -p "$out"
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"

# median of the numbers on stdin
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

echo
echo "| demo, output.format | volume bytes | folder bytes | wall s | CPU s | other s |"
echo "|---|---|---|---|---|---|"
for format in npy hdf5; do
  : >"$out/demo.$format.rows"
  for ((r = 1; r <= runs; ++r)); do
    dir="$out/demo.$format.$r"
    /usr/bin/time -f "%e %U %S" -o "$dir.time" "$tofsim" render configs/cornell_box.yaml --backend cpu \
      --set output.video=false --set 'sensors=[]' --set output.format=$format -q -o "$dir"
    if [[ $format == npy ]]; then
      volume=$(cat "$dir"/{transient,direct,indirect}.npy | wc -c)
    else
      volume=$(wc -c <"$dir/capture.h5")
    fi
    other=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["stats"]["pass_seconds"]["other"])' "$dir/transient.json")
    if [[ $format == hdf5 && $r == 1 ]] && /usr/bin/python3 -c 'import h5py' 2>/dev/null; then
      /usr/bin/python3 - "$dir/capture.h5" >"$out/reads" <<'PY'
import sys, time
import h5py
def ms(read):
    with h5py.File(sys.argv[1], "r") as f:
        start = time.perf_counter()
        read(f["transient"])
        return (time.perf_counter() - start) * 1e3
print(f"| {ms(lambda d: d[64, 64]):.1f} | {ms(lambda d: d[:, :, 320]):.0f} | {ms(lambda d: d[...]):.0f} |")
PY
    fi
    read -r wall user sys <"$dir.time"
    cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN {print u + s}')
    echo "$volume $(du -sb "$dir" | cut -f1) $wall $other $cpu" >>"$out/demo.$format.rows"
    rm -rf "$dir" "$dir.time"
  done
  volume=$(cut -d' ' -f1 "$out/demo.$format.rows" | median)
  folder=$(cut -d' ' -f2 "$out/demo.$format.rows" | median)
  wall=$(cut -d' ' -f3 "$out/demo.$format.rows" | median)
  other=$(cut -d' ' -f4 "$out/demo.$format.rows" | median)
  cpu=$(cut -d' ' -f5 "$out/demo.$format.rows" | median)
  echo "| $format | $volume | $folder | $wall | $cpu | $(printf %.3f "$other") |"
done

if [[ -s $out/reads ]]; then
  echo
  echo "h5py reading the hdf5 demo's transient (first run): ms for one pixel's histogram,"
  echo "one time slice (bin 320), the whole volume"
  echo
  echo "| pixel (64, 64) ms | time slice ms | whole ms |"
  echo "|---|---|---|"
  cat "$out/reads"
fi

echo
echo "| NLOS 64x64 confocal | H.npy bytes | capture.hdf5 bytes | wall s | CPU s |"
echo "|---|---|---|---|---|"
for hdf5 in false true; do
  : >"$out/nlos.$hdf5.rows"
  for ((r = 1; r <= runs; ++r)); do
    dir="$out/nlos.$hdf5.$r"
    /usr/bin/time -f "%e %U %S" -o "$dir.time" "$tofsim" render configs/nlos_confocal.yaml \
      --set 'sensors=[]' --set nlos.hdf5=$hdf5 --set output.format=hdf5 -q -o "$dir"
    h5=0
    [[ -f $dir/capture.hdf5 ]] && h5=$(wc -c <"$dir/capture.hdf5")
    read -r wall user sys <"$dir.time"
    echo "$(wc -c <"$dir/H.npy") $h5 $wall $(awk -v u="$user" -v s="$sys" 'BEGIN {print u + s}')" >>"$out/nlos.$hdf5.rows"
    rm -rf "$dir" "$dir.time"
  done
  echo "| nlos.hdf5: $hdf5 | $(cut -d' ' -f1 "$out/nlos.$hdf5.rows" | median) |" \
    "$(cut -d' ' -f2 "$out/nlos.$hdf5.rows" | median) | $(cut -d' ' -f3 "$out/nlos.$hdf5.rows" | median) |" \
    "$(cut -d' ' -f4 "$out/nlos.$hdf5.rows" | median) |"
done
