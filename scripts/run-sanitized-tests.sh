#!/usr/bin/env bash
# Builds everything with AddressSanitizer + UndefinedBehaviorSanitizer
# (-DTOFSIM_SANITIZE=ON, Debug with -O1 into build-asan/) and runs the whole
# test suite under them, GL tests on llvmpipe included. Any sanitizer report
# fails the test that triggered it. Leaks inside Mesa/llvmpipe/EGL are
# suppressed in tests/sanitizer/lsan.supp (third-party frames only, each
# explained); everything else is an error.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
source scripts/compiler-cache.sh
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" \
  -DTOFSIM_SANITIZE=ON "${cache_flags[@]}" >/dev/null
cmake --build build-asan -j2
supp="$PWD/tests/sanitizer"
# Mesa dlclose()s its driver (swrast_dri.so: llvmpipe) in eglTerminate, before
# LeakSanitizer runs at exit; whatever the driver still pointed to from its
# globals then looks leaked, with "<unknown module>" frames that no
# suppression can name. Preloading the driver keeps it mapped, so those
# blocks stay reachable and are not reported (tests/sanitizer/lsan.supp).
# verify_asan_link_order=0: the preload comes before libasan in the list.
dri="$(ls /usr/lib/*/dri/swrast_dri.so 2>/dev/null | head -n1 || true)"
if [ -n "$dri" ]; then export LD_PRELOAD="$dri"; fi
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:strict_string_checks=1:verify_asan_link_order=0"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# The release run's long Monte Carlo convergence checks are left out here
# (tests/sanitizer/release-only.txt says why and what covers their code).
skip="$(grep -v '^#' tests/sanitizer/release-only.txt | grep -v '^$' | sed 's/.*/^&$/' | paste -sd'|')"
# Sanitized llvmpipe is several times slower: a longer per-test timeout.
ctest --test-dir build-asan --output-on-failure -j2 --timeout 1800 -E "$skip"
