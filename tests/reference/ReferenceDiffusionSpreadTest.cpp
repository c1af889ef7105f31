// Multiple scattering in the reference far from the source and late, where
// diffusion theory is accurate (issue 42; core/physics/medium_diffusion.md,
// "Far and late"): the light leaving a semi-infinite medium spreads from
// where it entered as the time-domain closed form says (Patterson, Chance
// and Wilson 1989 with Haskell et al. 1994's extrapolated boundary;
// DiffusionClosedForm.h).
//
// In Patterson's form the light that enters at distance rho from a
// detector and leaves there after a geometric path l is F(l) exp(-rho^2 /
// (4 D l)): the distance only enters the Gaussian, whatever the absorption,
// the source depth, the boundary's extrapolation and the P1 radiance put in
// F. So the share of the light leaving at l that entered beyond a radius R
// around the detector depends on D = 1 / (3 mu_s') alone, mu_s' = mu_s
// (1 - g): it tests the medium's sigma_s and the phase function's g, not
// the approximations F holds.
//
// The medium is a region (a closed box, an invisible index-matched
// interface: the light that leaves never returns) under vacuum. A camera
// just above its top face looks straight in; a spot light 2 m above the
// camera lights a disk of the face around it. Rendered twice with the same
// seed, with the disk's radius 30 l* (A) and 10 l* (B): the light only
// changes the weights of next-event estimation, not the paths, so B is path
// by path the part of A that entered within 10 l*, and 1 - B / A is the
// share that entered 10-30 l* away. The camera's paths start at the
// detector and need only reach the lit face again, so the estimate has no
// rare paths (ReferenceSemiInfiniteTest's point source inside the medium
// has: its paths must pass the light, which limits it to 5 l*).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "DiffusionClosedForm.h"
#include "RenderReference.h"
#include "support/AnalyticScenes.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/scene/RegionMeshes.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::reference {
namespace {

using namespace capture;
namespace dif = test::diffusion;

// mu_s' 100 /m (l* 1 cm), albedo 0.9975.
constexpr double kMuS = 200.0, kG = 0.5, kMuA = 0.5, kEta = 1.33;
constexpr double kMuSPrime = kMuS * (1.0 - kG);
constexpr double kOuter = 0.30, kInner = 0.10;  // the lit disks' radii, m: 30 and 10 l*
constexpr double kLight = 2.0, kCamera = 1e-3;  // heights over the face, m
constexpr double kBin = 0.02;                   // geometric path in the medium, m
constexpr int kBins = 45;                       // l from 0 to 90 l*
constexpr int kFirst = 25;                      // the compared window: l from 50 to 90 l*
constexpr double kFovDeg = 20.0;
constexpr int kSide = 8, kPaths = 384;  // 24 576 paths a render

// The axis: bin b holds the optical paths of light that enters the face
// under the light (kLight of vacuum), travels l in [b, b + 1) kBin in the
// medium (eta l) and leaves under the camera (kCamera of vacuum).
TimeAxis axis() {
  const double start_m = kLight + kCamera;
  TimeAxis a{start_m / kSpeedOfLight_m_per_s, kEta * kBin / kSpeedOfLight_m_per_s, kBins};
  return a;
}

// The closed form's bins for the disk of radius `radius` lit by the spot
// (intensity 1, irradiance H / (H^2 + r^2)^(3/2) at r): every entry point a
// source at depth z0 = 1 / mu_s' of the power entering there (diffusion's
// stand-in for a pencil beam), its light timed from the light (the
// vacuum leg sqrt(H^2 + r^2)), seen at the detector as the P1 radiance.
std::vector<double> closedForm(double radius, double muSPrime) {
  const dif::SemiInfinite unit{kMuA, muSPrime, 0.0, 1.0 / muSPrime, 2.0 / (3.0 * muSPrime)};
  const double cosine = dif::meanImageCosine(kFovDeg, 128);
  const TimeAxis a = axis();
  constexpr int kRings = 120;
  std::vector<double> h(kBins, 0.0);
  for (int i = 0; i < kRings; ++i) {
    const double r = radius * (i + 0.5) / kRings;
    const double area = 2.0 * dif::kPi * r * radius / kRings;
    const double power = area * kLight / std::pow(kLight * kLight + r * r, 1.5);
    const double leg = std::sqrt(kLight * kLight + r * r);
    dif::SemiInfinite m = unit;
    m.rho = r;
    for (int b = 0; b < kBins; ++b) {
      // The bin's optical paths less the vacuum legs, over eta: l in the medium.
      const double lo = (a.binStart_s(b) * kSpeedOfLight_m_per_s - leg - kCamera) / kEta;
      const double hi = (a.binStart_s(b + 1) * kSpeedOfLight_m_per_s - leg - kCamera) / kEta;
      if (hi <= 0.0) continue;
      h[static_cast<std::size_t>(b)] +=
          power / (4.0 * dif::kPi) *
          dif::simpson([&](double l) { return m.radiance(l, cosine); }, std::max(lo, 1e-6), hi, 20);
    }
  }
  return h;
}

// The reference's histograms, one per pixel (the channels' mean), with the
// disk of radius `radius` lit.
std::vector<std::vector<double>> render(double radius) {
  scene::Scene scene;
  test::addBox(scene, "slab", {-1.0f, -1.0f, -0.5f}, {1.0f, 1.0f, 0.0f});  // 100 x 50 l*
  scene.regions.push_back(*scene::takeRegionMesh(scene, "slab"));
  // A black square high above keeps a surface in the scene; paths that reach it end.
  test::addQuad(scene, glm::vec3(0.0f, 0.0f, 20.0f), glm::vec3(0, 0, -1), 1.0f, glm::vec3(0.0f));
  RenderJob job;
  job.scene = &scene;
  job.camera().position_world = {0.0f, 0.0f, static_cast<float>(kCamera)};
  job.camera().look_at_world = {0.0f, 0.0f, -1.0f};
  job.camera().up_world = {0.0f, 1.0f, 0.0f};
  job.camera().fov_y_deg = static_cast<float>(kFovDeg);
  job.camera().width = job.camera().height = kSide;
  job.light.type = Light::Type::Spot;
  job.light.position_world = {0.0f, 0.0f, static_cast<float>(kLight)};
  job.light.direction_world = {0.0f, 0.0f, -1.0f};
  job.light.cone_half_angle_deg = static_cast<float>(std::atan(radius / kLight) * 180.0 / dif::kPi);
  job.light.cone_falloff_deg = 0.0f;
  job.light.intensity_W_per_sr = glm::vec3(1.0f);
  job.settings.time = axis();
  RegionMedium slab;
  slab.region = "slab";
  slab.medium.sigma_a_per_m = glm::vec3(static_cast<float>(kMuA));
  slab.medium.sigma_s_per_m = glm::vec3(static_cast<float>(kMuS));
  slab.medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
  slab.medium.g = static_cast<float>(kG);
  slab.index_of_refraction = kEta;
  job.settings.media.push_back(slab);
  ReferenceSettings settings;
  // l = 90 l* is ~180 events at mu_t 200.5 /m (Poisson sd 13): 220
  // vertices lose < 2e-3 of the light in the last bin.
  settings.bounces = 220;
  settings.samples_per_pixel = kPaths;
  settings.threads = 2;
  const TransientVolume total = test::renderReference(job, settings).total();
  std::vector<std::vector<double>> pixels;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      std::vector<double> h(kBins, 0.0);
      for (int b = 0; b < kBins; ++b)
        for (int c = 0; c < 3; ++c) h[static_cast<std::size_t>(b)] += total.at(y, x, b, c) / 3.0;
      pixels.push_back(h);
    }
  }
  return pixels;
}

