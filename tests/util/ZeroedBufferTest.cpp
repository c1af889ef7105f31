// util::ZeroedBuffer: zero and writable from the start, every byte of it,
// moves without copying, and an empty one holds nothing.
#include <gtest/gtest.h>

#include <cstdint>

#include "tofsim/util/ZeroedBuffer.h"

namespace tofsim::util {
namespace {

TEST(ZeroedBufferTest, StartsZeroAndWritableAcrossManyPages) {
  const std::size_t n = (std::size_t{8} << 20) / sizeof(double) + 3;  // 8 MiB and a bit
  ZeroedBuffer<double> b(n);
  ASSERT_EQ(b.size(), n);
  for (std::size_t i = 0; i < n; i += 509) EXPECT_EQ(b[i], 0.0) << i;
  EXPECT_EQ(b[n - 1], 0.0);
  b[0] += 1.5;
  b[n - 1] += 2.5;
  EXPECT_EQ(b[0], 1.5);
  EXPECT_EQ(b[n - 1], 2.5);
}

TEST(ZeroedBufferTest, MovesItsMemory) {
  ZeroedBuffer<float> a(1000);
  a[7] = 3.0f;
  const float* where = a.data();
  ZeroedBuffer<float> b(std::move(a));
  EXPECT_EQ(b.data(), where);
  EXPECT_EQ(b[7], 3.0f);
  ZeroedBuffer<float> c;
  EXPECT_EQ(c.size(), 0u);
  EXPECT_EQ(c.data(), nullptr);
  c = std::move(b);
  EXPECT_EQ(c.size(), 1000u);
  EXPECT_EQ(c[7], 3.0f);
}

}  // namespace
}  // namespace tofsim::util
