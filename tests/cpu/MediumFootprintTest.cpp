// The pixel footprint at a medium point (issue 40, item 3): a point with no
// surface spreads a pixel's light over the camera ray's cross-section at its
// distance, the plane through it normal to the ray
// (physics::footprintPlaneNormal), not over a tangent plane. With the light
// at the camera the path 2 |x - c| does not change across that plane, so
// every medium point's light stays in its bin; a plane facing the camera's
// axis instead (what a zero normal gave) tilts against the corner pixels'
// rays and spreads their light over many bins.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "support/AnalyticScenes.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::cpu {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(MediumFootprintTest, AMediumPointsFootprintIsTheRaysCrossSection) {
  scene::Scene scene;
  test::addQuad(scene, glm::vec3(0.0f, 0.0f, -50.0f), glm::vec3(0, 0, 1), 1.0f, glm::vec3(0.5f));
  capture::Camera camera;
  camera.position_world = glm::vec3(0.0f);
  camera.look_at_world = glm::vec3(0.0f, 0.0f, -1.0f);
  camera.fov_y_deg = 90.0f;  // wide pixels: the corner rays 55 degrees off the axis
  camera.width = 4;
  camera.height = 4;
  capture::RenderJob job;
  job.scene = &scene;
  job.imager = camera;
  job.light.position_world = camera.position_world;  // co-located: path 2 |x - c|
  job.light.intensity_W_per_sr = glm::vec3(1.0f);
  job.settings.indirect.enabled = false;
  job.settings.pixel_footprint = true;
  job.settings.time = TimeAxis{0.0, 0.002 / kSpeedOfLight_m_per_s, 4000};
  const glm::vec3 albedo(0.8f);
  // One medium point on each pixel's central ray, at distances 1 .. 2.5 m.
  ir::SurfaceImage given;
  given.width = camera.width;
  given.height = camera.height;
  const capture::PrimaryRays rays(job.imager);
  std::vector<double> distance;
  for (int32_t y = 0; y < camera.height; ++y) {
    for (int32_t x = 0; x < camera.width; ++x) {
      const double d = 1.0 + 0.1 * static_cast<double>(y * camera.width + x);
      const capture::PrimaryRay ray = rays.ray(x, y);
      given.firstSample.push_back(given.position.size());
      given.side.push_back(1);
      given.position.emplace_back(ray.origin + static_cast<float>(d) * ray.direction, 1.0f);
      given.normal.emplace_back(0.0f);
      given.vertex.push_back(physics::scatterVertex(physics::VERTEX_MEDIUM, albedo, 0.0f, 1.0f));
      given.geometric.emplace_back(0.0f);
      distance.push_back(d);
    }
  }
  given.firstSample.push_back(given.position.size());
  capture::VolumeCollector volume(camera.width, camera.height, job.settings.time,
                                  capture::kChannels);
  auto backend = std::make_unique<CpuBackend>(CpuBackendOptions{2, true});
  backend->setSurfaces(std::make_unique<ir::SurfaceImage>(given), nullptr);
  ir::IrRenderer(std::move(backend)).render(job, volume);

  const TimeAxis& axis = job.settings.time;
  for (int32_t y = 0; y < camera.height; ++y) {
    for (int32_t x = 0; x < camera.width; ++x) {
      const double d = distance[static_cast<std::size_t>(y * camera.width + x)];
      const int bin = axis.binOf(2.0 * d / kSpeedOfLight_m_per_s);
      // albedo / (4 pi) * I / d^2, all of it within a bin of 2 d.
      const double expected = albedo.r / (4.0 * kPi) / (d * d);
      double near = 0.0, all = 0.0;
      for (int t = 0; t < axis.bins; ++t) {
        all += volume.direct.at(y, x, t, 0);
        if (std::abs(t - bin) <= 1) near += volume.direct.at(y, x, t, 0);
      }
      EXPECT_NEAR(all, expected, 1e-4 * expected) << "pixel " << x << ", " << y;
      EXPECT_NEAR(near, all, 1e-4 * all) << "light spread out of its bin at " << x << ", " << y;
    }
  }
}

}  // namespace
}  // namespace tofsim::cpu
