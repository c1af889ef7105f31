#!/usr/bin/env bash
# Installs what the cluster test (tests/cluster/slurm_array_test.sh, ctest
# label `cluster`) and bench/slurm need besides scripts/install-deps.sh:
# Debian's Slurm (slurmctld, slurmd, sbatch, ...) and munge. The test needs
# none of the packages' own services or config: it runs its own daemons, with
# their files in a temporary folder.
set -euo pipefail
packages=(slurm-wlm munge)
bash "$(dirname "$0")/apt-install.sh" "${packages[@]}"
