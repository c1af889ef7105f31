#!/usr/bin/env bash
# Runs one libFuzzer target for a given time:
#   bash scripts/fuzz.sh fuzz_config 60
# Targets: fuzz_config fuzz_batch fuzz_gltf fuzz_sequence fuzz_npy fuzz_saved_volume fuzz_irf
# fuzz_rays fuzz_spad_tables fuzz_response_table fuzz_camera_files fuzz_tal_capture fuzz_capture_h5 (fuzz/README.md).
# Builds build-fuzz with clang when needed (-DTOFSIM_FUZZ=ON, Debian's clang
# and libclang-rt: scripts/install-fuzz-deps.sh). Starts from the seeds in
# fuzz/corpus/TARGET and grows a working corpus in build-fuzz/corpus/TARGET;
# a crashing input is saved to build-fuzz/artifacts/ and the script fails.
# Prints "TARGET: N executions in S s" at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
target="${1:?usage: fuzz.sh TARGET SECONDS}"
seconds="${2:?usage: fuzz.sh TARGET SECONDS}"

source scripts/compiler-cache.sh
if [ ! -f build-fuzz/build.ninja ]; then
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DTOFSIM_FUZZ=ON -DTOFSIM_BUILD_TESTS=OFF "${cache_flags[@]}" >/dev/null
fi
cmake --build build-fuzz -j2 --target "$target"

corpus="build-fuzz/corpus/$target"
mkdir -p "$corpus" build-fuzz/artifacts
log="build-fuzz/$target.log"
# An input that makes a loader allocate more than 2 GiB counts as a crash
# (-rss_limit_mb, which also bounds single mallocs): sizes must be checked
# against the file before allocating.
ASAN_OPTIONS="detect_leaks=1" \
UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1" \
  "build-fuzz/fuzz/$target" -max_total_time="$seconds" -rss_limit_mb=2048 -max_len=65536 \
  -timeout=10 -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/"$target"- \
  "$corpus" "fuzz/corpus/$target" >"$log" 2>&1 || {
  tail -n 60 "$log" >&2
  echo "$target: FAILED (input saved under build-fuzz/artifacts/)" >&2
  exit 1
}
runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
echo "$target: ${runs:-?} executions in $seconds s, no crash"
