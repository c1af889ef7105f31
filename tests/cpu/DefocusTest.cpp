// Thin-lens defocus (camera.aperture, capture/ThinLens.h) on the CPU
// backend against closed forms, on a plane facing the camera 1 m away, lit
// from the camera, seen by a 32 x 32 camera:
//  - a step edge on the plane in focus keeps its width (it is as sharp as
//    the pinhole's, every pixel's light the pinhole's to float);
//  - off focus the edge's profile is the disk's area profile of the circle
//    of confusion A |z - z_f| / (z z_f) (in pixels: over one pixel's angle),
//    and the line spread function's width fits that diameter;
//  - on the plane in focus each pixel's transient is the pinhole's (the
//    lens's path makes every aperture point's path to an in-focus point the
//    chief ray's: Fermat's principle);
//  - off focus a pixel's arrival-time mean and spread are those of the
//    paths light -> plane -> each aperture point (plus the lens's path from
//    it), closed form per point; timing the camera leg to the aperture
//    point without the lens, or from the lens centre, is rejected;
//  - the bytes do not depend on the threads or the segment plan.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "support/AnalyticScenes.h"
#include "support/CpuRender.h"
#include "support/TestJobs.h"
#include "tofsim/capture/ThinLens.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::cpu {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kDepth = 1.0f;  // camera to plane, m
constexpr int kSide = 32;
constexpr float kFovDeg = 10.0f;
constexpr float kAperture = 0.1f;  // m: a 9.1-pixel circle of confusion with focus at 2 m
constexpr int32_t kApertureSamples = 64;
constexpr double kBin_m = 0.0001;
constexpr double kStart_m = 1.99;

// The angle of one pixel at unit distance (square pixels).
double pixelAngle() { return 2.0 * std::tan(kFovDeg * kPi / 360.0) / kSide; }

struct PlaneScene {
  scene::Scene scene;
  capture::RenderJob job;
  glm::vec3 albedo{0.6f, 0.5f, 0.4f};

  // edge: the plane covers x > 0 only, its edge on the optical axis, between
  // columns 15 and 16 (nothing behind it).
  // lens: the same camera as a calibrated one (capture::Lens without
  // distortion), whose rays come from the lens's model.
  PlaneScene(bool edge, float aperture_m, float focus_m, bool lens = false) {
    const float size = 4.0f;
    test::addQuad(scene, glm::vec3(edge ? 0.5f * size : 0.0f, 0.0f, 0.0f), glm::vec3(0, 0, 1), size,
                  albedo);
    job.scene = &scene;
    capture::Camera& c = job.camera();
    c.position_world = {0.0f, 0.0f, kDepth};
    c.look_at_world = {0.0f, 0.0f, 0.0f};
    c.up_world = {0.0f, 1.0f, 0.0f};
    c.fov_y_deg = kFovDeg;
    c.width = c.height = kSide;
    c.aperture_m = aperture_m;
    c.focus_distance_m = focus_m;
    c.aperture_samples = kApertureSamples;
    if (lens) {
      capture::Lens l;
      l.fx = l.fy = 1.0 / pixelAngle();
      l.cx = l.cy = 0.5 * (kSide - 1);
      c.lens = l;
    }
    job.light.position_world = c.position_world;
    job.light.intensity_W_per_sr = glm::vec3(1.0f);
    job.settings.indirect.enabled = false;
    job.settings.pixel_footprint = false;  // each sample in its bin: the paths' own times
    job.settings.time =
        TimeAxis{kStart_m / kSpeedOfLight_m_per_s, kBin_m / kSpeedOfLight_m_per_s, 400};
  }
};

struct Moments {
  double mean_m = 0.0, sd_m = 0.0;
};

