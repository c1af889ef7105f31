// Medium points in the CPU's indirect gather (issue 40, item 3): a medium
// point (physics::VERTEX_MEDIUM: no normal, phase 1 / (4 pi)) takes a VPL's
// light with no cosine of its own (physics::receiverCosine), its VPL
// singularity bounded by the patch's solid angle (vplMediumGeometryTerm), and
// the ISM's depth tolerance of a receiver that faces the VPL (ismDepthBias
// with cosine 1), not the grazing one an absent normal would give.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "CpuIsm.h"
#include "GatherKernel.h"
#include "support/AnalyticScenes.h"
#include "support/GivenVplsCpuBackend.h"
#include "support/MediumPoints.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::cpu {
namespace {

constexpr double kPi = 3.14159265358979323846;

using GivenVplsBackend = test::GivenVplsCpuBackend;

ir::Vpl pointVpl(const glm::vec3& at, const glm::vec3& normal, const glm::vec3& flux,
                 float path_m) {
  ir::Vpl v;
  v.positionPath = glm::vec4(at, path_m);
  v.normal = glm::vec4(normal, 0.0f);
  v.flux = glm::vec4(flux, 0.0f);  // Lambertian: albedo Phi / pi, W/sr
  v.vertex = physics::scatterVertex(physics::VERTEX_LAMBERTIAN, glm::vec3(0.5f), 0.0f, 1.0f);
  return v;
}

// Given medium samples, one per point, with `normal` (which a medium point
// ignores: physics::receiverNormal).
ir::SurfaceImage mediumSamples(const std::vector<glm::vec3>& points, const glm::vec3& albedo,
                               const glm::vec3& normal = glm::vec3(0.0f)) {
  return test::givenSamples(points, std::vector<int>(points.size(), physics::VERTEX_MEDIUM),
                            albedo, normal, glm::vec3(0.0f));
}

TEST(MediumIndirectTest, AVplLightsMediumPointsWithNoReceiverCosineInTheirBins) {
  scene::Scene scene;
  test::addQuad(scene, glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0, 0, 1), 1.0f, glm::vec3(0.5f));
  const glm::vec3 albedo(0.6f, 0.5f, 0.4f), origin(0.0f, -2.0f, 0.5f);
  // Above the VPL's plane at several angles, and one below it (dark).
  const std::vector<glm::vec3> points{{0.3f, 0.0f, 0.5f},
                                      {-0.4f, 0.2f, 0.8f},
                                      {0.0f, 0.0f, 1.2f},
                                      {0.9f, 0.1f, 0.05f},
                                      {0.5f, 0.0f, -0.3f}};
  const ir::Vpl vpl =
      pointVpl(glm::vec3(0.0f), glm::vec3(0, 0, 1), glm::vec3(0.3f, 0.2f, 0.1f), 1.25f);
  capture::RenderJob job;
  job.scene = &scene;
  capture::PointSetImager imager;
  imager.width = static_cast<int32_t>(points.size());
  imager.points_world = points;
  imager.origin_world = origin;
  job.imager = imager;
  job.light.position_world = {0.0f, 0.0f, 3.0f};
  job.light.intensity_W_per_sr = glm::vec3(1.0f);
  job.settings.indirect.enabled = true;
  job.settings.indirect.visibility = capture::Visibility::Exact;
  job.settings.pixel_footprint = false;
  job.settings.time = TimeAxis{0.0, 0.005 / kSpeedOfLight_m_per_s, 2000};
  capture::VolumeCollector volume(imager.width, 1, job.settings.time, capture::kChannels);
  auto backend = std::make_unique<GivenVplsBackend>(std::vector<ir::Vpl>{vpl});
  backend->setSurfaces(std::make_unique<ir::SurfaceImage>(mediumSamples(points, albedo)), nullptr);
  ir::IrRenderer(std::move(backend)).render(job, volume);

  const TimeAxis& axis = job.settings.time;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const auto x = static_cast<int32_t>(p);
    const glm::vec3 toX = points[p] - glm::vec3(vpl.positionPath);
    const double r = glm::length(toX), cosVpl = std::max(0.0, double(toX.z) / r);
    const int bin = axis.binOf((vpl.positionPath.w + r + glm::length(origin - points[p])) /
                               kSpeedOfLight_m_per_s);
    for (int c = 0; c < 3; ++c) {
      // albedo / (4 pi) * I_vpl cos_l / r^2, I_vpl = flux (W/sr).
      const double expected = albedo[c] / (4.0 * kPi) * vpl.flux[c] * cosVpl / (r * r);
      double near = 0.0, all = 0.0;
      for (int t = 0; t < axis.bins; ++t) {
        all += volume.indirect.at(0, x, t, c);
        if (std::abs(t - bin) <= 1) near += volume.indirect.at(0, x, t, c);
      }
      EXPECT_NEAR(near, expected, 1e-5 * expected + 1e-12) << "point " << p << ", channel " << c;
      EXPECT_NEAR(all, near, 1e-12) << "light outside its bin at point " << p;
    }
  }
}

