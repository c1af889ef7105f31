#!/usr/bin/env bash
# Installs those of the Debian packages named that are not installed yet, as
# root or with sudo, non-interactively:
#   bash scripts/apt-install.sh PKG...
# Silent, and without even an apt-get update, when every one is installed
# (the common case: the install-*deps.sh scripts run before every build and
# test run). Shared by scripts/install-deps.sh, install-fuzz-deps.sh and
# install-cluster-deps.sh, which only list their packages.
set -euo pipefail
missing=()
for p in "$@"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "apt-install: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
