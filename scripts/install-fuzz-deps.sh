#!/usr/bin/env bash
# Installs what scripts/fuzz.sh needs besides scripts/install-deps.sh:
# Debian's clang and its compiler-rt (libFuzzer, ASan, UBSan runtimes).
set -euo pipefail
packages=(clang libclang-rt-dev)
bash "$(dirname "$0")/apt-install.sh" "${packages[@]}"
