#!/usr/bin/env bash
# Sets everything up and runs the main job: renders the default config
# (configs/cornell_box.yaml), its sensors and the light-in-flight video
# (out/transient.mp4) into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/apps/cli/tofsim render configs/cornell_box.yaml -o out