double windowSum(const std::vector<double>& h) {
  double s = 0.0;
  for (int b = kFirst; b < kBins; ++b) s += h[static_cast<std::size_t>(b)];
  return s;
}

// The share of the window's light that entered beyond the inner disk.
double outerShare(double outer, double inner) { return 1.0 - inner / outer; }

struct Estimate {
  double value = 0.0, standardError = 0.0;
};

// A statistic of the two renders' pixel sums over the window, and its
// jackknife standard error over the pixels (each draws from its own
// generator; a pixel's A and B are the same paths).
Estimate jackknife(const std::vector<double>& outer, const std::vector<double>& inner,
                   const std::function<double(double, double)>& statistic) {
  const std::size_t n = outer.size();
  double sumOuter = 0.0, sumInner = 0.0;
  for (std::size_t p = 0; p < n; ++p) {
    sumOuter += outer[p];
    sumInner += inner[p];
  }
  std::vector<double> leaveOneOut;
  for (std::size_t p = 0; p < n; ++p)
    leaveOneOut.push_back(statistic((sumOuter - outer[p]) / (n - 1), (sumInner - inner[p]) / (n - 1)));
  double m = 0.0;
  for (const double v : leaveOneOut) m += v / n;
  double s = 0.0;
  for (const double v : leaveOneOut) s += (v - m) * (v - m);
  return {statistic(sumOuter / n, sumInner / n), std::sqrt(s * (n - 1) / n)};
}

