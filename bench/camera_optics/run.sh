#!/usr/bin/env bash
# The cost of a real ToF camera's parts (issue 25) against today's ideal
# CW-ToF camera, in one run: configs/cwtof_corner.yaml (64 x 64, 1000 bins,
# 3 frequencies x 4 steps, CPU backend, video off) as it is, then with each
# part alone and all together: raw frames in DN (2 taps, 12-bit ADC, full
# well, gain / offset pattern, dark current), the lens (OpenCV distortion),
# cos^4 vignetting, the lens PSF on the transient (the config writes its
# direct and indirect volumes, so every bin is convolved), the PSF when only
# the CW-ToF sensor needs it (no volume written: the sensor convolves its
# raws), thin-lens defocus (16 aperture points). Each variant RUNS times,
# interleaved, so the machine's load hits them alike. Prints per run the
# render's stats.seconds (transient.json), the process wall and CPU (user +
# sys) seconds and max RSS, then the medians and their ratios to the ideal
# camera. Usage: bench/camera_optics/run.sh [RUNS=3] [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
runs=${1:-3}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
tofsim=./build/apps/cli/tofsim
raws=(--set sensors.0.taps=2 --set sensors.0.adc_bits=12 --set sensors.0.adc_gain=0.05
      --set sensors.0.full_well=200000 --set sensors.0.gain_sigma=0.01
      --set sensors.0.offset_sigma=20 --set sensors.0.dark_current=50)
lens=(--set 'camera.lens={camera_matrix: [80, 0, 31.5, 0, 80, 31.5, 0, 0, 1], distortion: [-0.2, 0.05, 0.001, -0.001, 0]}')
vignetting=(--set camera.vignetting=cos4)
psf=(--set 'camera.psf={core_sigma: 0.5, halo_weight: 0.03, halo_profile: exponential, halo_radius: 8}')
no_volumes=(--set output.transient=false --set 'output.components=[]')
defocus=(--set camera.aperture=0.004 --set camera.focus_distance=2.2 --set camera.aperture_samples=16)
variants=(ideal raws lens vignetting psf_transient psf_raws defocus all)
args_of() {
  case "$1" in
    ideal) ;;
    raws) printf '%s\n' "${raws[@]}" ;;
    lens) printf '%s\n' "${lens[@]}" ;;
    vignetting) printf '%s\n' "${vignetting[@]}" ;;
    psf_transient) printf '%s\n' "${psf[@]}" ;;
    psf_raws) printf '%s\n' "${psf[@]}" "${no_volumes[@]}" ;;
    defocus) printf '%s\n' "${defocus[@]}" ;;
    all) printf '%s\n' "${raws[@]}" "${lens[@]}" "${vignetting[@]}" "${psf[@]}" "${no_volumes[@]}" ;;
  esac
}
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| run | variant | render s (stats.seconds) | process wall s | process CPU s | max RSS MB |"
echo "|---|---|---|---|---|---|"
for ((r = 1; r <= runs; ++r)); do
  for v in "${variants[@]}"; do
    dir="$out/$v.$r"
    mapfile -t extra < <(args_of "$v")
    /usr/bin/time -f "%e %U %S %M" -o "$dir.time" "$tofsim" render configs/cwtof_corner.yaml -q \
      -o "$dir" --backend cpu --set output.video=false "${extra[@]}"
    # No transient.json without output.transient (psf_raws, all): the process's times only.
    seconds=nan
    if [ -f "$dir/transient.json" ]; then
      seconds=$(sed -n 's/.*"seconds": *\([0-9.eE+-]*\).*/\1/p' "$dir/transient.json" | head -1)
    fi
    read -r wall user sys rss <"$dir.time"
    cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')
    printf "| %d | %s | %s | %.2f | %s | %.0f |\n" "$r" "$v" "$seconds" "$wall" "$cpu" "$((rss / 1024))"
    echo "$v $seconds $wall $cpu" >>"$out/samples.txt"
    rm -rf "$dir"
  done
done
median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
echo
echo "| variant | median render s | ratio | median process wall s | ratio | median process CPU s | ratio |"
echo "|---|---|---|---|---|---|---|"
col() { awk -v n="$1" -v c="$2" '$1 == n { print $c }' "$out/samples.txt" | median; }
base_r=$(col ideal 2); base_w=$(col ideal 3); base_c=$(col ideal 4)
for v in "${variants[@]}"; do
  r=$(col "$v" 2); w=$(col "$v" 3); c=$(col "$v" 4)
  awk -v n="$v" -v r="$r" -v w="$w" -v c="$c" -v br="$base_r" -v bw="$base_w" -v bc="$base_c" \
    'BEGIN { printf "| %s | %.3f | %.2fx | %.2f | %.2fx | %.2f | %.2fx |\n", n, r, r / br, w, w / bw, c, c / bc }'
done