// Pixel (x, y)'s arrival, channel 0: the mean and spread of its bins'
// centres, as optical path.
Moments momentsOf(const TransientVolume& v, int x, int y) {
  double w = 0.0, m = 0.0, m2 = 0.0;
  for (int t = 0; t < v.bins(); ++t) {
    const double e = v.at(y, x, t, 0), at = kStart_m + (t + 0.5) * kBin_m;
    w += e, m += e * at, m2 += e * at * at;
  }
  m /= w;
  return {m, std::sqrt(std::max(0.0, m2 / w - m * m))};
}

TransientVolume volumeOf(const capture::RenderJob& job) {
  const test::CpuRender r = test::renderOnCpu(job);
  EXPECT_EQ(r.result.offAxis.before + r.result.offAxis.after, 0.0);
  return r.volume.total();
}

// Steady image (the sum over bins) of channel 0, row-major.
std::vector<double> steadyOf(const TransientVolume& v) {
  std::vector<double> steady(static_cast<std::size_t>(kSide) * kSide, 0.0);
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      for (int t = 0; t < v.bins(); ++t) steady[y * kSide + x] += v.at(y, x, t, 0);
    }
  }
  return steady;
}
std::vector<double> steadyOf(const capture::RenderJob& job) { return steadyOf(volumeOf(job)); }

// The closed-form circle of confusion, in pixels, of the plane at kDepth:
// detector-models.md's c = A f |z - z_f| / (z (z_f - f)) over the pixel
// pitch f' p of a sensor at the image distance f' = f z_f / (z_f - f),
// which is A |z - z_f| / (z z_f) / p whatever the focal length.
double circleOfConfusion_px(double focus_m) {
  const double f = 0.008;  // any focal length: it cancels
  const double c = kAperture * f * std::fabs(kDepth - focus_m) / (kDepth * (focus_m - f));
  return c / (f * focus_m / (focus_m - f) * pixelAngle());
}

// The share of a disk of radius r (pixels) on the lit side (x > 0) of the
// edge, for a pixel whose chief ray is u pixels right of the edge.
double diskShareRightOf(double u, double r) {
  const double t = std::clamp(u / r, -1.0, 1.0);
  return 0.5 + (t * std::sqrt(1.0 - t * t) + std::asin(t)) / kPi;
}

// Each pixel's share of the full plane's light: the edge's profile over the
// disk, with the plane's own fall-off divided out.
std::vector<double> edgeProfile(float focus_m, bool lens) {
  const std::vector<double> edge = steadyOf(PlaneScene(true, kAperture, focus_m, lens).job);
  const std::vector<double> full = steadyOf(PlaneScene(false, kAperture, focus_m, lens).job);
  std::vector<double> share(edge.size());
  for (std::size_t i = 0; i < edge.size(); ++i) share[i] = edge[i] / full[i];
  return share;
}

TEST(DefocusTest, AnEdgeOnThePlaneInFocusKeepsItsWidthAndItsTimes) {
  const TransientVolume pinholeVolume = volumeOf(PlaneScene(true, 0.0f, 1.0f).job);
  const TransientVolume focusedVolume = volumeOf(PlaneScene(true, kAperture, kDepth).job);
  const std::vector<double> pinhole = steadyOf(pinholeVolume), focused = steadyOf(focusedVolume);
  double worst = 0.0, worstMean = 0.0, worstSd = 0.0;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const double p = pinhole[y * kSide + x], f = focused[y * kSide + x];
      if (x < kSide / 2) {
        EXPECT_EQ(p, 0.0);
        EXPECT_EQ(f, 0.0) << "pixel " << x << ", " << y << " left of the edge sees the plane";
        continue;
      }
      ASSERT_GT(p, 0.0);
      worst = std::max(worst, std::fabs(f - p) / p);
      const Moments a = momentsOf(pinholeVolume, x, y), b = momentsOf(focusedVolume, x, y);
      worstMean = std::max(worstMean, std::fabs(a.mean_m - b.mean_m));
      worstSd = std::max(worstSd, std::fabs(a.sd_m - b.sd_m));
    }
  }
  // All 64 rays of a pixel meet on the plane in focus: the pinhole's light,
  // arriving when the pinhole's does (a path one bin off at a bin's
  // boundary moves a mean by 1/64 bin). Without the lens's path the
  // aperture points' legs would spread a corner pixel's light over +-60
  // bins (+-R sin 7 degrees, 6 mm).
  EXPECT_LT(worst, 1e-5);
  EXPECT_LT(worstMean, 0.05 * kBin_m);
  EXPECT_LT(worstSd, 0.05 * kBin_m);
  std::printf(
      "in focus: every pixel within %.2e of the pinhole's light; arrival mean within "
      "%.3f um, spread within %.3f um\n",
      worst, worstMean * 1e6, worstSd * 1e6);
}

