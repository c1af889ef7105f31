// The medium's direct light (issue 42, item 3): the light a homogeneous
// medium filling the scene scatters once into each pixel's camera ray, per
// time bin, on both IR backends (shaders/medium.glsl's quadrature, run by
// shaders/medium_direct.comp and core/cpu/src/CpuMediumDirect.cpp), against
// integrals the test computes itself in double by composite Simpson rules:
// the lidar equation for a co-located camera and light, the single-scattering
// formula for a ray that passes near the light (timed and unwarped), the
// phase function's ratio at the backscatter angle, an occluder's shadow on
// the ray, a plane that ends the medium's light; then GL against CPU.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "support/AnalyticScenes.h"
#include "support/Simpson.h"
#include "support/TestBackends.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::render {
namespace {

using capture::RenderJob;
using capture::VolumeCollector;
constexpr double kPi = 3.14159265358979323846;

using test::simpson;

// The s where a monotonic path(s) on [lo, hi] reaches q (bisection).
double solve(const std::function<double(double)>& path, double q, double lo, double hi) {
  const bool increasing = path(hi) >= path(lo);
  if (increasing ? q <= path(lo) : q >= path(lo)) return lo;
  if (increasing ? q >= path(hi) : q <= path(hi)) return hi;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if ((path(mid) < q) == increasing) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

// A scene the camera rays do not see: one small quad behind the camera at
// the origin, which looks along -z (no surface in view, no ray ends).
struct MediumScene {
  scene::Scene scene;
  RenderJob job;
  explicit MediumScene(int32_t side = 3) {
    test::addQuad(scene, glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0, 0, -1), 0.2f, glm::vec3(0.5f));
    job.scene = &scene;
    job.camera().position_world = glm::vec3(0.0f);
    job.camera().look_at_world = glm::vec3(0.0f, 0.0f, -1.0f);
    job.camera().fov_y_deg = 10.0f;
    job.camera().width = job.camera().height = side;
    job.light.position_world = glm::vec3(0.0f);
    job.light.intensity_W_per_sr = glm::vec3(2.0f, 1.0f, 0.5f);
    job.settings.indirect.enabled = false;
    job.settings.pixel_footprint = false;  // closed forms at the pixel centres
    job.settings.medium.sigma_a_per_m = glm::vec3(0.05f, 0.1f, 0.0f);
    job.settings.medium.sigma_s_per_m = glm::vec3(0.2f, 0.1f, 0.05f);
  }
  // `bins` bins of `width_m` optical path from `start_m`, index eta.
  void axis(double start_m, double width_m, int32_t bins, double eta = 1.0) {
    job.settings.time = TimeAxis{start_m / kSpeedOfLight_m_per_s, width_m / kSpeedOfLight_m_per_s,
                                 bins, eta};
  }
};

class MediumDirectGLTest : public test::BackendTest {
 protected:
  VolumeCollector render(const RenderJob& job, capture::RenderResult* result = nullptr) const {
    VolumeCollector out(capture::imageWidth(job.imager), capture::imageHeight(job.imager),
                        job.settings.time, 3);
    const capture::RenderResult r = renderer()->render(job, out);
    if (result != nullptr) *result = r;
    return out;
  }
};

// The lidar equation: with the camera and a point light together, pixel
// radiance in bin k is sigma_s p(pi) I times the integral of exp(-2 sigma_t
// s) / s^2 over the bin's depths s = path / (2 eta), in every pixel; the
// light past the axis is counted off it.
TEST_P(MediumDirectGLTest, CoLocatedLightFollowsTheLidarEquation) {
  MediumScene m;
  const double eta = 1.33, width = 0.2;
  const int32_t bins = 40;
  m.axis(0.0, width, bins, eta);
  capture::RenderResult result;
  const VolumeCollector out = render(m.job, &result);
  const capture::Medium& medium = m.job.settings.medium;
  const double pBack = 1.0 / (4.0 * kPi);
  double after = 0.0;  // expected light past the axis, all pixels and channels
  for (int c = 0; c < 3; ++c) {
    const double sigmaT = medium.sigmaT()[c];
    const auto f = [&](double s) { return std::exp(-2.0 * sigmaT * s) / (s * s); };
    const double scale = medium.sigma_s_per_m[c] * pBack * m.job.light.intensity_W_per_sr[c];
    for (int k = 1; k < bins; ++k) {  // bin 0 touches s = 0, the emitter
      const double expected = scale * simpson(f, k * width / (2 * eta), (k + 1) * width / (2 * eta));
      for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 3; ++x) {
          EXPECT_NEAR(out.direct.at(y, x, k, c), expected, 1e-3 * expected)
              << "pixel " << x << "," << y << " bin " << k << " channel " << c;
        }
      }
    }
    // Past the axis: s from D_end to 60 m (exp(-2 sigma_t s) / s^2 < 1e-9 of bin 1 there).
    const double end = bins * width / (2 * eta);
    after += 9.0 * scale * simpson(f, end, 60.0, 20000);
    // Bin 0 is bounded by the emitter's size: finite, and the largest.
    EXPECT_TRUE(std::isfinite(out.direct.at(1, 1, 0, c)));
    EXPECT_GT(out.direct.at(1, 1, 0, c), out.direct.at(1, 1, 1, c));
  }
  EXPECT_NEAR(result.offAxis.after, after, 2e-3 * after);
  EXPECT_EQ(result.offAxis.before, 0.0);
}

