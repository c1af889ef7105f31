#!/usr/bin/env bash
# Wall time and peak memory (/usr/bin/time -v) of psf_cwtof.yaml on the CPU
# backend: without a PSF, with it on the CW-ToF raws (the run writes no
# volume), and with it on every bin (the transient path, taken because the
# run writes transient.npy; the row without a PSF that writes it too
# separates the cost of writing). TOFSIM=path/to/tofsim measures another
# build. Writes into a temporary folder and removes it.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
tofsim="${TOFSIM:-$root/build/apps/cli/tofsim}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "commit: $(git -C "$root" rev-parse --short HEAD), binary: $tofsim, $(nproc) cores"
# Without camera.psf: the same config less its psf line, the scene absolute.
sed -e '/^  psf:/d' -e "s|^scene: .*|scene: $root/configs/scenes/cornell_box.gltf|" \
  "$here/psf_cwtof.yaml" >"$out/no_psf.yaml"
row() {
  local name="$1" config="$2"
  shift 2
  /usr/bin/time -v "$tofsim" render "$config" -o "$out/$name" --backend cpu -q "$@" \
    2>"$out/$name.time" >/dev/null || { cat "$out/$name.time"; exit 1; }
  local wall rss
  wall=$(grep "Elapsed (wall" "$out/$name.time" | awk '{print $NF}')
  rss=$(grep "Maximum resident set size" "$out/$name.time" | awk '{print $NF}')
  echo "| $name | $* | $wall | $rss kB |"
  rm -rf "${out:?}/$name"
}
echo "| row | overrides | wall | Maximum resident set size |"
echo "|---|---|---|---|"
row no_psf "$out/no_psf.yaml"
row psf_raws "$here/psf_cwtof.yaml"
row no_psf_transient "$out/no_psf.yaml" --set output.transient=true
row psf_transient "$here/psf_cwtof.yaml" --set output.transient=true
