// The reference renderer's output depends only on the job and the seed: not
// on the thread count, the segment size or the run.

#include <gtest/gtest.h>

#include <cstring>

#include "RenderReference.h"
#include "support/ClosedForm.h"
#include "tofsim/util/Error.h"

namespace tofsim::reference {
namespace {

using namespace capture;

bool sameBytes(const TransientVolume& a, const TransientVolume& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

ReferenceSettings threeBounces(int32_t threads) {
  ReferenceSettings s;
  s.bounces = 3;
  s.samples_per_pixel = 16;
  s.threads = threads;
  return s;
}

TEST(ReferenceDeterminismTest, SameSeedGivesSameBytesWhateverTheThreadCount) {
  test::CornerJob s(12);
  RenderResult r1, r2, r2again;
  const VolumeCollector one = test::renderReference(s.job, threeBounces(1), &r1);
  const VolumeCollector two = test::renderReference(s.job, threeBounces(2), &r2);
  const VolumeCollector again = test::renderReference(s.job, threeBounces(2), &r2again);
  EXPECT_TRUE(sameBytes(one.direct, two.direct));
  EXPECT_TRUE(sameBytes(one.indirect, two.indirect));
  EXPECT_TRUE(sameBytes(two.indirect, again.indirect));
  EXPECT_EQ(r1.offAxis.before, r2.offAxis.before);
  EXPECT_EQ(r1.offAxis.after, r2.offAxis.after);
}

TEST(ReferenceDeterminismTest, SegmentSizeDoesNotChangeTheBytes) {
  test::CornerJob s(12);
  const VolumeCollector whole = test::renderReference(s.job, threeBounces(2));
  // One row per segment.
  s.job.settings.memory_budget_bytes = 12 * 1000 * 3 * sizeof(float) * 2;
  RenderResult result;
  const VolumeCollector rows = test::renderReference(s.job, threeBounces(2), &result);
  EXPECT_EQ(result.segments, 12u);
  EXPECT_TRUE(sameBytes(whole.direct, rows.direct));
  EXPECT_TRUE(sameBytes(whole.indirect, rows.indirect));
}

TEST(ReferenceDeterminismTest, OtherSeedChangesOnlyTheIndirectPart) {
  // With the point filter the direct term is exact, drawn from no generator
  // (with box, the sub-pixel points are random too).
  test::CornerJob s(12);
  ReferenceSettings settings = threeBounces(2);
  settings.pixel_filter = PixelFilter::Point;
  const VolumeCollector a = test::renderReference(s.job, settings);
  s.job.settings.seed = 2;
  const VolumeCollector b = test::renderReference(s.job, settings);
  EXPECT_TRUE(sameBytes(a.direct, b.direct));
  EXPECT_FALSE(sameBytes(a.indirect, b.indirect));
}

TEST(ReferenceDeterminismTest, IndirectDisabledRendersTheDirectTermOnly) {
  test::CornerJob s(8);
  s.job.settings.indirect.enabled = false;
  const VolumeCollector out = test::renderReference(s.job, threeBounces(2));
  for (float v : out.indirect.values()) ASSERT_EQ(v, 0.0f);
  double direct = 0.0;
  for (float v : out.direct.values()) direct += v;
  EXPECT_GT(direct, 0.0);
}

TEST(ReferenceDeterminismTest, ProgressReportsEverySegment) {
  test::CornerJob s(8);
  s.job.settings.memory_budget_bytes = 8 * 1000 * 3 * sizeof(float) * 2 * 2;  // two rows
  std::vector<std::size_t> done;
  VolumeCollector sink(8, 8, s.job.settings.time, 3);
  ReferenceRenderer(threeBounces(2))
      .render(s.job, sink, [&](std::size_t d, std::size_t total, const std::string&) {
        EXPECT_EQ(total, 4u);
        done.push_back(d);
      });
  EXPECT_EQ(done, (std::vector<std::size_t>{1, 2, 3, 4}));
}

TEST(ReferenceDeterminismTest, InvalidSettingsAreInputErrors) {
  test::CornerJob s(4);
  VolumeCollector sink(4, 4, s.job.settings.time, 3);
  ReferenceSettings bad;
  bad.bounces = 0;
  EXPECT_THROW(ReferenceRenderer(bad).render(s.job, sink), InputError);
  bad = ReferenceSettings{};
  bad.samples_per_pixel = 0;
  EXPECT_THROW(ReferenceRenderer(bad).render(s.job, sink), InputError);
}

}  // namespace
}  // namespace tofsim::reference
