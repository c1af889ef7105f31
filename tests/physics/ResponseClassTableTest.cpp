// The response classes of a render (ResponseClassTable.h): every multiset of
// base kernels up to the depth, once, and composition as multiset union.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "tofsim/physics/ResponseClassTable.h"

namespace tofsim::physics {
namespace {

std::vector<ResponseKernel> kernels(int count) {
  std::vector<ResponseKernel> k(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) k[static_cast<std::size_t>(i)].lifetime_s = 1e-9 * (i + 1);
  return k;
}

TEST(ResponseClassTableTest, HoldsEveryMultisetUpToTheDepthOnce) {
  // Two kernels, paths of up to 3 delayed vertices: C(2 + 3, 3) = 10 classes.
  const ResponseClassTable t = ResponseClassTable::build(kernels(2), 3);
  ASSERT_EQ(t.classCount(), 10u);
  std::set<std::vector<uint32_t>> seen(t.members.begin(), t.members.end());
  EXPECT_EQ(seen.size(), 10u);
  EXPECT_TRUE(t.members[0].empty());
  for (const auto& m : t.members) EXPECT_TRUE(std::is_sorted(m.begin(), m.end()));
}

TEST(ResponseClassTableTest, ComposesAsMultisetUnion) {
  const ResponseClassTable t = ResponseClassTable::build(kernels(2), 3);
  for (uint32_t c = 0; c < t.classCount(); ++c) {
    EXPECT_EQ(t.then(c, 0), c);  // an instant vertex keeps the class
    for (uint32_t k = 1; k <= 2; ++k) {
      const uint32_t next = t.then(c, k);
      if (t.members[c].size() == 3) {
        EXPECT_EQ(next, ResponseClassTable::kNoClass);
        continue;
      }
      std::vector<uint32_t> expected = t.members[c];
      expected.push_back(k);
      std::sort(expected.begin(), expected.end());
      ASSERT_NE(next, ResponseClassTable::kNoClass);
      EXPECT_EQ(t.members[next], expected);
    }
  }
  // Order along the path does not matter: {1} then 2 is {2} then 1.
  EXPECT_EQ(t.then(t.single(1), 2), t.then(t.single(2), 1));
}

TEST(ResponseClassTableTest, NoKernelsMeansOnlyTheInstantClass) {
  const ResponseClassTable t = ResponseClassTable::build({}, 4);
  EXPECT_EQ(t.classCount(), 1u);
  EXPECT_FALSE(t.delayed());
  EXPECT_EQ(t.then(0, 0), 0u);
}

TEST(ResponseClassTableTest, RefusesTooManyClasses) {
  // 6 kernels at depth 3: C(9, 3) = 84 > 64.
  EXPECT_THROW(ResponseClassTable::build(kernels(6), 3), std::invalid_argument);
  EXPECT_NO_THROW(ResponseClassTable::build(kernels(6), 2));  // C(8, 2) = 28
}

// A light on a delayed surface (an NLOS laser spot on its relay wall, start
// kernel 2): every path holds it. The table is class 0 and {2} + each
// multiset of one vertex fewer (as many as the table one shallower, plus
// {2}); its row 0 is {2}'s, so a vertex lit directly gets {2, k}, an RSM VPL
// on an instant surface {2}, and the rest composes as before.
TEST(ResponseClassTableTest, AStartKernelBeginsEveryPath) {
  const ResponseClassTable t = ResponseClassTable::build(kernels(2), 3, 2);
  ASSERT_EQ(t.classCount(), ResponseClassTable::build(kernels(2), 2).classCount() + 1);
  EXPECT_TRUE(t.members[0].empty());
  EXPECT_EQ(t.members[1], (std::vector<uint32_t>{2}));
  for (uint32_t c = 1; c < t.classCount(); ++c) {
    EXPECT_EQ(std::count(t.members[c].begin(), t.members[c].end(), 2u) >= 1, true);
    EXPECT_LE(t.members[c].size(), 3u);
    EXPECT_EQ(t.then(c, 0), c);
  }
  EXPECT_EQ(t.single(0), 1u);
  EXPECT_EQ(t.members[t.single(1)], (std::vector<uint32_t>{1, 2}));
  EXPECT_EQ(t.members[t.single(2)], (std::vector<uint32_t>{2, 2}));
  EXPECT_EQ(t.members[t.then(t.single(1), 1)], (std::vector<uint32_t>{1, 1, 2}));
  EXPECT_EQ(t.then(t.then(t.single(1), 1), 1), ResponseClassTable::kNoClass);
  // Without a start kernel, the table of before, byte for byte.
  const ResponseClassTable plain = ResponseClassTable::build(kernels(2), 3, 0);
  const ResponseClassTable before = ResponseClassTable::build(kernels(2), 3);
  EXPECT_EQ(plain.members, before.members);
  EXPECT_EQ(plain.compose, before.compose);
}

TEST(ResponseClassTableTest, AStartKernelCountsTowardsTheLimit) {
  // 6 kernels: one vertex fewer at depth 3 is C(8, 2) = 28 (+ class 0 = 29
  // classes); at depth 4, C(9, 3) = 84: over 64.
  EXPECT_EQ(ResponseClassTable::build(kernels(6), 3, 1).classCount(), 29u);
  EXPECT_THROW(ResponseClassTable::build(kernels(6), 4, 1), std::invalid_argument);
  // Exactly 64: 63 multisets of the rest and class 0. 2 kernels, rest depth
  // d: (d + 1)(d + 2) / 2 = 63 has no solution; 1 kernel, rest depth 62:
  // 63 multisets, 64 classes.
  EXPECT_EQ(ResponseClassTable::build(kernels(1), 63, 1).classCount(), 64u);
  EXPECT_THROW(ResponseClassTable::build(kernels(1), 64, 1), std::invalid_argument);
  EXPECT_THROW(ResponseClassTable::build(kernels(2), 3, 3), std::invalid_argument);  // no kernel 3
}

}  // namespace
}  // namespace tofsim::physics
