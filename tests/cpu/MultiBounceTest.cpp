// Multi-bounce instant radiosity (render.indirect.bounces) on the CPU
// backend: the energy of all bounces and of bounce 2 alone against the
// reference path tracer with one interaction more (exact visibility, no
// clamp), the closed-form decay of a closed box (each bounce rho times the one
// before), causality, bytes unchanged with bounces: 1, and determinism.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "reference/RenderReference.h"
#include "support/AnalyticScenes.h"
#include "support/CpuRender.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::cpu {
namespace {

using namespace capture;

test::CpuRender renderIr(RenderJob job, int32_t bounces, int threads = 2) {
  job.settings.indirect.bounces = bounces;
  return test::renderOnCpu(job, {threads, true});
}

RenderJob exactUnclamped(RenderJob job) {
  job.settings.indirect.visibility = Visibility::Exact;
  job.settings.indirect.geometry_term_clamp_per_m2 = 0.0;
  return job;
}

struct BounceErrors {
  double total = 0.0;    ///< |IR bounces 2 - reference 3 interactions| / reference, indirect energy
  double bounce2 = 0.0;  ///< the same for bounce 2 alone (IR 2 - 1 vs reference 3 - 2)
};

BounceErrors energyErrors(const RenderJob& job, int samples) {
  const double ir1 = test::energy(renderIr(job, 1).volume.indirect);
  const double ir2 = test::energy(renderIr(job, 2).volume.indirect);
  const double ref2 =
      test::energy(test::renderReference(job, 2, samples, reference::PixelFilter::Box).indirect);
  const double ref3 =
      test::energy(test::renderReference(job, 3, samples, reference::PixelFilter::Box).indirect);
  const BounceErrors e{std::abs(ir2 - ref3) / ref3,
                       std::abs((ir2 - ir1) - (ref3 - ref2)) / (ref3 - ref2)};
  std::printf(
      "indirect energy: IR bounce 1 %.5g, bounces 1-2 %.5g; reference 2 interactions "
      "%.5g, 3 %.5g; error of all bounces %.4f, of bounce 2 alone %.4f\n",
      ir1, ir2, ref2, ref3, e.total, e.bounce2);
  return e;
}

TEST(MultiBounceTest, CornerEnergyOfTwoBouncesMatchesTheReference) {
  test::CornerJob s(24);
  s.job.settings.time = TimeAxis{0.0, 100e-12, 600};  // 0 .. 18 m: every 3-leg path
  s.job.settings.indirect.rsm_resolution = 48;
  const BounceErrors e = energyErrors(exactUnclamped(s.job), 4096);
  // Stated bounds, about 1.3x the errors measured at commit time: all bounces
  // 0.0031, bounce 2 alone 0.035 (2304 VPLs per bounce; the reference's
  // bounce 2 is the difference of two 4096-path renders, noise included).
  EXPECT_LT(e.total, 0.0045);
  EXPECT_LT(e.bounce2, 0.045);
}

TEST(MultiBounceTest, CornellBoxEnergyOfTwoBouncesMatchesTheReference) {
  const scene::Scene scene = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  RenderJob job = test::cornellBoxJob(scene, 24, 300, 0.03);  // 1.5 .. 10.5 m
  job.settings.indirect.rsm_resolution = 48;
  // Bounce 2's 9216 random VPLs, unclamped: with as many as bounce 1 has
  // (vpls_per_bounce: 0) its energy moved by up to 10 % from seed to seed.
  job.settings.indirect.vpls_per_bounce = 9216;
  const BounceErrors e = energyErrors(exactUnclamped(job), 4096);
  // Measured: all bounces 0.0088, bounce 2 alone 0.019 (0.025 / 0.046 at
  // seeds 2 / 3: both estimates' noise); bounce 1 alone is 2.4 % under the
  // reference. With one VPL per RSM texel (rsm_edge_samples: 1) bounce 1 was
  // 5.0 % low and all bounces 0.021 / 0.018 / 0.015 off at seeds 1 / 2 / 3:
  // the texels across the box's front edges, which the texel centres round to
  // whole texels in or out, and those across its creases, whose patches the
  // VPL's near field clips (RsmEdgeTexels.h).
  EXPECT_LT(e.total, 0.013);
  EXPECT_LT(e.bounce2, 0.027);
}

// A 2 m closed box of albedo rho, light and camera inside: every ray of a
// VPL hits, so the power of bounce k is exactly rho times that of bounce k-1
// (BounceVplsTest); what the camera sees of it tends to rho times as well, as
// the light's distribution over the walls settles to its uniform limit.
TEST(MultiBounceTest, ClosedBoxBounceEnergyTendsToAlbedoTimesThePreviousOne) {
  const float rho = 0.5f;
  const scene::Scene box = test::makeClosedBox(2.0f, glm::vec3(rho));
  RenderJob job;
  job.scene = &box;
  job.camera().position_world = {0.1f, -0.2f, 0.6f};
  job.camera().look_at_world = {-0.2f, 0.1f, -1.0f};
  job.camera().fov_y_deg = 90.0f;
  job.camera().width = job.camera().height = 16;
  job.light.position_world = {0.4f, 0.5f, -0.3f};
  job.light.intensity_W_per_sr = glm::vec3(1.0f);
  job.settings.time = TimeAxis{0.0, 0.02 / kSpeedOfLight_m_per_s, 1500};  // 0 .. 30 m
  job.settings.indirect.rsm_resolution = 24;
  job.settings.indirect.visibility = Visibility::Exact;
  double previous = 0.0, previousBounce = 0.0;
  std::vector<double> ratio(6, 0.0);
  for (int32_t k = 1; k <= 5; ++k) {
    const double all = test::energy(renderIr(job, k).volume.indirect);
    const double bounce = all - previous;
    if (k > 1) ratio[k] = bounce / previousBounce;
    if (k > 1) std::printf("closed box: bounce %d / bounce %d = %.4f\n", k, k - 1, ratio[k]);
    previous = all;
    previousBounce = bounce;
  }
  // Measured 0.478, 0.486, 0.493, 0.493 (1536 VPLs per bounce, clamp 100):
  // within 0.007 of rho from bounce 4 on.
  for (int32_t k = 2; k <= 5; ++k) EXPECT_NEAR(ratio[k], rho, 0.03) << k;
  for (int32_t k = 4; k <= 5; ++k) EXPECT_NEAR(ratio[k], rho, 0.01) << k;
}

// The corner seen through point pixels (all of a pixel's light in the bin of
// its centre's path). With planes A (the one the pixel sees) and B, light of
// bounce k (k indirect interactions) reflects alternately on B and A, ending
// on B: unfolding the reflections, its path from the light to the pixel's
// point x is at least |R(l) - x|, R the composed mirror images of the light.
// And no path beats the direct one to the same point.
glm::dvec3 mirrorIn(bool floor, glm::dvec3 p) {
  if (floor) {
    p.y = -p.y;  // the floor y = 0
  } else {
    p.z = -2.0 - p.z;  // the wall z = -1
  }
  return p;
}

TEST(MultiBounceTest, NoBounceArrivesBeforeItsShortestUnfoldedPath) {
  test::CornerJob s(16);
  RenderJob job = s.job;
  job.settings.pixel_footprint = false;
  job.settings.time = TimeAxis{0.0, 0.01 / kSpeedOfLight_m_per_s, 1500};
  const TimeAxis& axis = job.settings.time;
  std::vector<test::CpuRender> r;
  for (int32_t k = 1; k <= 3; ++k) r.push_back(renderIr(job, k));
  const glm::dvec3 eye(job.camera().position_world), light(job.light.position_world);
  std::size_t checked = 0, lit = 0;
  std::vector<int32_t> slack(4, axis.bins);
  for (int32_t y = 0; y < job.camera().height; ++y) {
    for (int32_t x = 0; x < job.camera().width; ++x) {
      const double depth = r[0].result.depth_m.at(y, x, 0);
      if (depth <= 0.0) continue;
      const glm::dvec3 p = eye + depth * glm::dvec3(job.camera().pixelDirection(x, y));
      const bool onFloor = std::abs(p.y) < 1e-3;
      ASSERT_TRUE(onFloor || std::abs(p.z + 1.0) < 1e-3) << x << " " << y;
      const double toCamera = glm::length(p - eye);
      // Bin of the direct path, then of bounce k's unfolded bound (the image
      // of the light in B, A, B, ... in reverse order of the reflections).
      const int32_t directBin =
          axis.binOf((glm::length(light - p) + toCamera) / kSpeedOfLight_m_per_s);
      for (int32_t k = 1; k <= 3; ++k) {
        glm::dvec3 image = light;
        for (int32_t i = k; i >= 1; --i) image = mirrorIn(onFloor == (i % 2 == 0), image);
        const int32_t bound =
            axis.binOf((glm::length(image - p) + toCamera) / kSpeedOfLight_m_per_s);
        ASSERT_GE(bound, directBin);
        // Bounce k alone: the VPLs of bounces < k add in the same order in
        // both renders, so where bounce k adds nothing the bins are bit-equal.
        const TransientVolume& all = r[k - 1].volume.indirect;
        int32_t firstAny = axis.bins, firstOwn = axis.bins;
        for (int32_t t = 0; t < axis.bins; ++t) {
          for (int32_t c = 0; c < 3; ++c) {
            const float before = k > 1 ? r[k - 2].volume.indirect.at(y, x, t, c) : 0.0f;
            if (all.at(y, x, t, c) != 0.0f) firstAny = std::min(firstAny, t);
            if (all.at(y, x, t, c) != before) firstOwn = std::min(firstOwn, t);
          }
        }
        // One bin of slack for the float rounding of the bin of a path.
        EXPECT_GE(firstAny, directBin - 1) << "bounces <= " << k << " at " << x << "," << y;
        EXPECT_GE(firstOwn, bound - 1) << "bounce " << k << " at " << x << "," << y;
        if (firstOwn < axis.bins) {
          ++lit;
          slack[k] = std::min(slack[k], firstOwn - bound);
        }
        ++checked;
      }
    }
  }
  std::printf(
      "earliest light of bounce 1, 2, 3 after its unfolded bound: %d, %d, %d bins of 1 cm\n",
      slack[1], slack[2], slack[3]);
  EXPECT_GT(checked, 3u * 150u);     // of 3 x 256 pixel-bounces, the rest see no surface
  EXPECT_GT(lit, checked * 9 / 10);  // every bounce reaches (nearly) every pixel
}

TEST(MultiBounceTest, OneBounceIsTheDefaultAndIgnoresVplsPerBounce) {
  test::CornerJob s(16);
  RenderJob job = s.job;
  job.settings.indirect.vpls_per_bounce = 777;
  const test::CpuRender one = renderIr(job, 1);
  const test::CpuRender plain = renderIr(s.job, RenderSettings().indirect.bounces);
  EXPECT_EQ(RenderSettings().indirect.bounces, 1);
  EXPECT_EQ(one.result.vpls, plain.result.vpls);
  EXPECT_EQ(one.volume.indirect.values(), plain.volume.indirect.values());
  EXPECT_EQ(one.volume.direct.values(), plain.volume.direct.values());
}

TEST(MultiBounceTest, ThreeBouncesGiveTheSameBytesWhateverTheThreadsAndBudget) {
  test::CornerJob s(16);  // ISM visibility: every bounce's VPLs get imperfect shadow maps
  s.job.settings.indirect.rsm_resolution = 16;
  const test::CpuRender a = renderIr(s.job, 3, 1);
  const std::size_t first = renderIr(s.job, 1, 1).result.vpls;
  // As many rays per later bounce as bounce 1 has VPLs; those leaving the
  // open corner make none.
  EXPECT_GT(a.result.vpls, first);
  EXPECT_LT(a.result.vpls, 3 * first);
  for (const int threads : {2, 3}) {
    const test::CpuRender b = renderIr(s.job, 3, threads);
    EXPECT_EQ(a.volume.indirect.values(), b.volume.indirect.values()) << threads;
    EXPECT_EQ(a.volume.direct.values(), b.volume.direct.values()) << threads;
  }
  RenderJob tight = s.job;
  tight.settings.memory_budget_bytes = std::size_t{2} << 20;
  const test::CpuRender c = renderIr(tight, 3, 3);
  EXPECT_GT(c.result.vplBatches, 1u);
  EXPECT_EQ(a.volume.indirect.values(), c.volume.indirect.values());
}

}  // namespace
}  // namespace tofsim::cpu
