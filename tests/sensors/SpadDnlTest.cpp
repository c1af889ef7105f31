// TDC differential non-linearity (tdc_dnl): code i is LSB (1 + DNL_i) wide,
// the light and dark counts fall into the true unequal bins and pile-up acts
// on them. A code-density test (uniform light, <= 1 % detections per cycle)
// recovers the table.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "TestVolumes.h"
#include "support/ChiSquare.h"
#include "support/ShortNumber.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {
namespace {

using test::array;
using test::makeVolume;
using tofsim::test::sci;

constexpr double kLsb = 10e-12;
constexpr int32_t kBins = 64, kSide = 32;
constexpr double kSignalPerBin = 5e-5;  // photons per render bin and cycle
constexpr double kDark_per_s = 0.0068 / (kBins * kLsb);

// Two whole periods over the 64 codes: the sum is 0 up to rounding.
std::vector<double> dnlTable() {
  std::vector<double> d(kBins);
  for (int i = 0; i < kBins; ++i) {
    d[i] = 0.25 * std::sin(2.0 * M_PI * 5.0 * i / kBins + 0.3) +
           0.1 * std::cos(2.0 * M_PI * 11.0 * i / kBins);
  }
  return d;
}

SpadParams tdc(const std::vector<double>& dnl) {
  SpadParams p;
  p.cycles = 200000;
  p.pde = 1.0;
  p.dark_count_rate_per_s = kDark_per_s;
  p.tdc_dnl.values = dnl;
  return p;
}

std::vector<double> pooledCounts(const SpadParams& p, uint64_t seed) {
  TransientVolume v = makeVolume(kSide, kSide, 0.0, kLsb, kBins);
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x)
      for (int t = 0; t < kBins; ++t) v.at(y, x, t, 0) = static_cast<float>(kSignalPerBin);
  const std::vector<SensorOutput> outs = runSpad(v, p, seed);
  const SensorOutput& c = array(outs, "spad_counts");
  std::vector<double> h(kBins, 0.0);
  for (std::size_t i = 0; i < c.data.size(); ++i) h[i % kBins] += c.data[i];
  return h;
}

// Code density with the pile-up removed (Coates): DNL_i = flux_i / mean - 1,
// against `table`, each with its binomial standard error (1 + DNL_i) /
// sqrt(h_i); chi-square over the bins (the mean takes one degree).
double codeDensityChiSquare(const std::vector<double>& h, const std::vector<double>& table) {
  const double cycles = double(kSide * kSide) * 200000.0;
  const std::vector<double> flux = coatesEstimate(h, static_cast<int64_t>(cycles));
  double mean = 0.0;
  for (double f : flux) mean += f / kBins;
  double chi = 0.0;
  for (int i = 0; i < kBins; ++i) {
    const double estimate = flux[i] / mean - 1.0;
    const double se = (1.0 + table[i]) / std::sqrt(h[i]);
    chi += (estimate - table[i]) * (estimate - table[i]) / (se * se);
  }
  return chi;
}

TEST(SpadDnlTest, CodeDensityRecoversTheDnlTable) {
  const std::vector<double> dnl = dnlTable();
  const std::vector<double> h = pooledCounts(tdc(dnl), 31);
  const double chi = codeDensityChiSquare(h, dnl);
  RecordProperty("chi2", sci(chi));
  RecordProperty("dof", kBins - 1);
  EXPECT_LT(chi, tofsim::test::chiSquareQuantile(kBins - 1, 3.09));
  EXPECT_GT(chi, tofsim::test::chiSquareQuantile(kBins - 1, -3.09));
  // Equal bins are rejected for these counts, and counts of equal bins for
  // the table.
  const double equal = codeDensityChiSquare(h, std::vector<double>(kBins, 0.0));
  RecordProperty("chi2_equal_bins", sci(equal));
  EXPECT_GT(equal, tofsim::test::chiSquareQuantile(kBins - 1, 3.09));
  const std::vector<double> flat = pooledCounts(tdc({}), 31);
  EXPECT_GT(codeDensityChiSquare(flat, dnl), tofsim::test::chiSquareQuantile(kBins - 1, 3.09));
}

// The counts follow the exact first-photon law of the true bins: flux_i =
// (signal per LSB + dark x LSB) (1 + DNL_i), written here from the table.
TEST(SpadDnlTest, PileUpActsOnTheTrueUnequalBins) {
  const std::vector<double> dnl = dnlTable();
  SpadParams p = tdc(dnl);
  p.cycles = 20000;
  p.dark_count_rate_per_s = 0.3 / (kBins * kLsb);  // ~35 % detections: strong pile-up
  TransientVolume v = makeVolume(kSide, kSide, 0.0, kLsb, kBins);
  const std::vector<SensorOutput> outs = runSpad(v, p, 32);
  const SensorOutput& c = array(outs, "spad_counts");
  std::vector<double> h(kBins, 0.0);
  for (std::size_t i = 0; i < c.data.size(); ++i) h[i % kBins] += c.data[i];
  std::vector<double> flux(kBins), unequalLaw, equalLaw;
  for (int i = 0; i < kBins; ++i) flux[i] = p.dark_count_rate_per_s * kLsb * (1.0 + dnl[i]);
  const auto chiOf = [&](const std::vector<double>& f) {
    const std::vector<double> law = firstPhotonProbabilities(f);
    const double n = double(kSide * kSide) * double(p.cycles);
    std::vector<double> obs = h, exp(kBins);
    double none = 1.0, detected = 0.0;
    for (int i = 0; i < kBins; ++i) {
      exp[i] = n * law[i];
      none -= law[i];
      detected += h[i];
    }
    obs.push_back(n - detected);
    exp.push_back(n * none);
    return tofsim::test::pearson(obs, exp);
  };
  const tofsim::test::ChiSquare chi = chiOf(flux);
  RecordProperty("chi2", sci(chi.statistic));
  EXPECT_LT(chi.statistic, tofsim::test::chiSquareQuantile(chi.dof, 3.09));
  std::vector<double> equal(kBins, p.dark_count_rate_per_s * kLsb);
  EXPECT_GT(chiOf(equal).statistic, tofsim::test::chiSquareQuantile(chi.dof, 3.09));
}

TEST(SpadDnlTest, ZeroDnlIsTheEqualBinsBytes) {
  TransientVolume v = makeVolume(8, 8, 0.0, kLsb, kBins);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) v.at(y, x, 20, 0) = 0.7f;
  SpadParams none = tdc({});
  none.jitter_fwhm_s = 25e-12;
  SpadParams zeros = none;
  zeros.tdc_dnl.values.assign(kBins, 0.0);
  EXPECT_EQ(array(runSpad(v, zeros, 33), "spad_counts").data,
            array(runSpad(v, none, 33), "spad_counts").data);
  SpadParams wrong = none;
  wrong.tdc_dnl.values.assign(kBins - 1, 0.01);
  EXPECT_THROW(runSpad(v, wrong, 33), InputError);
}

}  // namespace
}  // namespace tofsim::sensors
