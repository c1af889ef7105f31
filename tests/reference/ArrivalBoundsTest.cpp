// The arrival bounds of core/capture: closed forms on a plane, and the
// reference path tracer's light (up to three surface vertices) landing inside
// them, with the bounds' own ends reached by sampled paths to within the box.

#include <gtest/gtest.h>

#include <cmath>

#include "reference/RenderReference.h"
#include "tofsim/capture/ArrivalBounds.h"

namespace tofsim {
namespace {

// Plane z = 0 of side 6 m, camera and light at (0, 0, 1.5): the nearest path
// goes to the foot point and back (3 m), the farthest direct one to a corner
// and back (2 x 4.5 m), one bounce corner -> opposite corner (6 sqrt 2 m).
TEST(ArrivalBoundsTest, PlaneClosedForms) {
  test::PlaneJob plane;
  capture::RenderJob& job = plane.job;
  capture::ArrivalBounds b = capture::arrivalBounds(job, 1);
  ASSERT_TRUE(b.any);
  EXPECT_NEAR(b.shortest_m, 3.0, 1e-6);
  EXPECT_NEAR(b.longest_m, 9.0, 1e-6);
  b = capture::arrivalBounds(job, 2);
  EXPECT_NEAR(b.shortest_m, 3.0, 1e-6);
  EXPECT_NEAR(b.longest_m, 9.0 + 6.0 * std::sqrt(2.0), 1e-5);
  EXPECT_NEAR(b.longest_s(), b.longest_m / kSpeedOfLight_m_per_s, 1e-18);

  job.settings.time.camera_unwarp = true;  // the surface -> camera leg is dropped
  b = capture::arrivalBounds(job, 1);
  EXPECT_NEAR(b.shortest_m, 1.5, 1e-6);
  EXPECT_NEAR(b.longest_m, 4.5, 1e-6);

  job.settings.time.camera_unwarp = false;
  job.settings.time.index_of_refraction = 1.5;  // optical path = eta x length
  b = capture::arrivalBounds(job, 1);
  EXPECT_NEAR(b.shortest_m, 4.5, 1e-6);
  EXPECT_NEAR(b.longest_m, 13.5, 1e-6);
}

TEST(ArrivalBoundsTest, EmptySceneHasNoArrivals) {
  scene::Scene empty;
  test::PlaneJob plane;
  plane.job.scene = &empty;
  EXPECT_FALSE(capture::arrivalBounds(plane.job, 2).any);
}

// A light in the field of view, facing the camera, counts as seen: it arrives
// after |l - c| (0 with unwarp), before any surface path.
TEST(ArrivalBoundsTest, LightInViewCounts) {
  test::PlaneJob plane;
  plane.job.light.position_world = {0.1f, 0.05f, 1.0f};
  const capture::ArrivalBounds b = capture::arrivalBounds(plane.job, 1);
  EXPECT_NEAR(b.shortest_m, glm::length(glm::vec3(0.1f, 0.05f, -0.5f)), 1e-6);
}

// Every path the reference traces (camera ray, light, two random bounces)
// lands inside [shortest, longest]: an axis exactly that wide loses nothing.
TEST(ArrivalBoundsTest, ReferenceLightLiesWithinTheBounds) {
  test::CornerJob corner(12);
  for (bool unwarp : {false, true}) {
    capture::RenderJob job = corner.job;
    job.settings.time.camera_unwarp = unwarp;
    const capture::ArrivalBounds b = capture::arrivalBounds(job, 3);
    const double width_s = 0.005 / kSpeedOfLight_m_per_s;
    job.settings.time.start_s = b.shortest_s();
    job.settings.time.bin_width_s = width_s;
    job.settings.time.bins =
        static_cast<int32_t>(std::ceil((b.longest_s() - b.shortest_s()) / width_s)) + 1;
    reference::ReferenceSettings settings;
    settings.pixel_filter = reference::PixelFilter::Point;  // compares pixel centres
    settings.bounces = 3;
    settings.samples_per_pixel = 16;
    capture::RenderResult result;
    const capture::VolumeCollector volume = test::renderReference(job, settings, &result);
    EXPECT_EQ(result.offAxis.total(), 0.0) << "unwarp " << unwarp;
    const TransientVolume total = volume.total();
    double binned = 0.0;
    for (float v : total.values()) binned += v;
    EXPECT_GT(binned, 0.0);
  }
}

}  // namespace
}  // namespace tofsim