// Through the pinhole camera and through the same camera as a calibrated
// lens (the aperture's rays then start from the lens's undistorted rays).
class DefocusEdgeTest : public ::testing::TestWithParam<bool> {};

TEST_P(DefocusEdgeTest, AnEdgeOffFocusBlursOverTheCircleOfConfusion) {
  const float focus = 2.0f;
  const double coc = circleOfConfusion_px(focus);
  EXPECT_NEAR(capture::circleOfConfusion_px(
                  PlaneScene(true, kAperture, focus, GetParam()).job.camera(), kDepth),
              coc, 1e-5 * coc);
  const std::vector<double> share = edgeProfile(focus, GetParam());
  // Every row sees the same profile across the edge; the middle rows'.
  const int y = kSide / 2;
  const auto profileError = [&](double radius) {
    double worst = 0.0;
    for (int x = 0; x < kSide; ++x) {
      const double u = x + 0.5 - kSide / 2;
      worst = std::max(worst, std::fabs(share[y * kSide + x] - diskShareRightOf(u, radius)));
    }
    return worst;
  };
  const double error = profileError(0.5 * coc);
  // 64 points of Vogel's spiral stand for the disk: the share steps by 1/64.
  EXPECT_LT(error, 0.03);
  // A circle a fifth wider or narrower is outside that (measured 0.064, 0.086).
  EXPECT_GT(profileError(0.6 * coc), 0.05);
  EXPECT_GT(profileError(0.4 * coc), 0.05);
  // The line spread function (the profile's steps) has the variance of the
  // disk's projection, r^2 / 4, plus a pixel's 1/12.
  double mass = 0.0, mean = 0.0, second = 0.0;
  for (int x = 0; x + 1 < kSide; ++x) {
    const double step = share[y * kSide + x + 1] - share[y * kSide + x];
    const double at = x + 1.0 - kSide / 2;  // between the two pixel centres
    mass += step, mean += step * at, second += step * at * at;
  }
  mean /= mass;
  const double variance = second / mass - mean * mean;
  const double fitted = 4.0 * std::sqrt(variance - 1.0 / 12.0);
  EXPECT_NEAR(mass, 1.0, 1e-3);
  // The edge stays where it is, but for the 64 points' centroid (0.0087 of
  // the radius: 0.04 pixel) and their steps.
  EXPECT_NEAR(mean, 0.0, 0.1);
  EXPECT_NEAR(fitted, coc, 0.03 * coc);
  std::printf(
      "off focus (%s): circle of confusion %.3f px (closed form), fitted %.3f px; profile "
      "within %.4f of the disk's; a 20%% wider / narrower disk: %.3f / %.3f\n",
      GetParam() ? "calibrated lens" : "pinhole", coc, fitted, error, profileError(0.6 * coc),
      profileError(0.4 * coc));
}

INSTANTIATE_TEST_SUITE_P(Camera, DefocusEdgeTest, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "Lens" : "Pinhole"; });

// Vogel's spiral as ThinLens.h defines it, written out here.
glm::dvec2 vogel(int a, int count) {
  const double r = std::sqrt((a + 0.5) / count), phi = a * kPi * (3.0 - std::sqrt(5.0));
  return {r * std::cos(phi), r * std::sin(phi)};
}

