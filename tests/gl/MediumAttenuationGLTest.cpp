// Issue 42, item 2, on the GL backend: the medium filling the scene
// attenuates every leg of the gathers (direct_gather.comp, indirect_gather.comp
// with MEDIUM: medium_uniforms.glsl) and of the RSM VPLs' flux, as on the CPU
// (tests/cpu/MediumAttenuationTest.cpp: the same closed forms,
// support/MediumAttenuation.h). The backends' agreement in a medium:
// tests/cpu/CpuMatchesGlGLTest.cpp.

#include <gtest/gtest.h>

#include <memory>

#include "support/GlTestContext.h"
#include "support/MediumAttenuation.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/render/GlBackend.h"

namespace tofsim::render {
namespace {

std::unique_ptr<capture::Renderer> glRenderer() {
  return std::make_unique<ir::IrRenderer>(std::make_unique<GlBackend>(test::glTestContext()));
}

TEST(MediumAttenuationGLTest, AbsorbingMediumScalesEachBinOfDirectAndIndirectLight) {
  test::expectCornerAbsorbedPerBin(glRenderer);
}

TEST(MediumAttenuationGLTest, MergedSubPixelSamplesAndFootprintsAreAbsorbedByTheirPaths) {
  test::expectSubPixelSamplesAbsorbed(glRenderer);
}

TEST(MediumAttenuationGLTest, CameraUnwarpKeepsTheCameraLegsAttenuation) {
  test::expectUnwarpKeepsAttenuation(glRenderer);
}

}  // namespace
}  // namespace tofsim::render
