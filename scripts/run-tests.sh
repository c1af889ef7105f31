#!/usr/bin/env bash
# Sets everything up and runs every test (GL tests on Mesa's llvmpipe when no
# GPU is present).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2 --timeout 900