// A pixel's 2 x 2 medium samples in one plane are not a flat surface to be
// merged (render.indirect.merge_pixel_samples), even where the driver gave
// them that plane's normal: each keeps its own place, and the pixel receives
// the mean of their closed forms, merged or not.
TEST(MediumIndirectTest, MediumSamplesAreNotMergedAsAFlatSurface) {
  scene::Scene scene;
  test::addQuad(scene, glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0, 0, 1), 1.0f, glm::vec3(0.5f));
  // Off the samples' symmetry plane: the four paths differ.
  const glm::vec3 albedo(0.6f, 0.5f, 0.4f), origin(0.3f, -2.0f, 0.5f);
  const std::vector<glm::vec3> points{
      {-0.2f, 0.0f, 0.3f}, {0.2f, 0.0f, 0.3f}, {-0.2f, 0.0f, 0.7f}, {0.2f, 0.0f, 0.7f}};
  const ir::Vpl vpl =
      pointVpl(glm::vec3(0.0f), glm::vec3(0, 0, 1), glm::vec3(0.3f, 0.2f, 0.1f), 1.0f);
  ir::SurfaceImage given = mediumSamples(points, albedo, glm::vec3(0.0f, -1.0f, 0.0f));
  given.width = 1;
  given.firstSample = {0, points.size()};
  given.side = {2};
  capture::RenderJob job;
  job.scene = &scene;
  capture::PointSetImager imager;
  imager.width = 1;
  imager.points_world = {glm::vec3(0.0f, 0.0f, 0.5f)};
  imager.origin_world = origin;
  imager.step_u_world = glm::vec3(0.4f, 0.0f, 0.0f);
  imager.step_v_world = glm::vec3(0.0f, 0.0f, -0.4f);
  job.imager = imager;
  job.light.position_world = {0.0f, 0.0f, 3.0f};
  job.settings.indirect.enabled = true;
  job.settings.indirect.visibility = capture::Visibility::Exact;
  job.settings.pixel_footprint = false;
  job.settings.pixel_samples = 2;
  job.settings.time = TimeAxis{0.0, 0.005 / kSpeedOfLight_m_per_s, 2000};
  const TimeAxis& axis = job.settings.time;
  double expected = 0.0;
  for (const glm::vec3& x : points) {
    const double r = glm::length(x);
    expected += 0.25 * albedo.r / (4.0 * kPi) * vpl.flux.r * (x.z / r) / (r * r);
  }
  for (const bool merge : {false, true}) {
    job.settings.indirect.merge_pixel_samples = merge;
    capture::VolumeCollector volume(1, 1, axis, capture::kChannels);
    auto backend = std::make_unique<GivenVplsBackend>(std::vector<ir::Vpl>{vpl});
    backend->setSurfaces(
        std::make_unique<ir::SurfaceImage>(given),
        std::make_unique<ir::SurfaceImage>(mediumSamples({glm::vec3(0.0f, 0.0f, 0.5f)}, albedo)));
    ir::IrRenderer(std::move(backend)).render(job, volume);
    double sum = 0.0;
    int binsLit = 0;
    for (int t = 0; t < axis.bins; ++t) {
      sum += volume.indirect.at(0, 0, t, 0);
      binsLit += volume.indirect.at(0, 0, t, 0) > 0.0f;
    }
    EXPECT_NEAR(sum, expected, 1e-5 * expected) << "merge " << merge;
    EXPECT_EQ(binsLit, 4) << "merge " << merge << ": the four samples' paths, each in its bin";
  }
}