// A ray passing 3 cm from a point light (outside the pixel: a 1-degree
// field of view does not see the light itself), Henyey-Greenstein g = 0.5
// (forward scattering before the closest approach, back after it): each bin
// against the formula, with the emitter's radius R bounding 1/r^2 as
// 1/(r^2 + R^2) ((R/r)^2 is 1e-3 here), integrated densely over the bin's
// interval of s, timed through the camera (path r + s: one bin holds the
// closest approach and all the forward light, an angle interval wider than
// pi/2) and unwarped (path r: two branches).
void expectPassingRay(const MediumDirectGLTest& test, bool unwarp,
                      const std::function<VolumeCollector(const RenderJob&)>& render) {
  MediumScene m(1);
  const glm::dvec3 light(0.03, 0.0, -1.5);
  m.job.light.position_world = glm::vec3(light);
  m.job.camera().fov_y_deg = 1.0f;
  m.job.settings.medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
  m.job.settings.medium.g = 0.5f;
  const double width = 0.05;
  const int32_t bins = unwarp ? 40 : 60;
  m.axis(unwarp ? 0.0 : 1.45, width, bins);
  m.job.settings.time.camera_unwarp = unwarp;
  const VolumeCollector out = render(m.job);
  const capture::Medium& medium = m.job.settings.medium;
  const auto r = [&](double s) { return glm::length(glm::dvec3(0.0, 0.0, -s) - light); };
  const auto path = [&](double s) { return unwarp ? r(s) : r(s) + s; };
  // Monotonic pieces of the path over s in [0, 20 m].
  std::vector<std::pair<double, double>> pieces;
  if (unwarp) {
    pieces = {{0.0, 1.5}, {1.5, 20.0}};
  } else {
    pieces = {{0.0, 20.0}};
  }
  double peak = 0.0;
  std::vector<glm::dvec3> expected(bins, glm::dvec3(0.0));
  for (int c = 0; c < 3; ++c) {
    const double sigmaT = medium.sigmaT()[c];
    const auto f = [&](double s) {
      const glm::dvec3 u = (glm::dvec3(0.0, 0.0, -s) - light) / r(s);  // light's travel
      const double cosTheta = glm::dot(u, glm::dvec3(0.0, 0.0, 1.0));  // toward the camera
      const double g = medium.g;
      const double p = (1 - g * g) / (4 * kPi * std::pow(1 + g * g - 2 * g * cosTheta, 1.5));
      const double radius = physics::MEDIUM_EMITTER_RADIUS_M;
      return medium.sigma_s_per_m[c] * p * m.job.light.intensity_W_per_sr[c] *
             std::exp(-sigmaT * (r(s) + s)) / (r(s) * r(s) + radius * radius);
    };
    for (int k = 0; k < bins; ++k) {
      const double lo = m.job.settings.time.start_m() + k * width, hi = lo + width;
      for (const auto& [a, b] : pieces) {
        double s0 = solve(path, lo, a, b), s1 = solve(path, hi, a, b);
        if (s1 < s0) std::swap(s0, s1);
        // Split at the closest approach, where 1/r^2 peaks.
        const double split = std::clamp(1.5, s0, s1);
        expected[k][c] += simpson(f, s0, split, 20000) + simpson(f, split, s1, 20000);
      }
      peak = std::max(peak, expected[k][c]);
    }
  }
  int compared = 0;
  for (int k = 0; k < bins; ++k) {
    for (int c = 0; c < 3; ++c) {
      const double e = expected[k][c];
      EXPECT_NEAR(out.direct.at(0, 0, k, c), e, 1e-3 * e + 1e-7 * peak)
          << (test.GetParam() == test::TestBackend::Cpu ? "cpu" : "gl") << " bin " << k
          << " channel " << c;
      if (e > 1e-4 * peak) ++compared;  // held to 1e-3 relative
    }
  }
  // Beside the peak (the forward light and the closest approach, in one
  // bin), a tail of bins above 1e-4 of it.
  EXPECT_GT(compared, 36);
}

