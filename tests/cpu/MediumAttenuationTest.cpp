// Issue 42, item 2, on the CPU backend: a homogeneous medium filling the
// scene attenuates every leg of transient instant radiosity by
// exp(-sigma_t x) over its geometric length x: light -> surface -> camera
// (direct), light -> camera (the light seen directly), light -> VPL (the RSM
// VPLs' flux), parent -> child (later bounces' VPLs), VPL -> gather point ->
// camera (every indirect gather, with ISMs and exact visibility, the merged
// sub-pixel samples and the footprint deposit). A purely absorbing medium
// scales each time bin by exp(-sigma_a x its path / eta)
// (support/MediumAttenuation.h); camera_unwarp moves the camera leg out of
// the time, not out of the attenuation.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "support/MediumAttenuation.h"
#include "support/MediumPoints.h"
#include "support/TestJobs.h"
#include "tofsim/capture/DirectLightView.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"

namespace tofsim::cpu {
namespace {

using test::kMediumSigmaA;

ir::IrRenderer cpuRenderer(std::unique_ptr<CpuBackend> backend = nullptr) {
  if (!backend) backend = std::make_unique<CpuBackend>(CpuBackendOptions{2, true});
  return ir::IrRenderer(std::move(backend));
}

std::unique_ptr<capture::Renderer> cpuRendererPtr() {
  return std::make_unique<ir::IrRenderer>(std::make_unique<CpuBackend>(CpuBackendOptions{2, true}));
}

TEST(MediumAttenuationTest, AbsorbingMediumScalesEachBinOfDirectAndIndirectLight) {
  test::expectCornerAbsorbedPerBin(cpuRendererPtr);
}

// A grey medium (fog) takes the gather's one-exp-per-lane path.
TEST(MediumAttenuationTest, GreyMediumScalesEachBinOfDirectAndIndirectLight) {
  test::expectCornerAbsorbedPerBin(cpuRendererPtr, 16, glm::vec3(0.5f));
}

TEST(MediumAttenuationTest, MergedSubPixelSamplesAndFootprintsAreAbsorbedByTheirPaths) {
  test::expectSubPixelSamplesAbsorbed(cpuRendererPtr, true);
}

TEST(MediumAttenuationTest, AdaptiveSubPixelSamplesAreAbsorbedByTheirPaths) {
  test::expectSubPixelSamplesAbsorbed(cpuRendererPtr, false, 16, true);
}

TEST(MediumAttenuationTest, CameraUnwarpKeepsTheCameraLegsAttenuation) {
  test::expectUnwarpKeepsAttenuation(cpuRendererPtr);
}

TEST(MediumAttenuationTest, DelayedResponsesKeepTheirAttenuation) {
  // A delay (issue 41) moves light later in time, never its energy: each
  // pixel's light in the medium is the same with the wall delayed (the
  // delayed lanes and response classes of both gathers) as without, whose
  // bins the closed form above holds.
  test::CornerJob s = test::absorbingCornerJob();
  const capture::RenderJob fog = test::withAbsorbingMedium(s.job, kMediumSigmaA);
  physics::ResponseKernel delay;
  delay.model = physics::ResponseModel::Exponential;
  delay.lifetime_s = 5.0 * s.job.settings.time.bin_width_s;
  delay.fraction = 0.7;
  s.scene.materials[1].scatteringDelay = delay;  // the wall
  for (const bool footprint : {false, true}) {
    SCOPED_TRACE(footprint ? "footprints" : "point pixels");
    capture::RenderJob job = fog;
    job.settings.pixel_footprint = footprint;
    const auto delayed = test::renderComponents(*cpuRendererPtr(), job);
    s.scene.materials[1].scatteringDelay.reset();
    const auto undelayed = test::renderComponents(*cpuRendererPtr(), job);
    s.scene.materials[1].scatteringDelay = delay;
    for (const char* part : {"direct", "indirect"}) {
      const std::vector<double> a = test::pixelSums(undelayed.at(part), job.settings.time.bins);
      const std::vector<double> b = test::pixelSums(delayed.at(part), job.settings.time.bins);
      const double brightest = *std::max_element(a.begin(), a.end());
      std::size_t lit = 0;
      for (std::size_t k = 0; k < a.size(); ++k) {
        if (!(a[k] > 1e-4 * brightest)) continue;
        ++lit;
        ASSERT_NEAR(b[k], a[k], 1e-4 * a[k]) << part << ", pixel " << k / 3 << " channel " << k % 3;
      }
      EXPECT_GT(lit, 50u) << part;
    }
  }
}

// The CPU backend with one of its RSM VPLs only: every later bounce's VPL
// descends from it, so the resampling by power picks the same parents with
// and without the medium, and each child's ray is the same.
class OneRsmVplBackend : public CpuBackend {
 public:
  OneRsmVplBackend() : CpuBackend(CpuBackendOptions{2, true}) {}
  std::vector<ir::Vpl> generateVpls(const capture::RenderJob& job) override {
    std::vector<ir::Vpl> all = CpuBackend::generateVpls(job);
    if (all.empty()) return all;
    return {all[all.size() / 3]};
  }
};

TEST(MediumAttenuationTest, SecondBounceIsAttenuatedOverItsWholePath) {
  test::CornerJob s = test::absorbingCornerJob();
  s.job.settings.indirect.bounces = 2;
  s.job.settings.indirect.vpls_per_bounce = 256;
  s.job.settings.indirect.visibility = capture::Visibility::Exact;
  const auto vacuum =
      test::renderComponents(cpuRenderer(std::make_unique<OneRsmVplBackend>()), s.job);
  const auto fog = test::renderComponents(cpuRenderer(std::make_unique<OneRsmVplBackend>()),
                                          test::withAbsorbingMedium(s.job, kMediumSigmaA));
  const TimeAxis& axis = s.job.settings.time;
  EXPECT_GT(test::expectAbsorbedPerBin(vacuum.at("bounce1"), fog.at("bounce1"), axis, kMediumSigmaA,
                                       "bounce1"),
            20u);
  EXPECT_GT(test::expectAbsorbedPerBin(vacuum.at("bounce2"), fog.at("bounce2"), axis, kMediumSigmaA,
                                       "bounce2"),
            100u);
}

TEST(MediumAttenuationTest, LightSeenDirectlyIsAttenuatedOverItsDistance) {
  test::CornerJob s = test::absorbingCornerJob();
  // The light in view, 1.2 m in front of the camera.
  s.job.light.position_world = s.job.camera().position_world + glm::vec3(-0.1f, -0.3f, -1.15f);
  const auto nothingInFront = [](int32_t, int32_t) { return std::optional<glm::vec3>(); };
  const capture::DirectLightView vacuum = capture::directLightView(s.job, nothingInFront);
  const capture::DirectLightView fog =
      capture::directLightView(test::withAbsorbingMedium(s.job, kMediumSigmaA), nothingInFront);
  ASSERT_TRUE(vacuum.visible);
  ASSERT_TRUE(fog.visible);
  EXPECT_EQ(fog.bin, vacuum.bin);
  const float d = glm::length(s.job.light.position_world - s.job.camera().position_world);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(fog.radiance[c], vacuum.radiance[c] * std::exp(-kMediumSigmaA[c] * d),
                1e-5f * vacuum.radiance[c]);
  }
}

TEST(MediumAttenuationTest, MediumPointsDirectLightIsAttenuatedOnBothLegs) {
  test::expectMediumPointsAbsorbed(
      [](const capture::RenderJob& job, const ir::SurfaceImage& given) {
        auto backend = std::make_unique<CpuBackend>(CpuBackendOptions{2, true});
        backend->setSurfaces(std::make_unique<ir::SurfaceImage>(given), nullptr);
        return test::renderComponents(cpuRenderer(std::move(backend)), job);
      });
}

}  // namespace
}  // namespace tofsim::cpu
