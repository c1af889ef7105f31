#!/usr/bin/env bash
# Sets everything up and runs the main job: renders the default config
# (configs/cornell_box.yaml), its sensors and the light-in-flight video
# (out/transient.mp4) into out/. Builds only what that run needs: the CLI and
# the video module it loads (scripts/run-tests.sh builds everything).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
BUILD_TARGETS="tofsim tofsim_video_module" bash scripts/build.sh
./build/apps/cli/tofsim render configs/cornell_box.yaml -o out
