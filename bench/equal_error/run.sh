#!/usr/bin/env bash
# IR vs reference at equal error on the Cornell box (bench/README.md).
set -euo pipefail
cd "$(dirname "$0")/../.."
bash scripts/build.sh >/dev/null
echo "commit: $(git rev-parse --short HEAD)"
./build/bench/tofsim_equal_error configs/scenes/cornell_box.gltf "$@"
