#!/usr/bin/env bash
# The CPU gather's per-VPL passes (the terms, the footprint kernels, the ISM
# test, the near field's unclipped patches) must compile to 8-wide AVX2 code:
# when GCC cannot prove the arrays apart (more than ten run-time alias
# checks, or a call into another file after the loop: vplDistances) it
# silently leaves the loop scalar, the output stays the same and
# only the speed drops (vplTerms ran scalar from b100e61 to 9151a0d, the whole
# gather 1.4x slower). This reads the AVX2 clones' disassembly in the built
# library and fails when one holds no packed single-precision ymm arithmetic.
# Usage: vectorised_kernels.sh OBJDUMP LIBRARY
set -euo pipefail
objdump_bin=$1 library=$2
listing=$("$objdump_bin" -d -C --no-show-raw-insn "$library")
status=0
for kernel in 'tofsim::cpu::(anonymous namespace)::vplDistances' 'tofsim::cpu::(anonymous namespace)::vplKernels' \
  'tofsim::cpu::(anonymous namespace)::cullLanes' \
  'tofsim::cpu::(anonymous namespace)::unclippedNearField'; do
  packed=$(awk -v name="<${kernel}(" '
    index($0, name) && /\[clone \.avx2\]>:$/ { inside = 1; next }
    inside && /^$/ { inside = 0 }
    inside && /v(add|sub|mul|div|sqrt)ps[^,]*%ymm/ { n++ }
    END { print n + 0 }' <<<"$listing")
  echo "${kernel} [clone .avx2]: ${packed} packed ymm arithmetic instructions"
  if [[ $packed -lt 8 ]]; then
    echo "  not vectorised: see the -fopt-info-vec-missed output for its loop" >&2
    status=1
  fi
done
exit $status
