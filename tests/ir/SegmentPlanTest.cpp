// The segment plan and the shared segment loop: sizes from closed forms, every
// pixel covered once in order, the messages name the key to change.

#include <gtest/gtest.h>

#include <vector>

#include "tofsim/capture/SegmentSink.h"
#include "tofsim/capture/SegmentPlan.h"
#include "tofsim/capture/SegmentStream.h"
#include "tofsim/util/Error.h"

namespace tofsim::capture {
namespace {

constexpr std::size_t kHuge = std::size_t(1) << 40;

TEST(SegmentPlanTest, BudgetDividesIntoWholePixels) {
  // 10 floats per pixel, 2 volumes: 80 bytes + 8 for the off-axis light.
  const SegmentPlan plan = planSegments(1000, {10, 2, 0}, 88 * 64 + 87, kHuge, kHuge);
  EXPECT_EQ(plan.pixelsPerSegment, 64u);
  EXPECT_EQ(plan.segmentCount, 16u);  // ceil(1000 / 64)
  EXPECT_EQ(plan.bytesPerSegment, 64u * 88);
  EXPECT_EQ(plan.segment(15).first, 960u);
  EXPECT_EQ(plan.segment(15).count, 40u);  // the last one is shorter
}

TEST(SegmentPlanTest, FootprintBufferIsCountedInDoubles) {
  // 10 floats per pixel, 2 volumes and one footprint buffer of 10 doubles:
  // 80 + 80 bytes + 8 for the off-axis light.
  const SegmentPlan plan = planSegments(1000, {10, 2, 1}, 168 * 64 + 167, kHuge, kHuge);
  EXPECT_EQ(plan.pixelsPerSegment, 64u);
  EXPECT_EQ(plan.bytesPerSegment, 64u * 168);
  // The largest buffer is the doubles': 400 bytes hold 5 pixels of 80.
  EXPECT_EQ(planSegments(1000, {10, 2, 1}, kHuge, 400, kHuge).pixelsPerSegment, 5u);
}

TEST(SegmentPlanTest, ResponseClassRegionsShareTheFootprintBuffersLimit) {
  // The footprint buffer with 3 more regions (two delayed classes and a
  // scratch): 4 x 80 bytes of doubles per pixel, and 16 bytes of state.
  const PixelBuffers classes{10, 2, 4, 16};
  EXPECT_EQ(classes.bytes(), 80u + 320u + 16u + 8u);
  EXPECT_EQ(planSegments(1000, classes, 424 * 10, kHuge, kHuge).pixelsPerSegment, 10u);
  // One storage block of 3200 bytes holds 10 pixels of all four regions.
  EXPECT_EQ(planSegments(1000, classes, kHuge, 3200, kHuge).pixelsPerSegment, 10u);
  // A pixel whose regions exceed the block is an input error, not an abort.
  EXPECT_THROW(planSegments(1000, classes, kHuge, 319, kHuge), InputError);
}

TEST(SegmentPlanTest, DeviceLimitsCapTheSegment) {
  // One buffer of 400 bytes holds 10 pixels of 40 bytes.
  EXPECT_EQ(planSegments(1000, {10, 2, 0}, kHuge, 400, kHuge).pixelsPerSegment, 10u);
  EXPECT_EQ(planSegments(1000, {10, 2, 0}, kHuge, kHuge, 7).pixelsPerSegment, 7u);
  const SegmentPlan whole = planSegments(1000, {10, 2, 0}, kHuge, kHuge, kHuge);
  EXPECT_EQ(whole.pixelsPerSegment, 1000u);
  EXPECT_EQ(whole.segmentCount, 1u);
}

TEST(SegmentPlanTest, BudgetBelowOnePixelNamesTheKey) {
  try {
    planSegments(1000, {10, 2, 0}, 83, kHuge, kHuge);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("render.memory_budget"), std::string::npos) << e.what();
  }
}

TEST(SegmentPlanTest, FixedSegmentsCoverTheImageOnce) {
  const SegmentPlan plan = fixedSegments(10, 4, 1);
  ASSERT_EQ(plan.segmentCount, 3u);
  std::size_t next = 0;
  for (std::size_t s = 0; s < plan.segmentCount; ++s) {
    EXPECT_EQ(plan.segment(s).first, next);
    next += plan.segment(s).count;
  }
  EXPECT_EQ(next, 10u);
}

// Records what the loop hands on.
struct Recorder : capture::SegmentSink {
  std::vector<std::size_t> firsts;
  std::vector<float> direct, indirect;
  void consume(const capture::Segment& s) override {
    firsts.push_back(s.firstPixel);
    const std::size_t floats = s.pixelCount * 2 * capture::kChannels;
    direct.insert(direct.end(), s.component(capture::kDirect),
                  s.component(capture::kDirect) + floats);
    indirect.insert(indirect.end(), s.component(capture::kIndirect),
                    s.component(capture::kIndirect) + floats);
  }
};

TEST(SegmentStreamTest, SegmentsArriveInOrderWithTheLightSeenStraightAdded) {
  TimeAxis axis;
  axis.bins = 2;
  axis.bin_width_s = 1e-9;
  capture::DirectLightView light;
  light.visible = true;
  light.pixel = 3;
  light.bin = 1;
  light.radiance = glm::vec3(1.0f, 2.0f, 3.0f);
  Recorder a, b;
  capture::TeeSink tee({&a, &b});
  AxisLoss lost;
  const SegmentPlan plan = fixedSegments(5, 2, 1);
  streamSegments(plan, axis, {capture::kDirect, capture::kIndirect}, light, tee, lost,
                 [](const SegmentBuffers& s) {
                   // Buffers arrive zeroed; mark each pixel's first indirect value.
                   for (std::size_t p = 0; p < s.pixels.count; ++p) {
                     EXPECT_EQ(s.components[1][p * 6], 0.0f);
                     s.components[1][p * 6] = static_cast<float>(s.pixels.first + p);
                   }
                 });
  EXPECT_EQ(a.firsts, (std::vector<std::size_t>{0, 2, 4}));
  EXPECT_EQ(b.firsts, a.firsts);  // the tee feeds every consumer
  ASSERT_EQ(a.direct.size(), 5u * 6);
  for (std::size_t p = 0; p < 5; ++p) EXPECT_EQ(a.indirect[p * 6], static_cast<float>(p));
  // Pixel 3, bin 1: offset (3 * 2 + 1) * 3.
  EXPECT_EQ(a.direct[21], 1.0f);
  EXPECT_EQ(a.direct[23], 3.0f);
  EXPECT_EQ(lost.total(), 0.0);
}

}  // namespace
}  // namespace tofsim::capture