TEST_P(MediumDirectGLTest, RayPassingTheLightMatchesTheDenseIntegral) {
  expectPassingRay(*this, false, [&](const RenderJob& job) { return render(job); });
}

TEST_P(MediumDirectGLTest, UnwarpedRayPassingTheLightMatchesTheDenseIntegral) {
  expectPassingRay(*this, true, [&](const RenderJob& job) { return render(job); });
}

// The co-located return scales with the phase function at pi: Henyey-
// Greenstein's (1 - g) / (1 + g)^2 and Rayleigh's 3/2 of the isotropic one,
// bin by bin.
TEST_P(MediumDirectGLTest, PhaseFunctionScalesTheBackscatterByItsValueAtPi) {
  MediumScene m(1);
  m.axis(0.0, 0.1, 30);
  const VolumeCollector isotropic = render(m.job);
  m.job.settings.medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
  m.job.settings.medium.g = 0.6f;
  const VolumeCollector hg = render(m.job);
  m.job.settings.medium.phase = physics::PHASE_RAYLEIGH;
  const VolumeCollector rayleigh = render(m.job);
  const double g = 0.6;
  for (int k = 0; k < 30; ++k) {
    for (int c = 0; c < 3; ++c) {
      const double iso = isotropic.direct.at(0, 0, k, c);
      ASSERT_GT(iso, 0.0);
      EXPECT_NEAR(hg.direct.at(0, 0, k, c) / iso, (1 - g) / ((1 + g) * (1 + g)), 2e-5);
      EXPECT_NEAR(rayleigh.direct.at(0, 0, k, c) / iso, 1.5, 2e-5);
    }
  }
}

// An occluder between the light (0.5 m beside the camera) and the ray's
// depths 3 to 5 m: the bins of those depths lose all their light, the others
// keep what they had without it.
TEST_P(MediumDirectGLTest, AnOccluderRemovesTheLightOfTheRayItShadows) {
  MediumScene m(1);
  m.job.light.position_world = glm::vec3(0.5f, 0.0f, 0.0f);
  const double width = 0.1;
  m.axis(0.0, width, 120);
  const VolumeCollector open = render(m.job);
  // Facing +x at x = 0.25 (the midpoint of light and ray), z in [-2.5, -1.5]:
  // it shadows the ray's points at z in [-5, -3]; the camera does not see it.
  test::addQuad(m.scene, glm::vec3(0.25f, 0.0f, -2.0f), glm::vec3(1, 0, 0), 1.0f,
                glm::vec3(0.5f));
  const VolumeCollector shadowed = render(m.job);
  const auto path = [](double s) { return std::sqrt(0.25 + s * s) + s; };
  int dark = 0, lit = 0;
  for (int k = 0; k < 120; ++k) {
    const double s0 = solve(path, k * width, 0.0, 50.0);
    const double s1 = solve(path, (k + 1) * width, 0.0, 50.0);
    if (s1 <= 0.0) continue;  // before the light's path reaches the ray
    for (int c = 0; c < 3; ++c) {
      const float before = open.direct.at(0, 0, k, c), after = shadowed.direct.at(0, 0, k, c);
      ASSERT_GT(before, 0.0f) << "bin " << k;
      if (s0 > 3.05 && s1 < 4.95) {
        EXPECT_EQ(after, 0.0f) << "bin " << k << " channel " << c;
        ++dark;
      } else if (s1 < 2.95 || s0 > 5.05) {
        EXPECT_NEAR(after, before, 1e-6f * before) << "bin " << k << " channel " << c;
        ++lit;
      }
    }
  }
  EXPECT_GT(dark, 3 * 30);
  EXPECT_GT(lit, 3 * 60);
}

