// Multiple scattering in the reference against diffusion theory (issue 42):
// the time-domain diffusion Green's function of an infinite homogeneous
// medium (Patterson, Chance and Wilson 1989, Appl. Opt. 28(12), eq. 2 without
// boundaries): an isotropic point source emitting a unit pulse gives, at
// distance r, the fluence rate
//   phi(r, t) = c (4 pi D c t)^(-3/2) exp(-r^2 / (4 D c t) - mu_a c t),
//   D = 1 / (3 (mu_a + mu_s')), c = c0 / eta,
// so with l = c t the geometric path, a time bin [l0, l1] of the radiance's
// isotropic part phi / (4 pi) from a source of intensity I (power 4 pi I) is
//   I int_l0^l1 (4 pi D l)^(-3/2) exp(-r^2 / (4 D l) - mu_a l) dl.
// The camera sits at the detector point looking across the source
// direction: the image is mirror-symmetric about the plane through the
// camera perpendicular to it, so the mean over the image cancels the flux
// term (3 / 4 pi) F . w of the P1 radiance and leaves phi / (4 pi).
//
// The semi-infinite medium (Patterson's reflectance, the radiance leaving a
// boundary) is ReferenceSemiInfiniteTest; the infinite medium's fluence,
// away from any boundary, is measured here.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "DiffusionClosedForm.h"
#include "MediumClosedForm.h"
#include "RenderReference.h"
#include "support/AnalyticScenes.h"
#include "tofsim/physics/MediumPhysics.h"

namespace tofsim::reference {
namespace {

using namespace capture;

constexpr double kMuS = 100.0, kMuA = 1.0;  // 1/m: albedo 0.99, isotropic (mu_s' = mu_s)
constexpr double kR = 0.05;                 // source-detector distance: 5 transport mean free paths
constexpr double kL0 = 0.15, kBin = 0.05;   // geometric path of bin 0 and the bin width, m
constexpr int kBins = 6;                    // l from 15 to 45 mean free paths: late times
constexpr double kEta = 1.33;
constexpr int kSide = 16, kPaths = 256;     // 65 536 paths

// I int_l0^l1 (4 pi D l)^(-3/2) exp(-r^2 / (4 D l) - mu_a l) dl (Simpson).
double diffusionBin(double l0, double l1, double muA, double muSPrime) {
  const double d = 1.0 / (3.0 * (muA + muSPrime));
  return test::diffusion::simpson(
      [&](double l) { return test::diffusion::green(kR * kR, l, d, muA); }, l0, l1);
}

// Mean of phi / 4 pi over bins [first, last) and its standard error, from the
// image's mirror pairs (x, side - 1 - x): independent estimates (each pixel
// draws from its own generator) in which the flux term cancels.
struct Estimate {
  double mean = 0.0, standardError = 0.0;
};
Estimate fluence(const TransientVolume& v, int first, int last) {
  std::vector<double> pairs;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide / 2; ++x) {
      double sum = 0.0;
      for (int b = first; b < last; ++b)
        for (int c = 0; c < 3; ++c) sum += (v.at(y, x, b, c) + v.at(y, kSide - 1 - x, b, c)) / 6.0;
      pairs.push_back(sum);
    }
  }
  Estimate e;
  for (const double p : pairs) e.mean += p / pairs.size();
  double var = 0.0;
  for (const double p : pairs) var += (p - e.mean) * (p - e.mean) / (pairs.size() - 1);
  e.standardError = std::sqrt(var / pairs.size());
  return e;
}

TEST(ReferenceDiffusionTest, InfiniteMediumFluenceFollowsTheDiffusionGreensFunction) {
  // A black square far behind the camera keeps the scene non-empty; no path
  // reaches it through 5000 mean free paths.
  scene::Scene scene;
  test::addQuad(scene, glm::vec3(0.0f, 0.0f, -50.0f), glm::vec3(0, 0, 1), 1.0f, glm::vec3(0.0f));
  RenderJob job;
  job.scene = &scene;
  job.camera().position_world = {0.0f, 0.0f, 0.0f};
  job.camera().look_at_world = {0.0f, 0.0f, 1.0f};  // across the source direction (x)
  job.camera().fov_y_deg = 60.0f;
  job.camera().width = job.camera().height = kSide;
  job.light.position_world = {static_cast<float>(kR), 0.0f, 0.0f};
  job.light.intensity_W_per_sr = glm::vec3(1.0f);
  job.settings.time = test::pathAxis(kEta, kL0, kBin, kBins);
  job.settings.medium.sigma_a_per_m = glm::vec3(static_cast<float>(kMuA));
  job.settings.medium.sigma_s_per_m = glm::vec3(static_cast<float>(kMuS));
  ReferenceSettings settings;
  settings.pixel_filter = PixelFilter::Point;
  settings.bounces = 75;  // l = 0.45 m is ~45 events; 75 leaves a Poisson tail < 1e-4
  settings.samples_per_pixel = kPaths;
  settings.threads = 2;
  const TransientVolume total = test::renderReference(job, settings).total();
  // The late window and the whole one; the diffusion approximation is
  // allowed 5 % at these late times, the estimate 3 standard errors (from
  // the pairs; at this budget 3-7 %: the light is a point, and paths that
  // pass near it are rare and bright even with equiangular sampling).
  struct Window {
    int first, last;
  };
  for (const Window w : {Window{3, 6}, Window{0, 6}}) {
    const Estimate e = fluence(total, w.first, w.last);
    const double l0 = kL0 + w.first * kBin, l1 = kL0 + w.last * kBin;
    const double expected = diffusionBin(l0, l1, kMuA, kMuS);
    const double tolerance = 0.05 + 3.0 * e.standardError / expected;
    std::printf("l %.2f-%.2f m: reference %.4g +- %.2g, diffusion %.4g, ratio %.3f, tolerance %.3f\n",
                l0, l1, e.mean, e.standardError, expected, e.mean / expected, tolerance);
    EXPECT_LT(e.standardError / expected, 0.08);  // the test's power
    EXPECT_NEAR(e.mean / expected, 1.0, tolerance);
    if (w.first == 0 && w.last == 6) {
      // The same estimate rejects a medium that absorbs three times as much
      // or diffuses 1.5 times as fast.
      EXPECT_GT(std::fabs(e.mean / diffusionBin(l0, l1, 3.0 * kMuA, kMuS) - 1.0), tolerance);
      EXPECT_GT(std::fabs(e.mean / diffusionBin(l0, l1, kMuA, kMuS / 1.5) - 1.0), tolerance);
    }
  }
}

}  // namespace
}  // namespace tofsim::reference