TEST(ReferenceDiffusionTest, LateLightSpreadsFromTheSourceAsTheDiffusionClosedForm) {
  const std::vector<std::vector<double>> outer = render(kOuter);
  const std::vector<std::vector<double>> inner = render(kInner);
  std::vector<double> outerSums, innerSums;
  int larger = 0;  // pixel-bins where B exceeds A: none if the paths are the same
  for (std::size_t p = 0; p < outer.size(); ++p) {
    outerSums.push_back(windowSum(outer[p]));
    innerSums.push_back(windowSum(inner[p]));
    for (int b = 0; b < kBins; ++b) {
      const auto k = static_cast<std::size_t>(b);
      if (inner[p][k] > outer[p][k] * (1.0 + 1e-5) + 1e-30) ++larger;
    }
  }
  EXPECT_EQ(larger, 0) << "the renders' paths differ: B is no part of A";
  const std::vector<double> modelOuter = closedForm(kOuter, kMuSPrime);
  const std::vector<double> modelInner = closedForm(kInner, kMuSPrime);

  // The share that entered 10-30 l* away, l 50-90 l*. Diffusion's error
  // there, against 8x these paths by hand (seeds 1 and 2): the reference's
  // share is 0.960 +- 0.013 and 0.941 +- 0.014 of the closed form's; by
  // 10 l* windows 0.89-0.93 at 40-50 l*, 0.97-1.00 at 70-90 l*, 0.83 at
  // 30-40 l*, 0.67 at 20-30 l*: light that crossed 10 l* within a few times
  // 10 l* of path is not yet diffusive (its spread has a finite speed, the
  // Gaussian's tail none). Allowed: 8 % of the closed form's share + 3
  // standard errors (~4 % each at these paths).
  const double expected = outerShare(windowSum(modelOuter), windowSum(modelInner));
  const Estimate share = jackknife(outerSums, innerSums, outerShare);
  const double tolerance = 0.08 * expected + 3.0 * share.standardError;
  std::printf("share entering 10-30 l* away, l 50-90 l*: reference %.4f +- %.4f, diffusion %.4f "
              "(ratio %.3f, tolerance %.4f)\n",
              share.value, share.standardError, expected, share.value / expected, tolerance);
  EXPECT_NEAR(share.value, expected, tolerance);
  EXPECT_LT(share.standardError, 0.06 * expected) << "the test's power";
  // The same estimate rejects the closed form of a D 1.5 times too small or
  // too large (mu_s' x 1.5, / 1.5). The closed form of mu_s' x 1.25 (0.240)
  // may fall inside the tolerance, but a reference that renders sigma_s x
  // 1.25 (0.216) or g 0.6 (mu_s' x 0.8: 0.417) fails (by hand).
  for (const double factor : {1.5, 1.0 / 1.5}) {
    const double off = outerShare(windowSum(closedForm(kOuter, factor * kMuSPrime)),
                                  windowSum(closedForm(kInner, factor * kMuSPrime)));
    std::printf("  mu_s' x %.2f: diffusion %.4f\n", factor, off);
    EXPECT_GT(std::fabs(share.value - off), tolerance) << "mu_s' x " << factor;
  }

  // The level of A over the window against the closed form's: F(l)'s
  // approximations (the source at z0, the extrapolated boundary, the P1
  // radiance) and mu_a. By hand, 8x the paths: 0.997 and 1.003 (0.975-1.023
  // by 10 l* windows from 20 l* on). Allowed 5 % + 3 standard errors.
  const double modelLevel = windowSum(modelOuter);
  const Estimate levelRatio =
      jackknife(outerSums, innerSums, [&](double a, double) { return a / modelLevel; });
  const double levelTolerance = 0.05 + 3.0 * levelRatio.standardError;
  std::printf("level of A, l 50-90 l*: reference / diffusion %.3f +- %.3f (tolerance %.3f)\n",
              levelRatio.value, levelRatio.standardError, levelTolerance);
  EXPECT_NEAR(levelRatio.value, 1.0, levelTolerance);
}

}  // namespace
}  // namespace tofsim::reference