// How the camera leg is timed: to the aperture point plus the lens's path
// from it (the thin lens), to the aperture point alone, or to the centre.
enum class Leg { ThinLens, ApertureOnly, LensCentre };

// The closed form of pixel (x, y): each aperture point a's ray towards the
// chief ray's point F on the plane in focus meets the plane z = 0 at p; its
// light arrives after |p - l| + |p - a| + |F - c| - |F - a| (the lens's
// path: Fermat), weighted by the radiance albedo / pi I cos / |p - l|^2, in
// the bin it falls in.
Moments closedForm(int x, int y, double focus, Leg leg) {
  const double t = std::tan(kFovDeg * kPi / 360.0);
  const glm::dvec3 c(0.0, 0.0, kDepth), forward(0.0, 0.0, -1.0);
  const glm::dvec3 chief = glm::normalize(
      glm::dvec3((2.0 * (x + 0.5) / kSide - 1.0) * t, (1.0 - 2.0 * (y + 0.5) / kSide) * t, -1.0));
  const glm::dvec3 inFocus = c + chief * (focus / glm::dot(chief, forward));
  double w = 0.0, m = 0.0, m2 = 0.0;
  for (int i = 0; i < kApertureSamples; ++i) {
    const glm::dvec2 d = vogel(i, kApertureSamples) * (0.5 * kAperture);
    const glm::dvec3 a = c + glm::dvec3(d.x, d.y, 0.0);
    const glm::dvec3 p = a + (inFocus - a) * (a.z / (a.z - inFocus.z));
    const double toLight = glm::length(p - c);
    const double radiance = (c.z - p.z) / toLight / (toLight * toLight);  // albedo I / pi cancel
    const double lens = glm::length(inFocus - c) - glm::length(inFocus - a);
    const double camera = leg == Leg::LensCentre     ? glm::length(p - c)
                          : leg == Leg::ApertureOnly ? glm::length(p - a)
                                                     : glm::length(p - a) + lens;
    const double path = toLight + camera;
    const double binCentre = kStart_m + (std::floor((path - kStart_m) / kBin_m) + 0.5) * kBin_m;
    w += radiance, m += radiance * binCentre, m2 += radiance * binCentre * binCentre;
  }
  m /= w;
  return {m, std::sqrt(std::max(0.0, m2 / w - m * m))};
}

TEST(DefocusTest, ArrivalIsTheMeanOverTheAperturePointsPaths) {
  const float focus = 2.0f;
  const test::CpuRender r = test::renderOnCpu(PlaneScene(false, kAperture, focus).job);
  const TransientVolume v = r.volume.total();
  double worstMean = 0.0, worstSd = 0.0;
  double wrong[2][2] = {};  // [aperture only, lens centre][mean, sd]
  for (const auto& [x, y] : {std::pair{16, 16}, std::pair{0, 0}, std::pair{31, 5}, std::pair{3, 27},
                             std::pair{20, 31}}) {
    const Moments rendered = momentsOf(v, x, y);
    const Moments expected = closedForm(x, y, focus, Leg::ThinLens);
    worstMean = std::max(worstMean, std::fabs(rendered.mean_m - expected.mean_m));
    worstSd = std::max(worstSd, std::fabs(rendered.sd_m - expected.sd_m));
    for (int k = 0; k < 2; ++k) {
      const Moments w = closedForm(x, y, focus, k == 0 ? Leg::ApertureOnly : Leg::LensCentre);
      wrong[k][0] = std::max(wrong[k][0], std::fabs(rendered.mean_m - w.mean_m));
      wrong[k][1] = std::max(wrong[k][1], std::fabs(rendered.sd_m - w.sd_m));
    }
  }
  // A sample's path one bin off at a bin's boundary moves the mean by 1/64 bin.
  EXPECT_LT(worstMean, 0.05 * kBin_m);
  EXPECT_LT(worstSd, 0.05 * kBin_m);
  // Without the lens's path, or from the lens centre: far outside.
  for (const auto& w : wrong) EXPECT_GT(std::max(w[0], w[1]), 1.0 * kBin_m);
  std::printf(
      "arrival: mean within %.3f um and sd within %.3f um of the thin lens's paths; "
      "without the lens's path %.1f / %.1f um off, from the lens centre %.1f / %.1f "
      "um off\n",
      worstMean * 1e6, worstSd * 1e6, wrong[0][0] * 1e6, wrong[0][1] * 1e6, wrong[1][0] * 1e6,
      wrong[1][1] * 1e6);
}

