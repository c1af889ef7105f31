// The batch's order of runs that share a render (SharedRenders.h): a run
// waits while a run of its render key renders, takes the render once that
// one is done, renders itself when it failed; a run done before is a source
// from the start, unless its key shares through the batch's saved volume
// (gone with the batch that saved it); a run that cannot share never waits.

#include "SharedRenders.h"

#include <gtest/gtest.h>

namespace tofsim::pipeline {
namespace {

RunContentKey keyed(const std::string& render) {
  RunContentKey k;
  k.render = render;
  return k;
}

TEST(SharedRendersTest, RunsOfOneKeyWaitForItsRenderAndTakeIt) {
  const std::vector<RunContentKey> keys = {keyed("a"), keyed("a"), keyed("b"), keyed("a")};
  const std::vector<bool> shareable = {true, true, true, false};
  const std::vector<BatchRunResult> runs(4);
  SharedRenders shared(keys, shareable, {false, false, false, false}, runs);
  std::deque<std::size_t> pending = {0, 1, 2, 3};
  auto n = shared.next(pending);  // run 0 renders key a
  ASSERT_TRUE(n);
  EXPECT_EQ(n->run, 0u);
  EXPECT_TRUE(n->renders);
  n = shared.next(pending);  // run 1 waits for it: run 2 renders key b
  EXPECT_EQ(n->run, 2u);
  EXPECT_TRUE(n->renders);
  n = shared.next(pending);  // run 3 cannot share: it renders, waiting for nobody
  EXPECT_EQ(n->run, 3u);
  EXPECT_FALSE(n->renders);
  EXPECT_FALSE(n->source);
  EXPECT_FALSE(shared.next(pending));  // only run 1 is left, and it waits
  shared.ended(0, true, true);
  n = shared.next(pending);
  ASSERT_TRUE(n);
  EXPECT_EQ(n->run, 1u);
  EXPECT_EQ(n->source, 0u);
  EXPECT_FALSE(n->renders);
}

TEST(SharedRendersTest, AFailedRenderLetsTheNextRunRenderAndADoneRunServesAtOnce) {
  const std::vector<RunContentKey> keys = {keyed("a"), keyed("a"), keyed("c"), keyed("c")};
  std::vector<BatchRunResult> runs(4);
  runs[2].status = BatchRunStatus::Skipped;  // done before this batch
  SharedRenders shared(keys, {true, true, true, true}, {false, false, false, false}, runs);
  std::deque<std::size_t> pending = {0, 1, 3};
  auto n = shared.next(pending);
  EXPECT_EQ(n->run, 0u);
  n = shared.next(pending);  // run 3 takes run 2's render; run 1 waits
  EXPECT_EQ(n->run, 3u);
  EXPECT_EQ(n->source, 2u);
  shared.ended(0, true, false);  // run 0 failed
  n = shared.next(pending);
  EXPECT_EQ(n->run, 1u);
  EXPECT_TRUE(n->renders);
  EXPECT_FALSE(n->source);
}

// Runs that save no volume share through the batch's saved one: a run done
// before saved none for this batch, so the first pending run of its key
// renders, as does a run found done by another batch meanwhile.
TEST(SharedRendersTest, ARunDoneBeforeServesNoRunSharingThroughTheBatch) {
  const std::vector<RunContentKey> keys = {keyed("k"), keyed("k"), keyed("k")};
  std::vector<BatchRunResult> runs(3);
  runs[0].status = BatchRunStatus::Skipped;  // done before this batch
  SharedRenders shared(keys, {true, true, true}, {true, true, true}, runs);
  std::deque<std::size_t> pending = {1, 2};
  auto n = shared.next(pending);
  EXPECT_EQ(n->run, 1u);
  EXPECT_TRUE(n->renders);
  EXPECT_FALSE(n->source);
  shared.doneElsewhere(1, true);  // another batch finished it: it saved no volume here
  n = shared.next(pending);
  EXPECT_EQ(n->run, 2u);
  EXPECT_TRUE(n->renders);
  EXPECT_FALSE(n->source);
}

}  // namespace
}  // namespace tofsim::pipeline
