// The CPU's delayed response classes (core/cpu/src/ResponseClasses.h): a
// point sample deposited into an exponential class comes out, at the
// pixel's integrate step, as the closed-form bin integrals of its lifetime
// (convolved with its bin), the light past the axis booked after it; classes
// and pixels do not mix; the integrate step leaves the buffers zero, so the
// next segment's light is its own.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ResponseClasses.h"
#include "tofsim/physics/TemporalResponse.h"

namespace tofsim::cpu {
namespace {

constexpr int32_t kBins = 300;
constexpr double kBin_s = 10e-12;

// (1/tau) exp(-t/tau) convolved with bin 0's box, integrated over bin m (bins of 1).
double exponentialBinIntegral(double tau, int m) {
  if (m < 0) return 0.0;
  if (m == 0) return 1.0 - tau * (1.0 - std::exp(-1.0 / tau));
  return tau * (std::exp(1.0 / tau) - 1.0) * (std::exp(-m / tau) - std::exp(-(m + 1) / tau));
}

ResponseClasses twoClasses(std::size_t pixels) {
  physics::ResponseKernel exponential;
  exponential.lifetime_s = 500e-12;  // 50 bins
  exponential.fraction = 0.25;
  physics::ResponseKernel gaussian;
  gaussian.model = physics::ResponseModel::Gaussian;
  gaussian.mean_s = 300e-12;
  gaussian.sigma_s = 50e-12;
  ResponseClasses classes;
  classes.configure({{physics::responseTaps(exponential, kBin_s)},
                     {physics::responseTaps(gaussian, kBin_s)}},
                    pixels, kBins);
  return classes;
}

TEST(ResponseClassesTest, APointSampleComesOutAsItsLifetimesBinIntegrals) {
  ResponseClasses classes = twoClasses(4);
  ASSERT_EQ(classes.count(), 2u);
  const glm::vec3 energy(2.0f, 1.0f, 0.5f);
  physics::OffAxisSums lost;
  classes.deposit(1, 1, glm::vec3(200.6f, 0.0f, 0.0f), energy, lost);  // pixel 1, bin 200
  std::vector<float> histogram(kBins * 3, 0.0f);
  classes.integrateInto(1, histogram.data(), lost);
  for (int32_t n = 0; n < kBins; ++n) {
    const double unit = 0.25 * exponentialBinIntegral(50.0, n - 200) + (n == 200 ? 0.75 : 0.0);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(histogram[n * 3 + c], unit * energy[c], 2e-7 * unit * energy[c] + 1e-30) << n;
    }
  }
  // int_300^inf dt int_200^201 ds (1/tau) e^(-(t - s)/tau), per unit of energy.
  const double past = 0.25 * 50.0 * (std::exp(1.0 / 50.0) - 1.0) * std::exp(-100.0 / 50.0) * 3.5;
  EXPECT_NEAR(lost.after, past, 1e-6 * past);
  EXPECT_EQ(lost.before, 0.0f);
}

TEST(ResponseClassesTest, ClassesAndPixelsStayApartAndTheBuffersEndZero) {
  ResponseClasses classes = twoClasses(3);
  physics::OffAxisSums lost;
  classes.deposit(0, 2, glm::vec3(50.0f, 20.0f, 5.0f), glm::vec3(1.0f), lost);
  classes.deposit(2, 1, glm::vec3(10.2f, 0.0f, 0.0f), glm::vec3(1.0f), lost);
  std::vector<float> pixel0(kBins * 3, 0.0f), pixel1(kBins * 3, 0.0f), pixel2(kBins * 3, 0.0f);
  classes.integrateInto(1, pixel1.data(), lost);
  EXPECT_EQ(pixel1, std::vector<float>(kBins * 3, 0.0f));  // nothing deposited there
  classes.integrateInto(0, pixel0.data(), lost);
  // The Gaussian class alone: its light 30 bins later on average, none before bin 36.
  double mass = 0.0, mean = 0.0;
  for (int32_t n = 0; n < kBins; ++n) {
    mass += pixel0[n * 3];
    mean += pixel0[n * 3] * (n + 0.5);
    if (n < 36) {
      EXPECT_EQ(pixel0[n * 3], 0.0f) << n;
    }
  }
  EXPECT_NEAR(mass, 1.0, 1e-6);
  EXPECT_NEAR(mean / mass, 50.0 + 30.0, 1e-3);
  // Integrated again, and a new deposit after: only the new light.
  std::vector<float> again(kBins * 3, 0.0f);
  classes.integrateInto(0, again.data(), lost);
  EXPECT_EQ(again, std::vector<float>(kBins * 3, 0.0f));
  classes.integrateInto(2, pixel2.data(), lost);
  classes.deposit(2, 1, glm::vec3(10.2f, 0.0f, 0.0f), glm::vec3(1.0f), lost);
  std::vector<float> second(kBins * 3, 0.0f);
  classes.integrateInto(2, second.data(), lost);
  EXPECT_EQ(second, pixel2);
  // clear() drops what an unfinished segment left.
  classes.deposit(2, 2, glm::vec3(100.0f, 0.0f, 0.0f), glm::vec3(1.0f), lost);
  classes.clear();
  std::vector<float> cleared(kBins * 3, 0.0f);
  classes.integrateInto(2, cleared.data(), lost);
  EXPECT_EQ(cleared, std::vector<float>(kBins * 3, 0.0f));
}

}  // namespace
}  // namespace tofsim::cpu
