// Medium VPLs (issue 42, item 4; core/physics/medium_vpls.md): the light's
// paths that scatter in a scattering medium before any surface. Their
// energy (the power extinguished per channel, against the box's integral),
// their determinism, and the light they give a floor point through the CPU
// gather (vplEmitterCosine, vplScatter's phase function, the geometry clamp,
// exact visibility) against a double-precision volume integral, each within
// four standard deviations of the estimate, derived from the same integrals.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <vector>

#include "support/AnalyticScenes.h"
#include "support/GivenVplsCpuBackend.h"
#include "support/MediumPoints.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/BounceVpls.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/ir/MediumVpl.h"
#include "tofsim/ir/MediumVpls.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::cpu {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Gauss-Legendre, 8 nodes on [-1, 1].
constexpr double kNodes[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                              -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                              0.7966664774136267,  0.9602898564975363};
constexpr double kWeights[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                0.2223810344533745, 0.1012285362903763};

// sum over [a, b) of f by Gauss-Legendre on the pieces between `cuts` (sorted).
void integratePieces(std::vector<double> cuts, const std::function<void(double, double)>& f) {
  std::sort(cuts.begin(), cuts.end());
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double a = cuts[k], b = cuts[k + 1];
    if (!(b > a)) continue;
    for (int i = 0; i < 8; ++i) f(0.5 * (a + b) + 0.5 * (b - a) * kNodes[i], 0.5 * (b - a) * kWeights[i]);
  }
}

// Geometric cuts about `centre` (both sides) from 1e-4 out to `reach`, in [lo, hi].
std::vector<double> cutsAbout(double centre, double reach, double lo, double hi) {
  std::vector<double> cuts{lo, hi};
  for (double e = 1e-4; e < reach; e *= 1.5) {
    for (const double c : {centre - e, centre + e}) {
      if (c > lo && c < hi) cuts.push_back(c);
    }
  }
  return cuts;
}

// ---------------------------------------------------------------------------
// Energy: a point light at the centre of a closed cube of half side a emits
// 4 pi I; the medium extinguishes I integral (1 - exp(-sigma_t D(w))) dw of
// it per channel, sigma_s / sigma_t of that scattered. The medium VPLs'
// fluxes are an unbiased estimate of the extinguished power, channel by
// channel, in a medium whose sigma_t differs per channel (the free flight
// is drawn in their mean).

struct BoxMoments {
  glm::dvec3 mean{0.0}, second{0.0};  // E[w] and E[w^2] over directions and t
};

// Over the cube's directions (six faces alike; one face z = a by symmetry,
// its direction density a / r^3 dA), the mean of 1 - exp(-sigma D) and of the
// truncated free flight's squared weight E_t[w^2 | D] (sampleFreeFlight:
// w = sigma exp(-sigma t) (1 - exp(-s D)) / (s exp(-s t)), s the mean).
BoxMoments boxMoments(const glm::dvec3& sigmaT, double a) {
  const double s = (sigmaT.x + sigmaT.y + sigmaT.z) / 3.0;
  BoxMoments m;
  std::vector<double> cuts;
  for (int k = 0; k <= 40; ++k) cuts.push_back(-a + 2.0 * a * k / 40.0);
  integratePieces(cuts, [&](double x, double wx) {
    integratePieces(cuts, [&](double y, double wy) {
      const double r = std::sqrt(a * a + x * x + y * y);
      const double dw = a / (r * r * r) * wx * wy * 6.0 / (4.0 * kPi);  // fraction of the sphere
      const double reach = 1.0 - std::exp(-s * r);
      for (int c = 0; c < 3; ++c) {
        const double sc = sigmaT[c], k = 2.0 * sc - s;
        const double tail = std::abs(k) > 1e-12 ? (1.0 - std::exp(-k * r)) / k : r;
        m.mean[c] += dw * (1.0 - std::exp(-sc * r));
        m.second[c] += dw * sc * sc * reach / s * tail;
      }
    });
  });
  return m;
}