bool sameBytes(const TransientVolume& a, const TransientVolume& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(DefocusTest, BytesDoNotDependOnThreadsOrSegments) {
  // Indirect light, the footprint, 2 x 2 sub-pixels at the edges: every path
  // the aperture samples go through.
  test::CornerJob s(16);
  s.job.settings.indirect.rsm_resolution = 8;
  s.job.settings.indirect.points_per_vpl = 200;
  s.job.settings.pixel_samples = 2;
  s.job.settings.adaptive_pixel_samples = true;
  capture::Camera& c = s.job.camera();
  c.aperture_m = 0.05f;
  c.focus_distance_m = 1.5f;
  c.aperture_samples = 5;
  const test::CpuRender one = test::renderOnCpu(s.job, {1, true});
  ASSERT_GT(one.result.vpls, 0u);
  const test::CpuRender three = test::renderOnCpu(s.job, {3, true});
  s.job.settings.memory_budget_bytes = std::size_t{3} << 20;
  const test::CpuRender split = test::renderOnCpu(s.job, {2, true});
  EXPECT_GT(split.result.segments, 1u);
  for (const test::CpuRender* other : {&three, &split}) {
    EXPECT_TRUE(sameBytes(one.volume.direct, other->volume.direct));
    EXPECT_TRUE(sameBytes(one.volume.indirect, other->volume.indirect));
  }
  // And the aperture changes them: it is not ignored.
  c.aperture_m = 0.0f;
  const test::CpuRender pinhole = test::renderOnCpu(s.job, {2, true});
  EXPECT_FALSE(sameBytes(one.volume.direct, pinhole.volume.direct));
}

TEST(DefocusTest, ApertureOfZeroIsThePinholeByteForByte) {
  // The thin lens's other fields mean nothing without an aperture.
  test::CornerJob s(12);
  s.job.settings.indirect.rsm_resolution = 8;
  const test::CpuRender plain = test::renderOnCpu(s.job);
  s.job.camera().focus_distance_m = 0.3f;
  s.job.camera().aperture_samples = 7;
  const test::CpuRender zero = test::renderOnCpu(s.job);
  EXPECT_TRUE(sameBytes(plain.volume.direct, zero.volume.direct));
  EXPECT_TRUE(sameBytes(plain.volume.indirect, zero.volume.indirect));
  EXPECT_NE(capture::pinhole(s.job.imager), nullptr);
}

TEST(DefocusTest, VogelsSpiralStratifiesTheDisk) {
  // Point i alone in the i-th of K rings of equal area; centroid near 0.
  for (const int k : {2, 16, 64, 257}) {
    glm::dvec2 sum(0.0);
    for (int i = 0; i < k; ++i) {
      const glm::vec2 p = capture::aperturePoint(i, k);
      const double r2 = glm::dot(glm::dvec2(p), glm::dvec2(p));
      EXPECT_GT(r2, double(i) / k);
      EXPECT_LT(r2, double(i + 1) / k);
      sum += glm::dvec2(p);
    }
    EXPECT_LT(glm::length(sum / double(k)), 1.0 / std::sqrt(double(k))) << k;
  }
}

}  // namespace
}  // namespace tofsim::cpu
