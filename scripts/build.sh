#!/usr/bin/env bash
# Configures and builds tofsim (Release) into build/: every target (libraries,
# CLI, Python module, tests, benchmarks), or only the targets named in
# BUILD_TARGETS (scripts/run-demo.sh: BUILD_TARGETS="tofsim tofsim_video_module").
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/compiler-cache.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${cache_flags[@]}" "$@" >/dev/null
targets=()
if [ -n "${BUILD_TARGETS:-}" ]; then
  read -r -a names <<<"$BUILD_TARGETS"
  targets=(--target "${names[@]}")
fi
cmake --build build -j"$(nproc)" "${targets[@]}"