TEST(MediumVplsTest, TheLightsMediumVplsCarryThePowerTheBoxsMediumExtinguishes) {
  const float a = 1.0f;
  const scene::Scene scene = test::makeClosedBox(2.0f * a, glm::vec3(0.5f));
  const rays::RayScene rays(scene, 1);
  capture::Light light;
  light.position_world = glm::vec3(0.0f);
  light.intensity_W_per_sr = glm::vec3(1.0f, 2.0f, 0.5f);
  capture::Medium medium;
  medium.sigma_a_per_m = glm::vec3(0.2f, 0.1f, 0.4f);
  medium.sigma_s_per_m = glm::vec3(0.3f, 0.9f, 1.6f);  // sigma_t 0.5, 1, 2
  const std::size_t n = 20000;
  const std::vector<ir::Vpl> vpls = ir::lightMediumVpls(rays, light, medium, n, 7, 1.0, 2);
  ASSERT_EQ(vpls.size(), n);  // a closed box: every ray scatters somewhere
  glm::dvec3 sum(0.0);
  for (const ir::Vpl& v : vpls) {
    ASSERT_TRUE(ir::isMediumVpl(v));
    ASSERT_EQ(v.vertex.model, physics::VERTEX_MEDIUM);
    const glm::vec3 x(v.positionPath);
    ASSERT_LE(glm::max(glm::abs(x.x), glm::max(glm::abs(x.y), glm::abs(x.z))), a);
    // Its path is the way from the light, its light came from the light.
    ASSERT_NEAR(v.positionPath.w, glm::length(x), 1e-5f);
    ASSERT_NEAR(glm::dot(glm::vec3(v.incoming), -x / glm::length(x)), 1.0f, 1e-5f);
    sum += glm::dvec3(glm::vec3(v.flux)) * glm::dvec3(medium.albedo());
  }
  const BoxMoments m = boxMoments(glm::dvec3(medium.sigmaT()), a);
  for (int c = 0; c < 3; ++c) {
    const double power = 4.0 * kPi * light.intensity_W_per_sr[c];
    const double albedo = medium.albedo()[c];
    const double expected = power * albedo * m.mean[c];
    const double sigma = power * albedo * std::sqrt((m.second[c] - m.mean[c] * m.mean[c]) / n);
    EXPECT_NEAR(sum[c], expected, 4.0 * sigma + 1e-5 * expected)
        << "channel " << c << ": sigma " << sigma << " (" << sigma / expected << " relative)";
  }
}

TEST(MediumVplsTest, TheLightsMediumVplsAreTheSameBytesOnAnyThreadsAndNoneWithoutScattering) {
  const scene::Scene scene = test::makeClosedBox(2.0f, glm::vec3(0.5f));
  const rays::RayScene rays(scene, 1);
  capture::Light light;
  light.type = capture::Light::Type::Spot;
  light.cone_half_angle_deg = 40.0f;
  light.cone_falloff_deg = 10.0f;
  capture::Medium medium;
  medium.sigma_s_per_m = glm::vec3(0.5f);
  const std::vector<ir::Vpl> one = ir::lightMediumVpls(rays, light, medium, 1000, 3, 1.33, 1);
  const std::vector<ir::Vpl> four = ir::lightMediumVpls(rays, light, medium, 1000, 3, 1.33, 4);
  ASSERT_EQ(one.size(), four.size());
  ASSERT_EQ(std::memcmp(one.data(), four.data(), one.size() * sizeof(ir::Vpl)), 0);
  // A spot's rays stay in its cone; the path is eta times the way.
  for (const ir::Vpl& v : one) {
    const glm::vec3 x(v.positionPath);
    EXPECT_GE(glm::dot(x / glm::length(x), light.direction_world),
              std::cos(glm::radians(40.0f)) - 1e-5f);
    EXPECT_NEAR(v.positionPath.w, 1.33f * glm::length(x), 1e-5f);
  }
  medium.sigma_s_per_m = glm::vec3(0.0f);
  medium.sigma_a_per_m = glm::vec3(0.5f);
  EXPECT_TRUE(ir::lightMediumVpls(rays, light, medium, 1000, 3, 1.0, 1).empty());
}

