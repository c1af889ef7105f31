// render.indirect.rsm_edge_samples on the CPU backend, against closed forms:
// the first bounce's flux on a square plate whose silhouette crosses its RSM
// texels off their centres is the plate's solid angle's (one VPL per texel
// rounds the plate to whole texels; sub-texels to whole sub-texels), and at a
// crease the split texels give the corner's indirect light of a finer RSM.

#include <gtest/gtest.h>

#include <cmath>

#include "support/BackendScene.h"
#include "support/CpuRender.h"
#include "support/TestJobs.h"
#include "tofsim/cpu/CpuBackend.h"

namespace tofsim::cpu {
namespace {

// A 0.6 m square plate (z = 0, albedo 0.5) 1 m below a spot light looking
// straight down at it, the whole plate inside the spot's full-intensity cone.
struct PlateUnderSpot {
  scene::Scene scene = test::makePlane(0.6f, glm::vec3(0.5f));
  capture::RenderJob job;
  PlateUnderSpot() {
    job.scene = &scene;
    job.camera().position_world = {0.0f, 0.2f, 1.5f};
    job.camera().look_at_world = {0.0f, 0.0f, 0.0f};
    job.camera().width = 8;
    job.camera().height = 8;
    job.light.type = capture::Light::Type::Spot;
    job.light.position_world = {0.0f, 0.0f, 1.0f};
    job.light.direction_world = {0.0f, 0.0f, -1.0f};
    job.light.cone_half_angle_deg = 45.0f;  // RSM texels 2 / R wide at unit distance
    job.light.cone_falloff_deg = 1.0f;      // the plate's corners are at 23 degrees
    job.light.intensity_W_per_sr = glm::vec3(1.0f);
    job.settings.indirect.rsm_resolution = 32;  // texels 1/16 m on the plate
  }
};

// Sum of the VPLs' flux (red), W/sr: albedo I Omega / pi for the lit area.
double vplFlux(const capture::RenderJob& job) {
  CpuBackend backend({2, true});
  const test::BackendScene prepared(backend, *job.scene);
  backend.prepareSurfaces(job);
  double sum = 0.0;
  for (const ir::Vpl& v : backend.generateVpls(job)) sum += v.flux.r;
  return sum;
}

TEST(RsmEdgeSamplesTest, APlatesFirstBounceFluxIsItsSolidAngles) {
  PlateUnderSpot s;
  // Omega of a square of half side a at distance d on its axis.
  const double a = 0.3, d = 1.0;
  const double omega = 4.0 * std::asin(a * a / (a * a + d * d));
  const double expected = 0.5 * omega / M_PI;
  // The plate's edge is 4.8 texels from the axis: the texel centres round it
  // to 5 (error ~ +8 %); 4 x 4 sub-texels to 19 of 76 quarters (~ -2 %).
  // Half a (sub-)texel on each edge bounds the rounding: 2 (2/R/N)/(2a) of
  // the area, relative.
  const auto bound = [&](int n) { return 2.0 * (1.0 / 32.0 / n) / (2.0 * a) * 2.0; };
  s.job.settings.indirect.rsm_edge_samples = 1;
  const double one = vplFlux(s.job) / expected - 1.0;
  s.job.settings.indirect.rsm_edge_samples = 4;
  const double four = vplFlux(s.job) / expected - 1.0;
  EXPECT_GT(std::abs(one), bound(4)) << "one VPL per texel: " << one;
  EXPECT_LT(std::abs(four), bound(4)) << "4 x 4 at edges: " << four;
  EXPECT_LT(std::abs(four), 0.4 * std::abs(one));
}

TEST(RsmEdgeSamplesTest, ACornersIndirectLightApproachesAFinerRsms) {
  // The corner lit from the camera: its crease and the quads' silhouettes
  // run through the RSM's texels. Indirect light of every pixel (summed over
  // time), relative L1 to that of an RSM 16 times finer.
  test::CornerJob s(16);
  s.job.settings.pixel_footprint = false;
  s.job.settings.indirect.visibility = capture::Visibility::Exact;
  s.job.settings.indirect.geometry_term_clamp_per_m2 = 0.0;
  const auto indirect = [&](int rsm, int edgeSamples) {
    s.job.settings.indirect.rsm_resolution = rsm;
    s.job.settings.indirect.rsm_edge_samples = edgeSamples;
    const test::CpuRender out = test::renderOnCpu(s.job, {2, true});
    std::vector<double> light(static_cast<std::size_t>(16 * 16), 0.0);
    const TransientVolume& v = out.volume.indirect;
    for (std::size_t i = 0; i < v.size(); ++i) light[i / (v.size() / light.size())] += v.data()[i];
    return light;
  };
  const std::vector<double> truth = indirect(256, 1);
  const auto error = [&](const std::vector<double>& light) {
    double diff = 0.0, sum = 0.0;
    for (std::size_t p = 0; p < truth.size(); ++p) diff += std::abs(light[p] - truth[p]), sum += truth[p];
    return diff / sum;
  };
  const double one = error(indirect(16, 1));
  const double four = error(indirect(16, 4));
  EXPECT_LT(four, 0.7 * one) << "one VPL per texel " << one << ", 4 x 4 at edges " << four;
}

}  // namespace
}  // namespace tofsim::cpu
