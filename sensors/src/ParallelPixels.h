#pragma once
// Runs task(begin, end) over [0, count) cut into fixed blocks of pixels, on up
// to `threads` threads (0: every core), on the shared pool
// (tofsim/util/ParallelFor.h). The blocks do not depend on the thread count,
// and each pixel draws from its own random stream and writes only its own
// results, so the bytes do not depend on it either.

#include <cstddef>

#include "tofsim/util/ParallelFor.h"

namespace tofsim::sensors::detail {

inline constexpr std::size_t kPixelsPerBlock = 64;

template <typename Task>
void parallelPixels(std::size_t count, int threads, const Task& task) {
  parallelForBlocks(count, kPixelsPerBlock, resolveThreads(threads), task);
}

}  // namespace tofsim::sensors::detail
