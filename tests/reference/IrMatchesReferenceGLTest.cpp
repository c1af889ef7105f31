// Transient instant radiosity (exact visibility, no clamping) against the
// 2-bounce reference path tracer on the Cornell box: both estimate the same
// direct + one-bounce transport, so they must agree within the VPL
// discretisation and the reference's Monte Carlo noise.

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "support/GlTestContext.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/compare/VolumeComparison.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/render/GlBackend.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim {
namespace {

using namespace capture;

RenderJob cornellJob(const scene::Scene& scene) {
  // 3 cm bins: coarse enough that the VPLs' discrete emission times (the
  // paper's temporal banding) average out within a bin.
  RenderJob job = test::cornellBoxJob(scene, 24, 80, 0.03);
  job.settings.shadow_map_resolution = 1024;
  job.settings.indirect.rsm_resolution = 64;
  job.settings.indirect.visibility = Visibility::Exact;
  job.settings.indirect.geometry_term_clamp_per_m2 = 0.0;
  job.settings.pixel_footprint = false;  // pixel centres, as the point-filter reference
  return job;
}

TEST(IrMatchesReferenceGLTest, CornellBoxSteadyAndTransientAgree) {
  const scene::Scene scene = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  const RenderJob job = cornellJob(scene);
  VolumeCollector ir(24, 24, job.settings.time, 3), ref(24, 24, job.settings.time, 3);
  ir::IrRenderer(std::make_unique<render::GlBackend>(test::glTestContext())).render(job, ir);
  reference::ReferenceSettings settings;
  settings.pixel_filter = reference::PixelFilter::Point;  // compares pixel centres
  settings.bounces = 2;
  settings.samples_per_pixel = 1024;
  reference::ReferenceRenderer(settings).render(job, ref);
  // The reference's own noise: the same render with another seed.
  RenderJob otherSeed = job;
  otherSeed.settings.seed = 2;
  VolumeCollector ref2(24, 24, job.settings.time, 3);
  reference::ReferenceRenderer(settings).render(otherSeed, ref2);
  const compare::VolumeComparison noise = compare::compareVolumes(ref2.indirect, ref.indirect);
  std::printf("reference vs reference (other seed): indirect steady L1 %.4f, transient L1 %.4f\n",
              noise.steadyRelativeL1, noise.transientRelativeL1);

  const compare::VolumeComparison total = compare::compareVolumes(ir.total(), ref.total());
  const compare::VolumeComparison indirect = compare::compareVolumes(ir.indirect, ref.indirect);
  std::printf(
      "IR vs reference: total steady L1 %.4f, transient L1 %.4f; indirect steady L1 %.4f, "
      "transient L1 %.4f\n",
      total.steadyRelativeL1, total.transientRelativeL1, indirect.steadyRelativeL1,
      indirect.transientRelativeL1);
  double eIr = 0, eRef = 0;
  for (float v : ir.indirect.values()) eIr += v;
  for (float v : ref.indirect.values()) eRef += v;
  // Stated tolerances, about 1.4x the values measured at commit time (total
  // steady 0.021, transient 0.048; indirect steady 0.135, transient 0.335,
  // where the reference's own seed-to-seed noise is 0.05 and 0.24). The
  // indirect per-pixel error is dominated by unclamped VPL singularities near
  // the box's edges; over the whole image the total agrees within 2%.
  EXPECT_LT(total.steadyRelativeL1, 0.03);
  EXPECT_LT(total.transientRelativeL1, 0.07);
  EXPECT_LT(indirect.steadyRelativeL1, 0.18);
  EXPECT_LT(indirect.transientRelativeL1, 0.45);
  double irEnergy = 0.0, refEnergy = 0.0;
  for (float v : ir.indirect.values()) irEnergy += v;
  for (float v : ref.indirect.values()) refEnergy += v;
  // Total indirect energy: within 8% (measured 0.98, 1.06, 1.01 at 48^2, 64^2, 96^2 VPLs).
  EXPECT_NEAR(irEnergy / refEnergy, 1.0, 0.08);
  // The direct terms share one formula; they differ only where the light's
  // shadow map and the reference's shadow rays disagree on shadow edges.
  EXPECT_LT(compare::compareVolumes(ir.direct, ref.direct).steadyRelativeL1, 0.005);
}

}  // namespace
}  // namespace tofsim
