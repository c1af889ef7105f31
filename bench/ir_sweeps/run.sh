#!/usr/bin/env bash
# Reproduces the paper's Fig. 4/5 sweeps on the Cornell box and prints the
# table recorded in bench/README.md. Pass --quick for a one-minute version.
set -euo pipefail
cd "$(dirname "$0")/../.."
bash scripts/build.sh >/dev/null
echo "commit: $(git rev-parse --short HEAD)"
./build/bench/tofsim_ir_sweeps configs/scenes/cornell_box.gltf "$@"
