// NaN and infinity from the renderer (degenerate geometry, overflow) never
// reach the output files: FiniteSegments writes them as 0 and counts them
// before the file sinks and the steady image see them.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/TempDir.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/FiniteSegments.h"
#include "tofsim/pipeline/SteadySink.h"
#include "tofsim/pipeline/VolumeFileSink.h"

namespace tofsim {
namespace {

class NonFiniteOutputTest : public test::TempDirTest {};

TEST_F(NonFiniteOutputTest, NonFiniteValuesAreZeroedAndCounted) {
  TimeAxis axis;
  axis.bins = 2;
  axis.bin_width_s = 1e-11;
  const int W = 2, H = 1, floats = W * H * 2 * 3;
  std::vector<float> direct(floats, 1.0f), indirect(floats, 0.5f);
  direct[1] = std::numeric_limits<float>::quiet_NaN();
  indirect[4] = std::numeric_limits<float>::infinity();
  direct[7] = std::numeric_limits<float>::max();  // finite, but the sum overflows
  indirect[7] = std::numeric_limits<float>::max();

  pipeline::VolumeFileSink total(dir_ / "transient.npy", pipeline::kTotal, W, H, axis);
  pipeline::VolumeFileSink directFile(dir_ / "direct.npy", capture::kDirect, W, H, axis);
  pipeline::VolumeFileSink indirectFile(dir_ / "indirect.npy", capture::kIndirect, W, H, axis);
  pipeline::SteadySink steady(W, H, axis.bins);
  capture::TeeSink tee({&total, &directFile, &indirectFile, &steady});
  pipeline::FiniteSegments sink(tee, axis.bins, {});
  capture::Segment segment;
  segment.pixelCount = 2;
  segment.components = {{capture::kDirect, direct.data()}, {capture::kIndirect, indirect.data()}};
  sink.consume(segment);
  total.commit();
  directFile.commit();
  indirectFile.commit();

  EXPECT_EQ(sink.nonFiniteValues(), 3u);
  for (const char* name : {"transient.npy", "direct.npy", "indirect.npy"}) {
    for (float v : io::readNpy(dir_ / name).data) EXPECT_TRUE(std::isfinite(v)) << name;
  }
  const io::NpyArray totalValues = io::readNpy(dir_ / "transient.npy");
  EXPECT_EQ(totalValues.data[1], 0.5f);  // NaN direct dropped, indirect kept
  EXPECT_EQ(totalValues.data[4], 1.0f);  // inf indirect dropped, direct kept
  EXPECT_EQ(totalValues.data[7], 0.0f);  // overflowed sum dropped
  for (float v : steady.steady().data) EXPECT_TRUE(std::isfinite(v));
}

}  // namespace
}  // namespace tofsim
