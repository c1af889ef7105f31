#pragma once
// Runs task(begin, end) over [0, count) cut into fixed blocks of pixels, on up
// to `threads` threads (0: every core). The blocks do not depend on the thread
// count, and each pixel draws from its own random stream and writes only its
// own results, so the bytes do not depend on it either.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace tofsim::sensors::detail {

inline constexpr std::size_t kPixelsPerBlock = 64;

inline int resolveThreads(int threads) {
  if (threads > 0) return threads;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

template <typename Task>
void parallelPixels(std::size_t count, int threads, const Task& task) {
  const std::size_t blocks = (count + kPixelsPerBlock - 1) / kPixelsPerBlock;
  const std::size_t workers = std::min<std::size_t>(resolveThreads(threads), blocks);
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex errorMutex;
  const auto work = [&] {
    try {
      for (std::size_t b; (b = next.fetch_add(1)) < blocks;) {
        task(b * kPixelsPerBlock, std::min(count, (b + 1) * kPixelsPerBlock));
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(errorMutex);
      if (!error) error = std::current_exception();
      next = blocks;
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace tofsim::sensors::detail
