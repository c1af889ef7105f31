#!/usr/bin/env bash
# The cost of a real ToF camera's parts (issue 25) against today's ideal
# CW-ToF camera, in one run: configs/cwtof_corner.yaml (64 x 64, 1000 bins,
# 3 frequencies x 4 steps, CPU backend, video off), writing no volume (its
# sensor's outputs and the images), then with each part alone and all
# together: raw frames in DN (2 taps, 12-bit ADC, full
# well, gain / offset pattern, dark current), the lens (OpenCV distortion),
# cos^4 vignetting, the lens PSF when only the CW-ToF sensor needs it (the
# sensor convolves its raws), the PSF on every bin of the transient (with
# the config's direct and indirect volumes written, against the ideal
# camera writing them too), thin-lens
# defocus (16 aperture points). Each variant RUNS times,
# interleaved, so the machine's load hits them alike. Prints per run the
# render's stats.seconds (transient.json), the process wall and CPU (user +
# sys) seconds and max RSS, then the medians and their ratios to the ideal
# camera. Usage: bench/camera_optics/run.sh [RUNS=3] [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
source bench/timed_renders.sh
bench_args 3 "$@"
raws=(--set sensors.0.taps=2 --set sensors.0.adc_bits=12 --set sensors.0.adc_gain=0.05
      --set sensors.0.full_well=200000 --set sensors.0.gain_sigma=0.01
      --set sensors.0.offset_sigma=20 --set sensors.0.dark_current=50)
lens=(--set 'camera.lens={camera_matrix: [80, 0, 31.5, 0, 80, 31.5, 0, 0, 1], distortion: [-0.2, 0.05, 0.001, -0.001, 0]}')
vignetting=(--set camera.vignetting=cos4)
psf=(--set 'camera.psf={core_sigma: 0.5, halo_weight: 0.03, halo_profile: exponential, halo_radius: 8}')
no_volumes=(--set output.transient=false --set 'output.components=[]')
defocus=(--set camera.aperture=0.004 --set camera.focus_distance=2.2 --set camera.aperture_samples=16)
variants=(ideal_no_volumes raws lens vignetting psf_raws defocus all ideal psf_transient)
args_of() {
  case "$1" in
    ideal) ;;
    ideal_no_volumes) printf '%s\n' "${no_volumes[@]}" ;;
    raws) printf '%s\n' "${raws[@]}" "${no_volumes[@]}" ;;
    lens) printf '%s\n' "${lens[@]}" "${no_volumes[@]}" ;;
    vignetting) printf '%s\n' "${vignetting[@]}" "${no_volumes[@]}" ;;
    psf_transient) printf '%s\n' "${psf[@]}" ;;
    psf_raws) printf '%s\n' "${psf[@]}" "${no_volumes[@]}" ;;
    defocus) printf '%s\n' "${defocus[@]}" "${no_volumes[@]}" ;;
    all) printf '%s\n' "${raws[@]}" "${lens[@]}" "${vignetting[@]}" "${psf[@]}" "${no_volumes[@]}" ;;
  esac
}
runs_header
for ((r = 1; r <= runs; ++r)); do
  for v in "${variants[@]}"; do
    mapfile -t extra < <(args_of "$v")
    timed_render "$r" "$v" "$out/$v.$r" configs/cwtof_corner.yaml --backend cpu \
      --set output.video=false "${extra[@]}"
  done
done
medians_header
for v in "${variants[@]}"; do
  # Writing the volumes (100 MB here) costs more than most parts and varies
  # with the disk: every part is timed writing none (no transient.json
  # either: render s is nan), against the ideal camera writing none; only the
  # PSF on every bin, which needs a volume written, against the ideal camera
  # writing its volumes.
  case "$v" in ideal | psf_transient) ratio_row "$v" ideal ;; *) ratio_row "$v" ideal_no_volumes ;; esac
done
