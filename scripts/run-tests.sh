#!/usr/bin/env bash
# Sets everything up and runs every test (GL tests on Mesa's llvmpipe when no
# GPU is present).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# Slurm and munge for the cluster test (tests/cluster, label `cluster`); it
# skips where they cannot be installed.
bash scripts/install-cluster-deps.sh || echo "run-tests: slurm-wlm/munge not installed; the cluster test will skip" >&2
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2 --timeout 900
