// The one thread pool (tofsim/util/ParallelFor.h): every task runs once, the
// blocks do not depend on the thread count, and a worker's exception reaches
// the caller (before this pool, the reference's own threads called
// std::terminate on one).

#include <gtest/gtest.h>

#ifdef __linux__
#include <sched.h>
#endif

#include <atomic>
#include <stdexcept>
#include <vector>

#include "tofsim/util/ParallelFor.h"

namespace tofsim {
namespace {

TEST(ParallelForTest, EveryTaskRunsOnceOnAnyThreadCount) {
  for (int threads : {1, 2, 3, 7}) {
    std::vector<std::atomic<int>> runs(1000);
    parallelFor(runs.size(), threads, [&](std::size_t i) { ++runs[i]; });
    for (const auto& r : runs) ASSERT_EQ(r.load(), 1) << threads << " threads";
  }
}

TEST(ParallelForTest, BlocksAreFixedWhateverTheThreads) {
  for (int threads : {1, 4}) {
    std::vector<std::pair<std::size_t, std::size_t>> blocks(4);
    parallelForBlocks(10, 3, threads, [&](std::size_t begin, std::size_t end) {
      blocks[begin / 3] = {begin, end};
    });
    const std::vector<std::pair<std::size_t, std::size_t>> expected = {
        {0, 3}, {3, 6}, {6, 9}, {9, 10}};
    EXPECT_EQ(blocks, expected) << threads << " threads";
  }
}

TEST(ParallelForTest, AWorkersExceptionReachesTheCaller) {
  std::atomic<int> ran{0};
  EXPECT_THROW(parallelFor(64, 4,
                           [&](std::size_t i) {
                             ++ran;
                             if (i == 5) throw std::runtime_error("task 5");
                           }),
               std::runtime_error);
  EXPECT_GE(ran.load(), 6);
}

TEST(ParallelForTest, ZeroThreadsMeansEveryCore) {
  EXPECT_GE(resolveThreads(0), 1);
  EXPECT_EQ(resolveThreads(3), 3);
}

#ifdef __linux__
TEST(ParallelForTest, ZeroThreadsMeansTheCoresThisProcessMayRunOn) {
  // A Slurm task, taskset or a cpuset limits the process to some cores:
  // "every core" is those, not the machine's (hardware_concurrency).
  cpu_set_t before;
  ASSERT_EQ(sched_getaffinity(0, sizeof(before), &before), 0);
  if (CPU_COUNT(&before) < 2) GTEST_SKIP() << "one core allowed already";
  EXPECT_EQ(resolveThreads(0), CPU_COUNT(&before));
  int first = 0;
  while (!CPU_ISSET(first, &before)) ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof(one), &one), 0);
  const int limited = resolveThreads(0);
  ASSERT_EQ(sched_setaffinity(0, sizeof(before), &before), 0);  // back before checking
  EXPECT_EQ(limited, 1);
}
#endif

}  // namespace
}  // namespace tofsim
