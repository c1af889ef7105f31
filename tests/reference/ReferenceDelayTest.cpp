// Scattering delays in the reference path tracer (issue 41): a vertex whose
// material has a delay kernel delays the light it scatters with probability
// `fraction`, by a delay drawn from the kernel, re-emitted through its
// matrix. Checked on the closed-form plane at pixel centres (the light at the
// camera, one vertex per path, so each pixel's histogram is N draws of one
// delay): the prompt share and the delayed bins against the exact bin
// integrals of the kernel (chi-square), the binned mean and variance of a
// Gaussian and of a table against theirs, re-emission G -> R, and energy kept
// on the corner with three interactions. Each fails with the delay off or
// mis-parametrised (a wrong lifetime, an untruncated Gaussian, a table read as
// uniform, a transposed matrix, a weight on the delayed share).

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "RenderReference.h"
#include "support/ClosedForm.h"

namespace tofsim::reference {
namespace {

using namespace capture;

constexpr int kPaths = 4000;  // draws of the delay per pixel
constexpr double kBin_s = 0.002 / kSpeedOfLight_m_per_s;  // PlaneJob's bins, 6.67 ps

// The delay's CDF, seconds.
using Cdf = std::function<double(double)>;

Cdf exponentialCdf(double tau_s) {
  return [tau_s](double t) { return t <= 0.0 ? 0.0 : -std::expm1(-t / tau_s); };
}

double normalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// N(mean, sigma^2) truncated to t >= 0 (physics::ResponseKernel).
Cdf truncatedGaussianCdf(double mean_s, double sigma_s) {
  const double below = normalCdf(-mean_s / sigma_s);
  return [=](double t) {
    return t <= 0.0 ? 0.0 : (normalCdf((t - mean_s) / sigma_s) - below) / (1.0 - below);
  };
}

physics::ResponseKernel exponential(double fraction, double tau_s) {
  physics::ResponseKernel k;
  k.model = physics::ResponseModel::Exponential;
  k.fraction = fraction;
  k.lifetime_s = tau_s;
  return k;
}

// The plane of ReferenceClosedFormTest, 8 x 6 pixels, its material delayed
// by `kernel`; the light at the camera.
struct DelayedPlane {
  test::PlaneJob s;
  explicit DelayedPlane(const std::optional<physics::ResponseKernel>& kernel) {
    s.job.camera().width = 8;
    s.job.camera().height = 6;
    s.scene.materials.at(0).scatteringDelay = kernel;
  }
  VolumeCollector render(int32_t bounces = 1, RenderResult* result = nullptr) const {
    ReferenceSettings settings;
    settings.pixel_filter = PixelFilter::Point;
    settings.bounces = bounces;
    settings.samples_per_pixel = kPaths;
    settings.threads = 2;
    return test::renderReference(s.job, settings, result);
  }
  /// The light's arrival at pixel (x, y) without delay, seconds after bin 0's edge.
  double arrival_s(int x, int y) const {
    const glm::dvec3 p = test::hitOnPlane(s.job.camera(), x, y);
    const double r = glm::length(p - glm::dvec3(s.job.camera().position_world));
    return 2.0 * r / kSpeedOfLight_m_per_s - s.job.settings.time.start_s;
  }
};

// One pixel's histogram summed over channels, as shares of `energy`.
std::vector<double> shares(const TransientVolume& v, int y, int x, double energy) {
  std::vector<double> p(static_cast<std::size_t>(v.bins()), 0.0);
  for (int t = 0; t < v.bins(); ++t) {
    for (int c = 0; c < 3; ++c) p[static_cast<std::size_t>(t)] += v.at(y, x, t, c) / energy;
  }
  return p;
}

double pixelEnergy(const TransientVolume& v, int y, int x) {
  double e = 0.0;
  for (int t = 0; t < v.bins(); ++t) {
    for (int c = 0; c < 3; ++c) e += v.at(y, x, t, c);
  }
  return e;
}

// The expected share of each bin: the prompt (1 - f) in the arrival's bin, f
// times the delay's mass over each bin.
std::vector<double> expectedShares(int bins, double arrival_s, double fraction, const Cdf& cdf) {
  std::vector<double> q(static_cast<std::size_t>(bins), 0.0);
  for (int k = 0; k < bins; ++k) {
    const double lo = k * kBin_s - arrival_s, hi = (k + 1) * kBin_s - arrival_s;
    q[static_cast<std::size_t>(k)] = fraction * (cdf(hi) - cdf(lo));
    if (lo <= 0.0 && hi > 0.0) q[static_cast<std::size_t>(k)] += 1.0 - fraction;
  }
  return q;
}

// Pearson's chi-square of one pixel's N draws: cells of expected count >= 5,
// the rest lumped into one cell. Adds to chi2 and dof.
void addChiSquare(const std::vector<double>& p, const std::vector<double>& q, double& chi2,
                  int& dof) {
  double restP = 1.0, restQ = 1.0;
  int cells = 0;
  for (std::size_t k = 0; k < q.size(); ++k) {
    if (q[k] * kPaths < 5.0) continue;
    chi2 += kPaths * (p[k] - q[k]) * (p[k] - q[k]) / q[k];
    restP -= p[k];
    restQ -= q[k];
    ++cells;
  }
  if (restQ * kPaths >= 5.0) {
    chi2 += kPaths * (restP - restQ) * (restP - restQ) / restQ;
    ++cells;
  }
  dof += cells - 1;
}

TEST(ReferenceDelayTest, ExponentialDelayFollowsTheBinIntegralsOfTheKernel) {
  const double f = 0.6, tau_s = 7.5 * kBin_s;  // 50 ps
  const DelayedPlane plain(std::nullopt), delayed(exponential(f, tau_s));
  RenderResult result;
  const VolumeCollector before = plain.render(), after = delayed.render(1, &result);
  EXPECT_EQ(result.offAxis.total(), 0.0);
  double chi2 = 0.0, chi2WrongTau = 0.0;
  int dof = 0, dofWrongTau = 0, pixels = 0;
  for (int y = 0; y < 6; ++y) {
    for (int x = 0; x < 8; ++x) {
      const double energy = pixelEnergy(before.direct, y, x);
      ASSERT_GT(energy, 0.0);
      const double t0 = delayed.arrival_s(x, y);
      const std::vector<double> p = shares(after.direct, y, x, energy);
      const std::vector<double> q = expectedShares(after.direct.bins(), t0, f, exponentialCdf(tau_s));
      // The prompt share: the arrival bin holds 1 - f and the delayed light
      // that stays in it, within 5 standard errors of N draws.
      const auto b0 = static_cast<std::size_t>(std::floor(t0 / kBin_s));
      const double se = std::sqrt(q[b0] * (1.0 - q[b0]) / kPaths);
      EXPECT_NEAR(p[b0], q[b0], 5.0 * se) << "pixel " << x << "," << y;
      EXPECT_NEAR(p[b0] - f * (exponentialCdf(tau_s)((b0 + 1) * kBin_s - t0)), 1.0 - f, 5.0 * se);
      double total = 0.0;
      for (const double v : p) total += v;
      EXPECT_NEAR(total, 1.0, 1e-5) << "energy kept at pixel " << x << "," << y;
      addChiSquare(p, q, chi2, dof);
      addChiSquare(p, expectedShares(after.direct.bins(), t0, f, exponentialCdf(1.1 * tau_s)),
                   chi2WrongTau, dofWrongTau);
      ++pixels;
    }
  }
  EXPECT_EQ(pixels, 48);
  // The sum over pixels of their chi-squares: mean dof, variance 2 dof.
  std::printf("chi-square %.1f over %d degrees of freedom (a lifetime 10%% longer: %.1f)\n", chi2,
              dof, chi2WrongTau);
  EXPECT_LT(chi2, dof + 5.0 * std::sqrt(2.0 * dof));
  EXPECT_GT(chi2WrongTau, dofWrongTau + 5.0 * std::sqrt(2.0 * dofWrongTau));
}

// Pooled over the pixels: the binned delay's mean and variance (bin centres,
// the arrival subtracted) against those of the kernel's exact bin integrals,
// as z-scores of N draws per pixel.
struct Moments {
  double meanZ = 0.0, varianceZ = 0.0;
  double mean_s = 0.0, variance_s2 = 0.0;  ///< measured, averaged over the pixels
};

Moments binnedMoments(const DelayedPlane& plane, const VolumeCollector& before,
                      const VolumeCollector& after, const Cdf& cdf) {
  Moments m;
  double meanDiff = 0.0, meanVar = 0.0, varDiff = 0.0, varVar = 0.0;
  int pixels = 0;
  for (int y = 0; y < 6; ++y) {
    for (int x = 0; x < 8; ++x) {
      const double t0 = plane.arrival_s(x, y);
      const std::vector<double> p = shares(after.direct, y, x, pixelEnergy(before.direct, y, x));
      const std::vector<double> q = expectedShares(after.direct.bins(), t0, 1.0, cdf);
      const auto moments = [&](const std::vector<double>& w, double mu, int power) {
        double s = 0.0;
        for (std::size_t k = 0; k < w.size(); ++k) {
          s += w[k] * std::pow((static_cast<double>(k) + 0.5) * kBin_s - t0 - mu, power);
        }
        return s;
      };
      const double mu = moments(q, 0.0, 1), var = moments(q, mu, 2), m4 = moments(q, mu, 4);
      const double muHat = moments(p, 0.0, 1), varHat = moments(p, muHat, 2);
      meanDiff += muHat - mu;
      meanVar += var / kPaths;
      varDiff += varHat - var;
      varVar += (m4 - var * var) / kPaths;
      m.mean_s += muHat;
      m.variance_s2 += varHat;
      ++pixels;
    }
  }
  m.meanZ = meanDiff / std::sqrt(meanVar);
  m.varianceZ = varDiff / std::sqrt(varVar);
  m.mean_s /= pixels;
  m.variance_s2 /= pixels;
  return m;
}

TEST(ReferenceDelayTest, GaussianDelayRecoversItsMeanAndSigma) {
  const double mean_s = 40e-12, sigma_s = 15e-12;  // 6 and 2.25 bins; 0.4 % below t = 0
  physics::ResponseKernel k;
  k.model = physics::ResponseModel::Gaussian;
  k.mean_s = mean_s;
  k.sigma_s = sigma_s;
  const DelayedPlane plain(std::nullopt), delayed(k);
  const VolumeCollector before = plain.render(), after = delayed.render();
  const Moments m = binnedMoments(delayed, before, after, truncatedGaussianCdf(mean_s, sigma_s));
  EXPECT_LT(std::abs(m.meanZ), 4.0);
  EXPECT_LT(std::abs(m.varianceZ), 4.0);
  // The kernel's own moments (truncated at 0), recovered: the bins' centres
  // add a variance of w^2 / 12 (Sheppard) and nothing measurable to the mean
  // at sigma = 2.25 bins. Truncation moves the mean by 0.17 ps, 3 standard
  // errors of these 192,000 draws: the untruncated mean is further off.
  const double a = -mean_s / sigma_s;
  const double phi = std::exp(-0.5 * a * a) / std::sqrt(2.0 * M_PI), tail = 1.0 - normalCdf(a);
  const double truncMean = mean_s + sigma_s * phi / tail;
  const double truncSigma = sigma_s * std::sqrt(1.0 + a * phi / tail - (phi / tail) * (phi / tail));
  const double sigmaHat = std::sqrt(m.variance_s2 - kBin_s * kBin_s / 12.0);
  std::printf("Gaussian delay: mean %.4f ps (kernel %.4f), sigma %.4f ps (kernel %.4f)\n",
              m.mean_s * 1e12, truncMean * 1e12, sigmaHat * 1e12, truncSigma * 1e12);
  const double n = 48.0 * kPaths;
  EXPECT_NEAR(m.mean_s, truncMean, 4.0 * truncSigma / std::sqrt(n));
  EXPECT_NEAR(sigmaHat, truncSigma, 4.0 * truncSigma / std::sqrt(2.0 * n));
  // An untruncated sampler would give the mean mean_s (checked to differ).
  EXPECT_GT(std::abs(truncMean - mean_s), 2.0 * truncSigma / std::sqrt(n));
}

TEST(ReferenceDelayTest, TableOfAnExponentialGivesTheExponentialsMean) {
  const double tau_s = 7.5 * kBin_s;
  physics::ResponseKernel k;
  k.model = physics::ResponseModel::Table;
  for (int i = 0; i <= 240; ++i) {  // 0 .. 12 tau in steps of tau / 20
    const double t = i * tau_s / 20.0;
    k.tableDelay_s.push_back(t);
    k.tableWeight.push_back(3.0 * std::exp(-t / tau_s));  // any scale: normalised
  }
  const DelayedPlane plain(std::nullopt), delayed(k);
  const VolumeCollector before = plain.render(), after = delayed.render();
  const Moments m = binnedMoments(delayed, before, after, exponentialCdf(tau_s));
  std::printf("table of an exponential: binned mean %.4f ps, z %.2f; variance z %.2f\n",
              m.mean_s * 1e12, m.meanZ, m.varianceZ);
  EXPECT_LT(std::abs(m.meanZ), 4.0);
  EXPECT_LT(std::abs(m.varianceZ), 4.0);
}

TEST(ReferenceDelayTest, ReemissionTurnsGreenLightRedPerTheMatrix) {
  const double f = 0.5;
  physics::ResponseKernel k = exponential(f, 7.5 * kBin_s);
  k.reemission[1] = glm::dvec3(0.6, 0.2, 0.0);  // light absorbed in G: 0.6 to R, 0.2 stays G
  DelayedPlane plain(std::nullopt), delayed(k);
  for (DelayedPlane* p : {&plain, &delayed}) p->s.job.light.intensity_W_per_sr = {0.0f, 2.0f, 0.0f};
  const VolumeCollector before = plain.render(), after = delayed.render();
  const Image green = steadyImage(before.direct), out = steadyImage(after.direct);
  const double se = std::sqrt(f * (1.0 - f) / kPaths);
  for (int y = 0; y < 6; ++y) {
    for (int x = 0; x < 8; ++x) {
      const double g = green.at(y, x, 1);
      ASSERT_GT(g, 0.0);
      EXPECT_EQ(green.at(y, x, 0), 0.0f);
      // The delayed share of the G light the plane reflects (its G albedo
      // first, then the matrix) comes back 0.6 R + 0.2 G; the prompt stays G.
      const double delayedShare = out.at(y, x, 0) / (0.6 * g);
      EXPECT_NEAR(delayedShare, f, 5.0 * se) << "pixel " << x << "," << y;
      EXPECT_NEAR(out.at(y, x, 1) / g, 1.0 - 0.8 * delayedShare, 1e-5);
      EXPECT_EQ(out.at(y, x, 2), 0.0f);
    }
  }
}

// The corner (floor and wall) with the wall delayed, three interactions,
// box filter: each path's light is moved in time, never scaled, so every
// pixel keeps its energy (the delays draw from their own stream: the paths'
// directions are those of the undelayed render, and the sums agree to
// rounding, far inside the Monte Carlo error). A change of weight on the
// delayed share, or of directions, fails.
TEST(ReferenceDelayTest, DelaysKeepEveryPixelsEnergy) {
  test::CornerJob plain(8), delayed(8);
  for (test::CornerJob* j : {&plain, &delayed}) j->job.settings.time.bins = 2500;  // all on the axis
  delayed.scene.materials.at(1).scatteringDelay = exponential(0.5, 5.0 * 0.01 / kSpeedOfLight_m_per_s);
  ReferenceSettings settings;
  settings.bounces = 3;
  settings.samples_per_pixel = 64;
  settings.threads = 2;
  RenderResult r0, r1;
  const VolumeCollector before = test::renderReference(plain.job, settings, &r0);
  const VolumeCollector after = test::renderReference(delayed.job, settings, &r1);
  EXPECT_EQ(r0.offAxis.total(), 0.0);
  EXPECT_EQ(r1.offAxis.total(), 0.0);
  const TransientVolume a = before.total(), b = after.total();
  double moved = 0.0, total = 0.0;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      for (int c = 0; c < 3; ++c) {
        double ea = 0.0, eb = 0.0;
        for (int t = 0; t < a.bins(); ++t) {
          ea += a.at(y, x, t, c);
          eb += b.at(y, x, t, c);
          moved += std::abs(a.at(y, x, t, c) - b.at(y, x, t, c));
        }
        EXPECT_NEAR(eb, ea, 1e-5 * ea + 1e-12) << "pixel " << x << "," << y << " channel " << c;
        total += ea;
      }
    }
  }
  // Not vacuous: much of the light did move.
  EXPECT_GT(moved, 0.2 * total);
  // Same seed, same bytes, whatever the thread count.
  settings.threads = 1;
  const VolumeCollector again = test::renderReference(delayed.job, settings);
  EXPECT_EQ(again.total().values(), b.values());
}

}  // namespace
}  // namespace tofsim::reference
