// Closed form: a plane seen at 10 degrees under a point light at the camera,
// 128 x 128. For pixels wholly on the plane, the first-order footprint kernel
// (path and its derivatives at the pixel centre, radiance at the centre) is
// compared with a fine sub-pixel quadrature of the exact direct term: path
// 2 |x - c| and radiance rho / pi * I * cos / r^2 at each sub-point.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/HistogramMetrics.h"
#include "tofsim/capture/Camera.h"
#include "tofsim/physics/FootprintBuffer.h"

namespace tofsim::physics {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kBinWidth_m = 0.0029979246f;  // 10 ps
constexpr int32_t kBins = 8192;               // 24.6 m of optical path
constexpr double kAlbedo = 0.6, kIntensity = 5.0;

struct GrazingScene {
  capture::Camera camera;
  float tanHalf = 0.0f;
  explicit GrazingScene(float height_m) {
    const double grazing = 10.0 * kPi / 180.0;
    camera.position_world = vec3(0.0f, height_m, 0.0f);
    camera.look_at_world =
        camera.position_world +
        vec3(0.0f, -static_cast<float>(std::sin(grazing)), -static_cast<float>(std::cos(grazing)));
    camera.width = camera.height = 128;
    camera.fov_y_deg = 40.0f;
    tanHalf = std::tan(0.5f * glm::radians(camera.fov_y_deg));
  }
  // Unnormalised ray direction forward + s right + t up through pixel point (px, py).
  glm::dvec3 direction(double px, double py) const {
    const double s = (2.0 * px / camera.width - 1.0) * tanHalf;  // square image
    const double t = (1.0 - 2.0 * py / camera.height) * tanHalf;
    return glm::dvec3(camera.forward()) + s * glm::dvec3(camera.right()) +
           t * glm::dvec3(camera.up());
  }
  // Hit of that ray on the plane y = 0 (metres), or nothing above the horizon.
  bool hit(glm::dvec3 d, glm::dvec3& x) const {
    if (d.y >= 0.0) return false;
    const glm::dvec3 c(camera.position_world);
    x = c + d * (-c.y / d.y);
    return true;
  }
  // rho / pi * I * cos / r^2 with the light at the camera.
  double radiance(const glm::dvec3& x) const {
    const glm::dvec3 toLight = glm::dvec3(camera.position_world) - x;
    const double r = glm::length(toLight);
    return kAlbedo / kPi * kIntensity * (toLight.y / r) / (r * r);
  }
};

// The pixel's histogram from sub x sub sub-points, or empty when a corner misses.
std::vector<double> quadrature(const GrazingScene& scene, int32_t px, int32_t py, int sub) {
  glm::dvec3 x;
  for (int corner = 0; corner < 4; ++corner) {
    if (!scene.hit(scene.direction(px + corner % 2, py + corner / 2), x)) return {};
  }
  std::vector<double> h(kBins, 0.0);
  const glm::dvec3 c(scene.camera.position_world);
  for (int i = 0; i < sub; ++i) {
    for (int j = 0; j < sub; ++j) {
      scene.hit(scene.direction(px + (i + 0.5) / sub, py + (j + 0.5) / sub), x);
      const int64_t b = static_cast<int64_t>(std::floor(2.0 * glm::length(x - c) / kBinWidth_m));
      if (b >= 0 && b < kBins) h[b] += scene.radiance(x) / (static_cast<double>(sub) * sub);
    }
  }
  return h;
}

// The first-order footprint: everything at the pixel centre, through the shared kernel.
std::vector<double> footprint(const GrazingScene& scene, int32_t px, int32_t py) {
  const vec3 c = scene.camera.position_world;
  const vec3 dir = scene.camera.pixelDirection(px, py);
  const vec3 x = c + dir * (-c.y / dir.y);
  const vec3 n(0.0f, 1.0f, 0.0f);
  const float pixelStep = 2.0f * scene.tanHalf / static_cast<float>(scene.camera.height);
  const vec3 forward = scene.camera.forward();
  const vec3 dxdu = surfaceStepAcrossPixel(x - c, forward, scene.camera.right() * pixelStep, n);
  const vec3 dxdv = surfaceStepAcrossPixel(x - c, forward, -scene.camera.up() * pixelStep, n);
  const vec3 gradient = opticalPathGradient(x, c, c, 1.0f, false);
  const float path = 2.0f * glm::length(x - c);
  const vec3 kernel =
      footprintKernel(path, pathStepsAcrossPixel(gradient, dxdu, dxdv), 0.0f, kBinWidth_m);
  std::vector<double> diff(static_cast<std::size_t>(kBins) * 3, 0.0);
  depositFootprint(diff.data(), kBins, kernel, vec3(static_cast<float>(scene.radiance(x))));
  std::vector<float> h3(diff.size(), 0.0f);
  integrateFootprint(diff.data(), kBins, h3.data());
  std::vector<double> h(kBins);
  for (int32_t b = 0; b < kBins; ++b) h[b] = h3[static_cast<std::size_t>(b) * 3];
  return h;
}

// Camera height 0.5 m (the centre pixel 2.9 m away, ~60 bins per pixel) and
// 2 m (11.5 m, ~250 bins, the dotted-floor case).
class GrazingPlaneFootprint : public testing::TestWithParam<float> {};

TEST_P(GrazingPlaneFootprint, FirstOrderTrapezoidMatchesSubPixelQuadrature) {
  const GrazingScene scene(GetParam());
  std::vector<double> l1s, pointL1s, energyErrors;
  double widestBins = 0.0;
  for (int32_t py = 64; py < 128; py += 8) {
    for (int32_t px = 1; px < 128; px += 16) {
      const std::vector<double> truth = quadrature(scene, px, py, 400);
      if (truth.empty()) continue;
      const std::vector<double> kernel = footprint(scene, px, py);
      l1s.push_back(test::normalisedL1(kernel, truth));
      energyErrors.push_back(
          std::abs(test::histogramSum(kernel) / test::histogramSum(truth) - 1.0));
      // Point sampling: everything in the centre's bin.
      std::vector<double> point(kBins, 0.0);
      const vec3 c = scene.camera.position_world;
      const vec3 dir = scene.camera.pixelDirection(px, py);
      const float path = 2.0f * glm::length(dir * (-c.y / dir.y));
      point[static_cast<std::size_t>(std::floor(path / kBinWidth_m))] = 1.0;
      pointL1s.push_back(test::normalisedL1(point, truth));
      int32_t occupied = 0;
      for (double v : truth) occupied += v > 0.0;
      widestBins = std::max(widestBins, static_cast<double>(occupied));
    }
  }
  ASSERT_GE(l1s.size(), 40u);
  const double medianL1 = test::median(l1s);
  const double worstL1 = *std::max_element(l1s.begin(), l1s.end());
  const double worstEnergy = *std::max_element(energyErrors.begin(), energyErrors.end());
  std::printf(
      "%zu pixels, up to %.0f bins wide: median L1 %.4f (max %.4f), point sampling "
      "median L1 %.3f; energy within %.3f%%\n",
      l1s.size(), widestBins, medianL1, worstL1, test::median(pointL1s), 100.0 * worstEnergy);
  EXPECT_LT(medianL1, 0.06);
  EXPECT_LT(worstL1, 0.2);
  EXPECT_LT(worstEnergy, 0.02);
  EXPECT_GT(test::median(pointL1s), 1.5);  // the point-sampled pixel is almost disjoint
}

INSTANTIATE_TEST_SUITE_P(CameraHeights, GrazingPlaneFootprint, testing::Values(0.5f, 2.0f));

}  // namespace
}  // namespace tofsim::physics
