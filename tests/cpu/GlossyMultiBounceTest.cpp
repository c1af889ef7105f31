// Multi-bounce instant radiosity with glossy VPLs (render.materials: gltf,
// render.indirect.bounces: 2) on the CPU backend: a later bounce continues a
// glossy VPL's path by sampling its BRDF, weighted by f cos / pdf
// (ir::traceBounce). The indirect energy of bounces 1-2 and of bounce 2
// alone against the reference path tracer with one interaction more (exact
// visibility, no clamp), on a glossy metal floor and a glossy dielectric
// wall 0.3 m behind it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "reference/RenderReference.h"
#include "support/CpuRender.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/reference/ReferenceRenderer.h"

namespace tofsim::cpu {
namespace {

using namespace capture;

double irIndirect(RenderJob job, int32_t bounces) {
  job.settings.indirect.bounces = bounces;
  return test::energy(test::renderOnCpu(job).volume.indirect);
}

double referenceIndirect(const RenderJob& job, int32_t interactions) {
  return test::energy(
      test::renderReference(job, interactions, 16384, reference::PixelFilter::Box).indirect);
}

TEST(GlossyMultiBounceTest, FloorAndWallEnergyOfTwoGlossyBouncesMatchesTheReference) {
  test::CornerJob s(24);
  // The wall moved 0.3 m back and up: no concave edge, so the unclamped
  // geometry term stays bounded. On the touching corner IR's second glossy
  // bounce came out 5 % low on average over seeds (3.45 against 3.63, with
  // one render of the default VPL count at 4.16): the heavy tail of glossy
  // VPLs next to the edge, which the gap removes (there IR agrees within 3 %).
  for (auto& q : s.scene.meshes[1].positions_world) q += glm::vec3(0.0f, 0.3f, -0.3f);
  s.scene.materials.at(0).metallic = 0.8f;  // the floor
  s.scene.materials.at(0).roughness = 0.4f;
  s.scene.materials.at(1).roughness = 0.5f;  // the wall, a dielectric
  s.job.settings.materials = MaterialModel::Gltf;
  s.job.settings.time = TimeAxis{0.0, 100e-12, 600};  // 0 .. 18 m: every 3-leg path
  s.job.settings.indirect.rsm_resolution = 48;
  s.job.settings.indirect.vpls_per_bounce = 40000;
  s.job.settings.indirect.visibility = Visibility::Exact;
  s.job.settings.indirect.geometry_term_clamp_per_m2 = 0.0;
  const double ir1 = irIndirect(s.job, 1), ir2 = irIndirect(s.job, 2);
  const double ref2 = referenceIndirect(s.job, 2), ref3 = referenceIndirect(s.job, 3);
  const double total = std::abs(ir2 - ref3) / ref3;
  const double bounce2 = std::abs((ir2 - ir1) - (ref3 - ref2)) / (ref3 - ref2);
  std::printf(
      "glossy floor and wall, indirect energy: IR bounce 1 %.5g, bounces 1-2 %.5g; reference 2 "
      "interactions %.5g, 3 %.5g; error of all bounces %.4f, of bounce 2 alone %.4f\n",
      ir1, ir2, ref2, ref3, total, bounce2);
  // Measured with BRDF-sampled bounces (and the reference's BRDF sampling):
  // all bounces 0.0082, bounce 2 alone 0.0031. With cosine-sampled bounces
  // (weights pi f, which spread) bounce 2 was 0.011-0.03 and other seeds put
  // it up to 5 % above the reference; the bounds keep that margin.
  EXPECT_LT(total, 0.02);
  EXPECT_LT(bounce2, 0.03);
}

}  // namespace
}  // namespace tofsim::cpu
