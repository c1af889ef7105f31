#pragma once
// Runs task(i) for i in [0, tasks) on `threads` threads. Which thread runs a
// task is left to chance (an atomic counter balances the load), so a task
// must own everything it writes: the CPU backend's tasks are fixed tiles of
// pixels, each the only writer of its pixels' bins, and the later bounces'
// tasks fixed runs of rays, each writing its own children's slots, which
// makes the bytes independent of the thread count and of the schedule.
// Header-only: a user links Threads::Threads. The one thread pool of tofsim:
// the CPU backend, the later bounces, the reference and the sensors use it.

#ifdef __linux__
#include <sched.h>
#endif

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace tofsim {

/// A thread count as configs give it: 0 (or less) = every core this process
/// may run on. That is its CPU affinity where the system has one (a Slurm
/// task's --cpus-per-task, taskset, a container's cpuset), not the machine's
/// core count, which std::thread::hardware_concurrency() gives: a task
/// limited to 2 of 64 cores would otherwise start 64 threads on its 2.
inline int resolveThreads(int requested) {
  if (requested > 0) return requested;
#ifdef __linux__
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof(allowed), &allowed) == 0) {
    return std::max(1, CPU_COUNT(&allowed));
  }
#endif
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

template <typename Task>
void parallelFor(std::size_t tasks, int threads, const Task& task) {
  const std::size_t workers = std::min<std::size_t>(std::max(threads, 1), tasks);
  if (workers <= 1) {
    for (std::size_t i = 0; i < tasks; ++i) task(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex errorMutex;
  const auto work = [&] {
    try {
      for (std::size_t i; (i = next.fetch_add(1)) < tasks;) task(i);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(errorMutex);
      if (!error) error = std::current_exception();
      next = tasks;  // the others stop after their current task
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

/// task(begin, end) over [0, count) cut into fixed blocks of `block` items
/// (the last one shorter), on parallelFor: the blocks do not depend on the
/// thread count.
template <typename Task>
void parallelForBlocks(std::size_t count, std::size_t block, int threads, const Task& task) {
  const std::size_t blocks = (count + block - 1) / block;
  parallelFor(blocks, threads,
              [&](std::size_t b) { task(b * block, std::min(count, (b + 1) * block)); });
}

}  // namespace tofsim
