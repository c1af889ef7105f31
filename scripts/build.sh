#!/usr/bin/env bash
# Configures and builds tofsim (Release) into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/compiler-cache.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${cache_flags[@]}" "$@" >/dev/null
cmake --build build -j"$(nproc)"