// Later bounces in a grey scattering medium inside a closed box: every
// child ray ends in the medium (a medium child, its flux the power
// extinguished there) or on a wall (a Lambertian child, albedo P / pi), and
// in a grey medium the free flight's weights are exactly 1, so the power the
// children receive is the power their parents send, to float rounding: a
// medium parent's albedo x its extinguished power (phase sampling), a
// Lambertian parent's pi x its albedo Phi / pi (cosine sampling).
TEST(MediumVplsTest, LaterBouncesThroughTheMediumConserveThePowerTheParentsSend) {
  const float wallAlbedo = 0.5f;
  const scene::Scene scene = test::makeClosedBox(2.0f, glm::vec3(wallAlbedo));
  const rays::RayScene rays(scene, 1);
  ir::BounceTracing tracing;
  tracing.medium.sigma_s_per_m = glm::vec3(0.6f);
  tracing.medium.sigma_a_per_m = glm::vec3(0.2f);
  tracing.medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
  tracing.medium.g = 0.7f;
  const ir::Vpl mediumParent = ir::mediumVpl(glm::vec3(0.2f, -0.1f, 0.3f), 1.0f, glm::vec3(2.0f),
                                             glm::vec3(0.0f, 0.0f, 1.0f), tracing.medium, 0.0f);
  ir::Vpl wallParent;  // on the floor z = -1, Lambertian: albedo Phi / pi
  wallParent.positionPath = glm::vec4(0.1f, 0.2f, -1.0f, 1.5f);
  wallParent.normal = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f);
  wallParent.flux = glm::vec4(glm::vec3(0.3f), 0.0f);
  wallParent.vertex = physics::scatterVertex(physics::VERTEX_LAMBERTIAN, glm::vec3(wallAlbedo), 0.0f, 1.0f);
  const double pi = kPi;
  const struct {
    ir::Vpl parent;
    double sent;  // W
  } cases[] = {{mediumParent, 0.75 * 2.0}, {wallParent, pi * 0.3}};
  for (const auto& [parent, sent] : cases) {
    const std::size_t count = 4000;
    const std::vector<ir::Vpl> children =
        ir::traceBounce(rays, {parent}, count, 2, 5, 1.0, tracing);
    ASSERT_EQ(children.size(), count);  // a closed box: every ray ends somewhere
    double received = 0.0;
    std::size_t inMedium = 0;
    for (const ir::Vpl& c : children) {
      const bool medium = ir::isMediumVpl(c);
      inMedium += medium;
      // A medium child's flux is the power extinguished at it (W); a wall's
      // holds its scatter, albedo P / pi.
      received += medium ? c.flux.r : c.flux.r * pi / wallAlbedo;
      if (medium) {
        EXPECT_EQ(c.vertex.model, physics::VERTEX_MEDIUM);
        EXPECT_GT(c.positionPath.w, parent.positionPath.w);
      }
    }
    EXPECT_GT(inMedium, count / 10);
    EXPECT_LT(inMedium, count);
    EXPECT_NEAR(received, sent, 1e-4 * sent) << (ir::isMediumVpl(parent) ? "medium" : "wall")
                                              << " parent";
  }
}

// ---------------------------------------------------------------------------
// A point light at height h above a floor (albedo rho) in a medium: the floor
// point y right below it receives, through the medium,
//   L = integral over the medium's points m of
//       I exp(-sigma r) / r^2  sigma_s p(w . (y - m) / d)  (rho / pi)
//       min(cos_y / d^2, clamp) exp(-sigma (d + |y - c|)),
// r = |m - l|, d = |y - m|, w the light's direction of travel, in the bin of
// r + d + |y - c|. Symmetric about the vertical through l and y: a 2D
// integral in (r, theta) from the downward axis, cut at the windows' path
// edges and geometrically about the floor point. Its variance over N VPLs
// is (integral F^2 / pdf - L^2) / N, pdf the VPLs' density of m
// (lightMediumVpls: s exp(-s r) / ((1 - exp(-s D)) 4 pi r^2)).

