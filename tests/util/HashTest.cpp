// FNV-1a 64 against its published test vectors.

#include <gtest/gtest.h>

#include "tofsim/util/Hash.h"

namespace tofsim {
namespace {

TEST(HashTest, Fnv1a64KnownVectors) {
  EXPECT_EQ(Fnv1a64().value(), 0xcbf29ce484222325ull);
  Fnv1a64 a;
  a.update("a");
  EXPECT_EQ(a.value(), 0xaf63dc4c8601ec8cull);
  Fnv1a64 foobar;
  foobar.update("foo");
  foobar.update("bar");  // streaming equals one piece
  EXPECT_EQ(foobar.value(), 0x85944171f73967e8ull);
  EXPECT_EQ(hex64(0xaf63dc4c8601ec8cull), "af63dc4c8601ec8c");
}

}  // namespace
}  // namespace tofsim
