// The temporal-response stage for classes of several kernels and kernels
// that re-emit (TemporalResponse.h: applyResponse over a class's stages,
// temporal_response.glsl). A cascade moves an impulse's mean by the sum of
// its members' means exactly (each stage's hats reproduce linear functions)
// and keeps its energy (the bins plus the light reported past the axis); a
// class of one member gives the bytes of the one-kernel stage; re-emission
// returns a channel's delayed light in the channels its matrix's column says,
// the prompt share untouched, and the light the matrix absorbs is not booked
// as past the axis.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "tofsim/physics/ResponseClassTable.h"
#include "tofsim/physics/TemporalResponse.h"

namespace tofsim::physics {
namespace {

constexpr double kBin_s = 10e-12;

// A difference buffer holding one unit of light (per channel `energy`) in bin k.
std::vector<double> impulse(int32_t bins, int32_t k, const glm::dvec3& energy) {
  std::vector<double> diff(static_cast<std::size_t>(bins) * 3, 0.0);
  for (int o = 0; o < 3; ++o) {
    for (int c = 0; c < 3; ++c) {
      diff[static_cast<std::size_t>(k + o) * 3 + c] += (o == 1 ? -2.0 : 1.0) * energy[c];
    }
  }
  return diff;
}

struct Output {
  std::vector<float> histogram;
  double past = 0.0;
  glm::dvec3 total{0.0}, mean{0.0};  // per channel, mean in bin indices
};

Output run(std::vector<double> diff, int32_t bins, const std::vector<ResponseTaps>& stages) {
  Output out{std::vector<float>(static_cast<std::size_t>(bins) * 3, 0.0f)};
  std::vector<double> scratch(diff.size(), -1.0);  // garbage: never read before it is written
  out.past = applyResponse(diff.data(), scratch.data(), bins, 0, stages, out.histogram.data());
  for (int32_t n = 0; n < bins; ++n) {
    for (int c = 0; c < 3; ++c) {
      out.total[c] += out.histogram[static_cast<std::size_t>(n) * 3 + c];
      out.mean[c] += out.histogram[static_cast<std::size_t>(n) * 3 + c] * n;
    }
  }
  out.mean /= out.total;
  return out;
}

std::vector<ResponseKernel> threeKernels() {
  std::vector<ResponseKernel> k(3);
  k[0].lifetime_s = 300e-12;  // 30 bins
  k[0].fraction = 0.7;
  k[1].model = ResponseModel::Gaussian;
  k[1].mean_s = 200e-12;
  k[1].sigma_s = 40e-12;
  k[2].model = ResponseModel::Table;
  k[2].tableDelay_s = {0.0, 50e-12, 300e-12};
  k[2].tableWeight = {0.0, 2.0, 0.5};
  k[2].fraction = 0.8;
  return k;
}

// Each kernel's mean delay in bins, its delayed share included.
double meanBins(const ResponseKernel& k) {
  switch (k.model) {
    case ResponseModel::Exponential:
      return k.fraction * k.lifetime_s / kBin_s;
    case ResponseModel::Gaussian:
      return k.fraction * k.mean_s / kBin_s;  // 5 sigma from 0
    case ResponseModel::Table: {
      // Piecewise linear density: its first moment over its area.
      double area = 0.0, moment = 0.0;
      const std::vector<double>& u = k.tableDelay_s;
      const std::vector<double>& w = k.tableWeight;
      for (std::size_t i = 0; i + 1 < u.size(); ++i) {
        const double h = (u[i + 1] - u[i]) / kBin_s, a = u[i] / kBin_s;
        area += 0.5 * h * (w[i] + w[i + 1]);
        moment += h * (w[i] * (a / 2 + h / 6) + w[i + 1] * (a / 2 + h / 3));
      }
      return k.fraction * moment / area;
    }
  }
  return 0.0;
}

TEST(ResponseCascadeTest, ACascadeAddsItsMembersMeansAndKeepsTheEnergy) {
  const std::vector<ResponseKernel> kernels = threeKernels();
  const glm::dvec3 energy(1.0, 0.5, 2.0);
  const int32_t k = 20;
  for (std::size_t members = 2; members <= 3; ++members) {
    std::vector<ResponseTaps> stages;
    double mean = k;  // the impulse's in bin indices (a bin's light at its index)
    for (std::size_t m = 0; m < members; ++m) {
      stages.push_back(responseTaps(kernels[m], kBin_s));
      mean += meanBins(kernels[m]);
    }
    // An axis that holds the whole cascade (the exponential to e^-40).
    const Output whole = run(impulse(2000, k, energy), 2000, stages);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(whole.total[c], energy[c], 1e-6 * energy[c]) << members << " members";
      EXPECT_NEAR(whole.mean[c], mean, 1e-4) << members << " members";
    }
    EXPECT_NEAR(whole.past, 0.0, 1e-9);
    // A short axis: the cascade's light past it is reported.
    const Output cut = run(impulse(120, k, energy), 120, stages);
    const double kept = cut.total.x + cut.total.y + cut.total.z;
    EXPECT_GT(cut.past, 0.1);
    EXPECT_NEAR(kept + cut.past, 3.5, 3e-6) << members << " members";
  }
}

TEST(ResponseCascadeTest, AClassOfOneMemberIsTheOneKernelStage) {
  const ResponseTaps taps = responseTaps(threeKernels()[0], kBin_s);
  std::vector<double> a = impulse(300, 7, glm::dvec3(1.0, 0.3, 0.2)), b = a;
  std::vector<float> single(900, 0.0f), cascade(900, 0.0f);
  const double pastSingle = applyResponse(a.data(), 300, 0, taps, single.data());
  const double pastCascade =
      applyResponse(b.data(), nullptr, 300, 0, std::vector<ResponseTaps>{taps}, cascade.data());
  EXPECT_EQ(0, std::memcmp(single.data(), cascade.data(), single.size() * sizeof(float)));
  EXPECT_EQ(pastSingle, pastCascade);
  // classStages lists each class's members in order.
  const ResponseClassTable table = ResponseClassTable::build(threeKernels(), 2);
  const std::vector<std::vector<ResponseTaps>> stages = classStages(table, kBin_s);
  ASSERT_EQ(stages.size(), table.classCount() - 1);
  for (std::size_t c = 1; c < table.classCount(); ++c) {
    ASSERT_EQ(stages[c - 1].size(), table.members[c].size());
    for (std::size_t m = 0; m < stages[c - 1].size(); ++m) {
      EXPECT_EQ(stages[c - 1][m].taps,
                responseTaps(table.kernels[table.members[c][m] - 1], kBin_s).taps);
    }
  }
  EXPECT_EQ(responseBuffers(table), table.classCount() - 1 + 1);  // the classes and a scratch
  EXPECT_EQ(responseBuffers(ResponseClassTable::build(threeKernels(), 1)), 3u);
  EXPECT_EQ(responseBuffers(ResponseClassTable::build({}, 3)), 0u);
}

// Light absorbed in G comes back as column 1 of the matrix: R and (less) G.
ResponseKernel greenToRed(double lifetime_s) {
  ResponseKernel k;
  k.lifetime_s = lifetime_s;
  k.fraction = 0.6;
  k.reemission[1] = glm::dvec3(0.7, 0.1, 0.0);  // column 1: sums to 0.8
  return k;
}

TEST(ResponseCascadeTest, ReemissionMovesTheDelayedShareAsItsMatrixSays) {
  const int32_t bins = 800, k = 30;
  const ResponseKernel kernel = greenToRed(100e-12);  // 10 bins: all of it on the axis
  const Output out =
      run(impulse(bins, k, glm::dvec3(0.0, 1.0, 0.0)), bins, {responseTaps(kernel, kBin_s)});
  // Energy per the column: R = f M_r1, G = (1 - f) + f M_g1, B = 0.
  EXPECT_NEAR(out.total.x, 0.6 * 0.7, 1e-6);
  EXPECT_NEAR(out.total.y, 0.4 + 0.6 * 0.1, 1e-6);
  EXPECT_EQ(out.total.z, 0.0);
  // The absorbed 0.6 x 0.2 is not light past the axis.
  EXPECT_NEAR(out.past, 0.0, 1e-9);
  // R is the delayed share alone: the exponential's shape, no prompt spike.
  ResponseKernel plain = kernel;
  plain.reemission = glm::dmat3(1.0);
  const Output green =
      run(impulse(bins, k, glm::dvec3(0.0, 1.0, 0.0)), bins, {responseTaps(plain, kBin_s)});
  for (int32_t n = 0; n < bins; ++n) {
    const double delayed = green.histogram[n * 3 + 1] - (n == k ? 0.4 : 0.0);
    EXPECT_NEAR(out.histogram[n * 3], 0.7 * delayed, 1e-7) << n;
  }
  EXPECT_NEAR(out.mean.x, k + 10.0, 1e-4);  // the delayed light's mean: tau later
  // Red light is not re-emitted by this matrix's column 0 (identity there).
  const Output red =
      run(impulse(bins, k, glm::dvec3(1.0, 0.0, 0.0)), bins, {responseTaps(kernel, kBin_s)});
  EXPECT_NEAR(red.total.x, 1.0, 1e-6);
  EXPECT_EQ(red.total.y, 0.0);
}

TEST(ResponseCascadeTest, ReemittedLightPastTheAxisIsReportedAndAbsorbedLightIsNot) {
  // A lifetime of 50 bins on an axis of 100: part of the tail is cut.
  const ResponseKernel kernel = greenToRed(500e-12);
  const std::vector<ResponseTaps> stages = {responseTaps(threeKernels()[1], kBin_s),
                                            responseTaps(kernel, kBin_s)};
  for (const auto& one : {std::vector<ResponseTaps>{stages[1]}, stages}) {
    const Output out = run(impulse(100, 10, glm::dvec3(0.0, 2.0, 0.0)), 100, one);
    const double kept = out.total.x + out.total.y + out.total.z;
    EXPECT_GT(out.past, 0.1);
    EXPECT_NEAR(kept + out.past, 2.0 * (0.4 + 0.6 * 0.8), 2e-6) << one.size() << " stages";
  }
  // A matrix entry outside [0, 1] is refused.
  ResponseKernel bad = kernel;
  bad.reemission[0][2] = -0.1;
  EXPECT_THROW(responseTaps(bad, kBin_s), std::invalid_argument);
}

}  // namespace
}  // namespace tofsim::physics
