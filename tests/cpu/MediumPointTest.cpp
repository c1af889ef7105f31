// Gather points that are not surfaces (issue 40, item 3): samples handed to
// the CPU backend through the given-samples path (IrBackend::setSurfaces)
// whose vertices are medium points (physics::VERTEX_MEDIUM: no normal, the
// isotropic phase function 1 / (4 pi)). Each receives the light with no
// cosine at the receiver, from whichever side it comes: albedo / (4 pi) *
// I / r^2, in the bin of its path |l - x| + |x - origin|. A surface sample at
// the same place, whose normal faces away from the light, receives nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "support/MediumPoints.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::cpu {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The points and their samples (support/MediumPoints.h), rendered on the CPU.
struct MediumPoints : test::MediumPoints {
  capture::VolumeCollector render(const ir::SurfaceImage& given) const {
    capture::VolumeCollector volume(static_cast<int32_t>(points.size()), 1, job.settings.time,
                                    capture::kChannels);
    auto backend = std::make_unique<CpuBackend>(CpuBackendOptions{2, true});
    backend->setSurfaces(std::make_unique<ir::SurfaceImage>(given), nullptr);
    ir::IrRenderer(std::move(backend)).render(job, volume);
    return volume;
  }
};

TEST(MediumPointTest, AMediumPointReceivesTheLightWithNoCosineFromEverySide) {
  const MediumPoints m;
  const TransientVolume volume =
      m.render(m.samples(physics::VERTEX_MEDIUM, glm::vec3(0.0f))).total();
  const TimeAxis& axis = m.job.settings.time;
  for (std::size_t p = 0; p < m.points.size(); ++p) {
    const auto x = static_cast<int32_t>(p);
    const glm::vec3 at = m.points[p];
    const double r = glm::length(m.job.light.position_world - at);
    const int bin = axis.binOf((r + glm::length(m.origin - at)) / kSpeedOfLight_m_per_s);
    for (int c = 0; c < 3; ++c) {
      const double expected =
          m.albedo[c] / (4.0 * kPi) * m.job.light.intensity_W_per_sr[c] / (r * r);
      double near = 0.0, all = 0.0;
      for (int t = 0; t < axis.bins; ++t) {
        all += volume.at(0, x, t, c);
        if (std::abs(t - bin) <= 1) near += volume.at(0, x, t, c);
      }
      EXPECT_NEAR(near, expected, 1e-5 * expected) << "point " << p << ", channel " << c;
      EXPECT_NEAR(all, near, 1e-12) << "light outside its bin at point " << p;
    }
  }
}

TEST(MediumPointTest, ASurfaceSampleThereTakesTheCosineAndNothingFromBehind) {
  const MediumPoints m;
  // Lambertian samples facing +z: the light (at z = 1) is above point 0
  // (cosine 1), level with point 1 (0) and below point 2 (behind it).
  const TransientVolume volume =
      m.render(m.samples(physics::VERTEX_LAMBERTIAN, glm::vec3(0, 0, 1))).total();
  const TimeAxis& axis = m.job.settings.time;
  double sums[3] = {0.0, 0.0, 0.0};
  for (int x = 0; x < 3; ++x) {
    for (int t = 0; t < axis.bins; ++t) sums[x] += volume.at(0, x, t, 0);
  }
  EXPECT_NEAR(sums[0], m.albedo[0] / kPi * m.job.light.intensity_W_per_sr[0], 1e-5);
  EXPECT_EQ(sums[1], 0.0);
  EXPECT_EQ(sums[2], 0.0);
}

}  // namespace
}  // namespace tofsim::cpu
