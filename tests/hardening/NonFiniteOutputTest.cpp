// NaN and infinity from the renderer (degenerate geometry, overflow) never
// reach the output files: OutputSink writes them as 0 and counts them.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/TempDir.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/OutputSink.h"

namespace tofsim {
namespace {

class NonFiniteOutputTest : public test::TempDirTest {};

TEST_F(NonFiniteOutputTest, NonFiniteValuesAreZeroedAndCounted) {
  config::OutputConfig output;
  output.direct = true;
  output.indirect = true;
  TimeAxis axis;
  axis.bins = 2;
  axis.bin_width_s = 1e-11;
  const int W = 2, H = 1, floats = W * H * 2 * 3;
  std::vector<float> direct(floats, 1.0f), indirect(floats, 0.5f);
  direct[1] = std::numeric_limits<float>::quiet_NaN();
  indirect[4] = std::numeric_limits<float>::infinity();
  direct[7] = std::numeric_limits<float>::max();  // finite, but the sum overflows
  indirect[7] = std::numeric_limits<float>::max();

  pipeline::OutputSink sink(dir_, output, W, H, axis);
  capture::Segment segment;
  segment.pixelCount = 2;
  segment.components = {{capture::kDirect, direct.data()}, {capture::kIndirect, indirect.data()}};
  sink.consume(segment);
  sink.commit();

  EXPECT_EQ(sink.nonFiniteValues(), 3u);
  for (const char* name : {"transient.npy", "direct.npy", "indirect.npy"}) {
    for (float v : io::readNpy(dir_ / name).data) EXPECT_TRUE(std::isfinite(v)) << name;
  }
  const io::NpyArray total = io::readNpy(dir_ / "transient.npy");
  EXPECT_EQ(total.data[1], 0.5f);  // NaN direct dropped, indirect kept
  EXPECT_EQ(total.data[4], 1.0f);  // inf indirect dropped, direct kept
  EXPECT_EQ(total.data[7], 0.0f);  // overflowed sum dropped
  for (float v : sink.steady().data) EXPECT_TRUE(std::isfinite(v));
}

}  // namespace
}  // namespace tofsim
