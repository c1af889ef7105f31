#!/usr/bin/env bash
# tofsim's IR against mitransient (through y-tal's `tal render`) on one NLOS
# capture at equal error, on this machine, in one run (bench/nlos/README.md):
#   bash bench/nlos/run.sh [TAL_VENV]     # needs a venv with y-tal and mitransient
# Truth: quadrature_truth.py (the third bounce by 1 mm quadrature). Prints
# each renderer's whole-process seconds and its error, and writes
# bench/nlos/results.txt.
set -euo pipefail
cd "$(dirname "$0")/../.."
venv="${1:-/tmp/talvenv}"
export DRJIT_LIBLLVM_PATH="${DRJIT_LIBLLVM_PATH:-/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
seconds() { /usr/bin/time -f "%e" "$@" 2>&1 >/dev/null | tail -1; }
/usr/bin/python3 bench/nlos/quadrature_truth.py "$work/truth.npy" 0.001 >/dev/null
results=()
for rsm in 64 128 256 512; do
  s=$(seconds build/apps/cli/tofsim render configs/nlos_single.yaml -q -o "$work/ir$rsm" \
        --set nlos.laser_falloff=projector --set render.indirect.rsm_resolution=$rsm \
        --set nlos.hdf5=false)
  results+=("tofsim_ir_rsm$rsm($s s)=$work/ir$rsm/H.npy")
done
for spp in 250 1000 4000 16000 64000; do
  mkdir -p "$work/tal$spp"
  sed "s/^sample_count: .*/sample_count: $spp/" bench/nlos/tal_single.yaml >"$work/tal$spp/tal.yaml"
  s=$( cd "$work/tal$spp" && seconds "$venv/bin/tal" render tal.yaml -t 2 --no-steady \
         --no-ground-truth --no-partial-results </dev/null )
  results+=("mitransient_spp$spp($s s)=$(find "$work/tal$spp" -name '*.hdf5' | head -1)")
done
PYTHONPATH= "$venv/bin/python" bench/nlos/compare.py "$work/truth.npy" "${results[@]}" |
  tee bench/nlos/results.txt