using GivenVplsBackend = test::GivenVplsCpuBackend;

struct FloorScene {
  double h = 1.0, halfFloor = 20.0, rho = 0.5, intensity = 1.0;
  double sigmaS = 0.3, sigmaA = 0.2, clamp = 100.0;
  // Close to the floor point: a camera ray of 1.4 cm, so that light scattered
  // into it on the way (the camera ray's own medium points) stays far below
  // the statistics' spread; the leg's time and transmittance are the test's.
  glm::dvec3 camera{0.0, -0.01, 0.01};
  capture::Medium medium() const {
    capture::Medium m;
    m.sigma_s_per_m = glm::vec3(static_cast<float>(sigmaS));
    m.sigma_a_per_m = glm::vec3(static_cast<float>(sigmaA));
    return m;
  }
};

struct Window {
  double lo_m, hi_m;     // path
  double mean = 0.0;     // integral of F
  double second = 0.0;   // integral of F^2 / pdf
};

void integrateFloorPoint(const FloorScene& s, int phase, double g, std::vector<Window>& windows) {
  const double sigma = s.sigmaS + s.sigmaA, camLeg = glm::length(s.camera);
  const double edgeAngle = std::atan(s.halfFloor / s.h), rFar = 80.0;
  std::vector<double> thetaCuts = cutsAbout(0.0, kPi / 2.0, 0.0, kPi);
  thetaCuts.push_back(kPi / 2.0);
  thetaCuts.push_back(edgeAngle);
  for (int k = 1; k < 40; ++k) thetaCuts.push_back(kPi / 2.0 + k * (kPi / 2.0) / 40.0);
  integratePieces(thetaCuts, [&](double theta, double wTheta) {
    const double ct = std::cos(theta), st = std::sin(theta);
    // The floor's hit (the light's ray ends there), or none past its edge.
    const bool hitsFloor = theta < edgeAngle;
    const double D = hitsFloor ? s.h / ct : ir::kNoHit;
    const double rEnd = hitsFloor ? D : rFar;
    std::vector<double> rCuts = cutsAbout(s.h, 1.0, 0.0, rEnd);
    for (double r = 1.0; r < rEnd; r += 1.0) rCuts.push_back(r);
    for (const Window& w : windows) {
      for (const double q : {w.lo_m, w.hi_m}) {  // r + d = q - camLeg
        const double Q = q - camLeg;
        const double r = (Q * Q - s.h * s.h) / (2.0 * (Q - s.h * ct));
        if (Q > s.h && r > 0.0 && r < rEnd) rCuts.push_back(r);
      }
    }
    const double reach = hitsFloor ? 1.0 - std::exp(-sigma * D) : 1.0;
    integratePieces(rCuts, [&](double r, double wR) {
      const double mz = s.h - r * ct;  // height above the floor
      const double d = std::sqrt(std::max(0.0, s.h * s.h + r * r - 2.0 * s.h * r * ct));
      if (!(mz > 0.0) || !(d > 0.0)) return;
      const double cosY = mz / d;
      const double mu = (s.h * ct - r) / d;  // w . (y - m) / d
      const double p = phase == physics::PHASE_ISOTROPIC
                           ? 1.0 / (4.0 * kPi)
                           : (1.0 - g * g) / (4.0 * kPi * std::pow(1.0 + g * g - 2.0 * g * mu, 1.5));
      const double F = s.intensity * std::exp(-sigma * r) / (r * r) * s.sigmaS * p * s.rho / kPi *
                       std::min(cosY / (d * d), s.clamp) * std::exp(-sigma * (d + camLeg));
      const double pdf = sigma * std::exp(-sigma * r) / (reach * 4.0 * kPi * r * r);
      const double dV = 2.0 * kPi * r * r * st * wR * wTheta;
      const double path = r + d + camLeg;
      for (Window& w : windows) {
        if (path >= w.lo_m && path < w.hi_m) {
          w.mean += F * dV;
          w.second += F * F / pdf * dV;
        }
      }
    });
  });
}

