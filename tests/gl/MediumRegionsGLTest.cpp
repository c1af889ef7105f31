// Issue 42's per-region media (`media:`) on the GL backend: the cube
// region's closed forms that tests/cpu/MediumRegionsTest.cpp checks on the
// CPU backend (support/RegionTank.h), through the GL passes (region_legs.comp
// for the camera and light legs, the indirect gather's VPL -> x legs,
// medium_regions.glsl): an absorbing cube multiplies the plane's return by
// exp(-sigma_a 2 L) per pixel, an index 1.33 moves each pixel's peak to the
// bin of (eta - 1) 2 L later, and instant radiosity through a cube in the
// corner matches the reference. What the GL backend refuses: a scattering
// region, and regions of more triangles than its shaders' loops take
// (render/GlRegionLimits.h). GL = CPU on a region scene under every pixel
// model: tests/cpu/CpuMatchesGlGLTest.cpp (CornerVolumesThroughAnAbsorbingRegion).

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "support/GlTestContext.h"
#include "support/RegionTank.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/render/GlBackend.h"
#include "tofsim/render/GlRegionLimits.h"
#include "tofsim/util/Error.h"

namespace tofsim::render {
namespace {

capture::VolumeCollector renderOnGl(const capture::RenderJob& job) {
  capture::VolumeCollector out(capture::imageWidth(job.imager), capture::imageHeight(job.imager),
                               job.settings.time, capture::kChannels);
  ir::IrRenderer(std::make_unique<GlBackend>(test::glTestContext())).render(job, out);
  return out;
}

const glm::vec3 kSigmaA(1.0f, 0.5f, 0.2f);

TEST(MediumRegionsGLTest, AnAbsorbingCubeAttenuatesThePlanesReturn) {
  const test::TankJob tank(kSigmaA, 1.0), vacuum(kSigmaA, 1.0, false);
  test::expectAbsorbedByTheCube(renderOnGl(tank.plane.job).direct,
                                renderOnGl(vacuum.plane.job).direct, tank.plane.job, kSigmaA);
}

TEST(MediumRegionsGLTest, ARegionsIndexDelaysThePlanesPeak) {
  const test::TankJob tank(glm::vec3(0.0f), 1.33), vacuum(glm::vec3(0.0f), 1.0, false);
  test::expectDelayedByTheCube(renderOnGl(tank.plane.job).direct,
                               renderOnGl(vacuum.plane.job).direct, tank.plane.job);
}

TEST(MediumRegionsGLTest, InstantRadiosityMatchesTheReferenceThroughAnAbsorbingCube) {
  test::expectIrMatchesReferenceThroughACube(renderOnGl, 1e-5);
}

// The config refuses these first (MediumConfigTest, MediaCliTest); a library
// caller gets the backend's InputError instead of a silently wrong render.
std::string refusal(const capture::RenderJob& job) {
  try {
    renderOnGl(job);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MediumRegionsGLTest, ScatteringAndTooLargeRegionsAreRefused) {
  test::TankJob scattering(kSigmaA, 1.0);
  scattering.plane.job.settings.media.front().medium.sigma_s_per_m = glm::vec3(0.1f);
  // IrRenderer's refusal for a backend that does not trace rays.
  EXPECT_NE(refusal(scattering.plane.job).find("does not scatter light in regions"),
            std::string::npos);
  // 12 triangles: more than render.pixel_samples 16 leaves room for.
  test::TankJob fine(kSigmaA, 1.0);
  fine.plane.job.settings.pixel_samples = 16;
  fine.plane.job.camera().width = fine.plane.job.camera().height = 2;
  ASSERT_LT(glRegionTriangleLimit(16), 12u);
  const std::string tooLarge = refusal(fine.plane.job);
  EXPECT_NE(tooLarge.find("the media's regions have 12 triangles with the region 'tank'"),
            std::string::npos)
      << tooLarge;
  EXPECT_NE(tooLarge.find("at most " + std::to_string(glRegionTriangleLimit(16))),
            std::string::npos)
      << tooLarge;
}

}  // namespace
}  // namespace tofsim::render
