#!/usr/bin/env bash
# Installs what the cluster test (tests/cluster/slurm_array_test.sh, ctest
# label `cluster`) and bench/slurm need besides scripts/install-deps.sh:
# Debian's Slurm (slurmctld, slurmd, sbatch, ...) and munge. The test needs
# none of the packages' own services or config: it runs its own daemons, with
# their files in a temporary folder.
set -euo pipefail
packages=(slurm-wlm munge)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "install-cluster-deps: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
