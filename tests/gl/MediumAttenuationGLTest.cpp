// Issue 42, item 2, on the GL backend: the medium filling the scene
// attenuates every leg of the gathers (direct_gather.comp, indirect_gather.comp
// with MEDIUM: medium_uniforms.glsl) and of the RSM VPLs' flux, as on the CPU
// (tests/cpu/MediumAttenuationTest.cpp: the same closed forms,
// support/MediumAttenuation.h). Sub-pixel samples and footprints (the
// footprint deposit) in a medium: the backends' agreement,
// tests/cpu/CpuMatchesGlGLTest.cpp (CornerVolumesInAnAbsorbingMedium), the
// CPU's closed form being MediumAttenuationTest's.

#include <gtest/gtest.h>

#include <memory>

#include "support/GivenSamplesGlBackend.h"
#include "support/GlTestContext.h"
#include "support/MediumAttenuation.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/render/GlBackend.h"

namespace tofsim::render {
namespace {

// A smaller image than the CPU's: llvmpipe's exact visibility walks a BVH
// per pair.
constexpr int32_t kSide = 10;

std::unique_ptr<capture::Renderer> glRenderer() {
  return std::make_unique<ir::IrRenderer>(std::make_unique<GlBackend>(test::glTestContext()));
}

TEST(MediumAttenuationGLTest, AbsorbingMediumScalesEachBinOfDirectAndIndirectLight) {
  test::expectCornerAbsorbedPerBin(glRenderer, kSide);
}

TEST(MediumAttenuationGLTest, CameraUnwarpKeepsTheCameraLegsAttenuation) {
  test::expectUnwarpKeepsAttenuation(glRenderer, kSide);
}

TEST(MediumAttenuationGLTest, MediumPointsDirectLightIsAttenuatedOnBothLegs) {
  test::expectMediumPointsAbsorbed(
      [](const capture::RenderJob& job, const ir::SurfaceImage& given) {
        return test::renderComponents(
            ir::IrRenderer(std::make_unique<test::GivenSamplesGlBackend>(given)), job);
      });
}

}  // namespace
}  // namespace tofsim::render