void expectFloorPointMatchesTheIntegral(int phase, double g) {
  const FloorScene s;
  scene::Scene scene = test::makePlane(2.0f * static_cast<float>(s.halfFloor),
                                       glm::vec3(static_cast<float>(s.rho)));
  const rays::RayScene rays(scene, 1);
  capture::RenderJob job;
  job.scene = &scene;
  capture::PointSetImager imager;
  imager.width = 1;
  imager.points_world = {glm::vec3(0.0f)};
  imager.origin_world = glm::vec3(s.camera);
  job.imager = imager;
  job.light.position_world = glm::vec3(0.0f, 0.0f, static_cast<float>(s.h));
  job.light.intensity_W_per_sr = glm::vec3(static_cast<float>(s.intensity));
  job.settings.medium = s.medium();
  job.settings.medium.phase = phase;
  job.settings.medium.g = static_cast<float>(g);
  job.settings.indirect.enabled = true;
  job.settings.indirect.medium_vpls = 0;  // the given ones only
  job.settings.indirect.visibility = capture::Visibility::Exact;  // no ISMs to build
  job.settings.indirect.geometry_term_clamp_per_m2 = s.clamp;
  job.settings.pixel_footprint = false;
  const double binWidth_m = 0.05;
  job.settings.time = TimeAxis{0.0, binWidth_m / kSpeedOfLight_m_per_s, 2000};
  const std::size_t n = 1 << 16;
  std::vector<ir::Vpl> vpls =
      ir::lightMediumVpls(rays, job.light, job.settings.medium, n, 11, 1.0, 2);
  capture::VolumeCollector volume(1, 1, job.settings.time, capture::kChannels);
  auto backend = std::make_unique<GivenVplsBackend>(std::move(vpls));
  backend->setSurfaces(std::make_unique<ir::SurfaceImage>(test::givenSamples(
                           {glm::vec3(0.0f)}, {physics::VERTEX_LAMBERTIAN},
                           glm::vec3(static_cast<float>(s.rho)), glm::vec3(0, 0, 1),
                           glm::vec3(0, 0, 1))),
                       nullptr);
  ir::IrRenderer(std::move(backend)).render(job, volume);

  std::vector<Window> windows;
  const double edges[] = {1.0, 1.1, 1.25, 1.6, 2.1, 3.1, 4.6, 8.6, 98.6};
  for (std::size_t k = 0; k + 1 < std::size(edges); ++k) windows.push_back({edges[k], edges[k + 1]});
  integrateFloorPoint(s, phase, g, windows);
  for (const Window& w : windows) {
    double got = 0.0;
    const int first = static_cast<int>(std::lround(w.lo_m / binWidth_m));
    const int last = static_cast<int>(std::lround(w.hi_m / binWidth_m));
    for (int t = first; t < last; ++t) got += volume.indirect.at(0, 0, t, 0);
    const double sigma = std::sqrt(std::max(0.0, w.second - w.mean * w.mean) / n);
    EXPECT_NEAR(got, w.mean, 4.0 * sigma + 2e-3 * w.mean)
        << "paths [" << w.lo_m << ", " << w.hi_m << ") m: sigma " << sigma << " ("
        << sigma / w.mean << " relative)";
  }
}

TEST(MediumVplsTest, AFloorPointsLightFromAnIsotropicMediumMatchesTheVolumeIntegral) {
  expectFloorPointMatchesTheIntegral(physics::PHASE_ISOTROPIC, 0.0);
}

TEST(MediumVplsTest, AFloorPointsLightFromAForwardScatteringMediumMatchesTheVolumeIntegral) {
  expectFloorPointMatchesTheIntegral(physics::PHASE_HENYEY_GREENSTEIN, 0.6);
}

}  // namespace
}  // namespace tofsim::cpu