// A plane facing the co-located camera and light at 2.03 m: the medium's
// light ends at it (nothing after its bin), the bins before follow the lidar
// equation, and its bin holds the medium's light up to the plane plus the
// surface's light (no more than in vacuum, no less than that attenuated by
// exp(-2 sigma_t r): the attenuation is another part's).
TEST_P(MediumDirectGLTest, APlaneEndsTheMediumLightAndStillReturnsItsOwn) {
  MediumScene m(1);
  const float r = 2.03f;
  test::addQuad(m.scene, glm::vec3(0.0f, 0.0f, -r), glm::vec3(0, 0, 1), 4.0f, glm::vec3(0.5f));
  const double width = 0.1;
  m.axis(0.0, width, 60);
  const VolumeCollector withMedium = render(m.job);
  RenderJob vacuumJob = m.job;
  vacuumJob.settings.medium = capture::Medium{};
  const VolumeCollector vacuum = render(vacuumJob);
  const int plane = static_cast<int>(std::floor(2.0 * r / width));  // bin 40
  ASSERT_GT(vacuum.direct.at(0, 0, plane, 0), 0.0f);
  const capture::Medium& medium = m.job.settings.medium;
  for (int c = 0; c < 3; ++c) {
    const double sigmaT = medium.sigmaT()[c];
    const auto f = [&](double s) { return std::exp(-2.0 * sigmaT * s) / (s * s); };
    const double scale =
        medium.sigma_s_per_m[c] / (4.0 * kPi) * m.job.light.intensity_W_per_sr[c];
    for (int k = 1; k < plane; ++k) {
      const double expected = scale * simpson(f, k * width / 2, (k + 1) * width / 2);
      EXPECT_NEAR(withMedium.direct.at(0, 0, k, c), expected, 1e-3 * expected) << "bin " << k;
    }
    for (int k = plane + 1; k < 60; ++k) EXPECT_EQ(withMedium.direct.at(0, 0, k, c), 0.0f);
    const double mediumPart = scale * simpson(f, plane * width / 2, r);
    const double surface = withMedium.direct.at(0, 0, plane, c) - mediumPart;
    const double inVacuum = vacuum.direct.at(0, 0, plane, c);
    EXPECT_LE(surface, inVacuum * (1 + 1e-4));
    EXPECT_GE(surface, inVacuum * std::exp(-2.0 * sigmaT * r) * (1 - 1e-4));
  }
}

TOFSIM_ON_BOTH_BACKENDS(MediumDirectGLTest);

// GL against CPU on a spot light beside the camera (its cone's rim on the
// rays), Henyey-Greenstein scattering, a plane some rays meet and some miss,
// 2 x 2 samples a pixel, pixel footprints (the surface's light spread, as
// the backends' G-buffers differ by float rounding): each pixel's bins agree
// to 2e-3 of its largest.
TEST(MediumDirectAgreementGLTest, GlMatchesCpu) {
  MediumScene m(8);
  test::addQuad(m.scene, glm::vec3(0.1f, 0.0f, -2.0f), glm::vec3(0, 0, 1), 0.25f,
                glm::vec3(0.6f));
  m.job.camera().fov_y_deg = 20.0f;
  m.job.light.type = capture::Light::Type::Spot;
  m.job.light.position_world = glm::vec3(0.1f, 0.05f, 0.0f);
  m.job.light.direction_world = glm::normalize(glm::vec3(-0.02f, 0.0f, -1.0f));
  m.job.light.cone_half_angle_deg = 12.0f;
  m.job.light.cone_falloff_deg = 4.0f;
  m.job.settings.medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
  m.job.settings.medium.g = 0.7f;
  m.job.settings.pixel_samples = 2;
  m.job.settings.pixel_footprint = true;
  m.axis(0.0, 0.1, 60);
  VolumeCollector gl(8, 8, m.job.settings.time, 3), cpu(8, 8, m.job.settings.time, 3);
  test::makeTestRenderer(test::TestBackend::Gl)->render(m.job, gl);
  test::makeTestRenderer(test::TestBackend::Cpu)->render(m.job, cpu);
  int lit = 0;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      for (int c = 0; c < 3; ++c) {
        float peak = 0.0f;
        for (int k = 0; k < 60; ++k) peak = std::max(peak, cpu.direct.at(y, x, k, c));
        lit += peak > 0.0f ? 1 : 0;  // the corner rays leave the cone
        for (int k = 0; k < 60; ++k) {
          EXPECT_NEAR(gl.direct.at(y, x, k, c), cpu.direct.at(y, x, k, c), 2e-3f * peak)
              << "pixel " << x << "," << y << " bin " << k << " channel " << c;
        }
      }
    }
  }
  EXPECT_GT(lit, 3 * 40);
}

}  // namespace
}  // namespace tofsim::render