// A medium point right in front of a VPL's patch (a square of side a): the
// gather's term is the patch's solid angle over its area, on the axis at
// height h 4 asin(a^2 / (a^2 + 4 h^2)) / a^2 (at most 2 pi / a^2), where the
// point VPL's 1 / h^2 has no bound; far away (beyond the near field) the
// point VPL's again, and the two agree where they meet.
TEST(MediumIndirectTest, AMediumPointNearAVplStaysBoundedByThePatchsSolidAngle) {
  const float a = 0.02f;
  ir::Vpl vpl = pointVpl(glm::vec3(0.0f), glm::vec3(0, 0, 1), glm::vec3(0.5f, 0.25f, 0.125f), 0.0f);
  vpl.patchU = glm::vec4(a, 0.0f, 0.0f, 0.0f);
  vpl.patchV = glm::vec4(0.0f, a, 0.0f, 0.0f);
  const VplArrays arrays(std::vector<ir::Vpl>{vpl});
  GatherConstants c;
  c.start_m = 0.0f, c.binWidth_m = 0.003f, c.indexOfRefraction = 1.0f, c.bins = 4096;
  c.geometryClamp = 0.0f;  // no clamp: the bound is the near field's own
  const double bound = 2.0 * kPi / (a * a);
  // Heights from a thousandth of the patch to just inside its near field
  // (8 widths), and beyond it.
  for (const float h : {2e-5f, 1e-4f, 1e-3f, 5e-3f, 0.02f, 0.159f, 0.161f, 0.4f}) {
    PixelSurface s;
    s.x = glm::vec3(0.0f, 0.0f, h);
    s.vertex = physics::scatterVertex(physics::VERTEX_MEDIUM, glm::vec3(0.6f), 0.0f, 1.0f);
    s.n = physics::receiverNormal(s.vertex, glm::vec3(0, 0, 1));
    s.cosineOffset = physics::receiverCosineOffset(s.vertex);
    s.brdf = physics::scatter(s.vertex, s.n, glm::vec3(0, 0, 1), glm::vec3(0, 0, 1)).f;
    s.camera = glm::vec3(0.0f, 1.0f, 1.0f);
    s.toCamera = glm::normalize(s.camera - s.x);
    VplTerms terms;
    vplTerms(s, arrays, 0, 1, c, terms);
    ASSERT_NE(terms.bin[0], kNoLight) << "h " << h;
    const double g = terms.r[0] / (double(s.brdf.r) * vpl.flux.r);
    const double solidAngle = 4.0 * std::asin(double(a) * a / (double(a) * a + 4.0 * h * h));
    const bool near = h < 8.0f * a;
    const double expected = near ? solidAngle / (a * a) : 1.0 / (double(h) * h);
    EXPECT_NEAR(g, expected, 2e-5 * expected) << "h " << h;
    EXPECT_LE(g, bound * (1.0 + 1e-6)) << "h " << h;
    // Where the near field ends the patch's integral and the point's agree.
    if (h > 0.1f) {
      EXPECT_NEAR(solidAngle / (a * a) * h * h, 1.0, 5e-3) << "h " << h;
    }
  }
}

// The ISM test at a medium point: its tolerance is one texel's depth (a
// receiver cosine of 1), so a plate halfway between the VPL and the point
// hides it, and a point off to the side, whose texels hold nothing, stays
// lit. An absent normal taken as a grazing receiver would widen the
// tolerance eightfold and let the light through the plate.
TEST(MediumIndirectTest, TheIsmHidesAMediumPointBehindAPlateAndNotOneInTheOpen) {
  scene::Scene scene;
  test::addQuad(scene, glm::vec3(0.0f, 0.0f, 0.5f), glm::vec3(0, 0, -1), 0.4f, glm::vec3(0.5f));
  const std::vector<ir::Vpl> vpls{
      pointVpl(glm::vec3(0.0f), glm::vec3(0, 0, 1), glm::vec3(1.0f), 0.0f)};
  capture::IndirectSettings settings;
  settings.ism_resolution = 32;
  settings.points_per_vpl = 20000;
  settings.ism_pull_push = false;  // empty texels stay empty: the open side is open
  CpuIsm ism(scene, vpls, settings, 5);
  ism.allocate(1);
  ism.build(0, 1, 1);
  physics::ScatterVertex medium =
      physics::scatterVertex(physics::VERTEX_MEDIUM, glm::vec3(0.6f), 0.0f, 1.0f);
  const glm::vec3 n = physics::receiverNormal(medium, glm::vec3(0, 0, -1));
  const float offset = physics::receiverCosineOffset(medium);
  const auto lit = [&](const glm::vec3& x) {
    VplTerms terms;
    const float dist = glm::length(x);
    terms.dx[0] = x.x / dist, terms.dy[0] = x.y / dist, terms.dz[0] = x.z / dist;
    terms.dist[0] = dist;
    terms.bin[0] = 7;
    ism.cullHidden(0, 1, 1.0f, n, offset, terms);
    return terms.bin[0] != kNoLight;
  };
  EXPECT_FALSE(lit(glm::vec3(0.0f, 0.0f, 1.0f)));   // behind the plate
  EXPECT_FALSE(lit(glm::vec3(0.05f, 0.0f, 0.8f)));  // behind it, off the axis
  EXPECT_TRUE(lit(glm::vec3(1.0f, 0.0f, 0.6f)));    // in the open
  EXPECT_TRUE(lit(glm::vec3(0.0f, -0.3f, 0.2f)));   // between the VPL and the plate's side
}

}  // namespace
}  // namespace tofsim::cpu
