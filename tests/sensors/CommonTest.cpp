#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "TestVolumes.h"
#include "tofsim/sensors/Common.h"
#include "tofsim/sensors/TimeKernel.h"
#include "tofsim/util/Error.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::sensors {
namespace {

TEST(CommonTest, ResamplingConservesEnergyAndSplitsByOverlap) {
  TimeAxis from{1e-9, 10e-12, 50};
  TimeAxis to{0.9e-9, 7e-12, 120};  // covers [0.9, 1.74) ns, the render [1, 1.5) ns
  std::vector<double> in(50);
  for (int i = 0; i < 50; ++i) in[i] = 1.0 + (i * 37 % 11);
  std::vector<double> out;
  resampleEnergy(in, from, to, out);
  const double sumIn = std::accumulate(in.begin(), in.end(), 0.0);
  EXPECT_NEAR(std::accumulate(out.begin(), out.end(), 0.0), sumIn, 1e-12 * sumIn);
  // Bin [1.0, 1.01) ns lies in target bins 14 ([0.998, 1.005)) and 15.
  std::vector<double> one(50, 0.0);
  one[0] = 1.0;
  resampleEnergy(one, from, to, out);
  EXPECT_NEAR(out[14], 5.0 / 10.0, 1e-9);
  EXPECT_NEAR(out[15], 5.0 / 10.0, 1e-9);
}

// The axis a sensor bins on keeps the render's medium and legs, so depths
// from the instrument bins mean what depths from the render's bins mean.
TEST(CommonTest, InstrumentAxisKeepsTheMediumAndTheLegsTimed) {
  TimeAxis render{0.0, 10e-12, 100};
  render.index_of_refraction = 1.5;
  render.camera_unwarp = true;
  InstrumentBins bins;
  bins.bin_width_s = 40e-12;
  const TimeAxis axis = resolveBins(bins, render);
  EXPECT_EQ(axis.index_of_refraction, 1.5);
  EXPECT_TRUE(axis.camera_unwarp);
  EXPECT_EQ(axis.bins, 25);
  // One leg in a medium of 1.5: depth = (c / 1.5) t.
  EXPECT_DOUBLE_EQ(axis.depthOf_m(1e-9), kSpeedOfLight_m_per_s / 1.5 * 1e-9);
  render.camera_unwarp = false;  // two legs: half of that
  EXPECT_DOUBLE_EQ(render.depthOf_m(1e-9), kSpeedOfLight_m_per_s / 1.5 * 1e-9 / 2);
}

TEST(CommonTest, WeightedChannelsAndRadiometricScale) {
  TransientVolume v = test::makeVolume(1, 1, 0.0, 1e-12, 2, 3);
  v.at(0, 0, 1, 0) = 1.0f;
  v.at(0, 0, 1, 1) = 2.0f;
  v.at(0, 0, 1, 2) = 4.0f;
  SensorCommon common;
  common.channel.weights = {0.5, 0.25, 0.125};
  common.radiometry.source_scale = 3.0;
  std::vector<double> s;
  pixelSignal(v, common, 0, 0, s);
  EXPECT_DOUBLE_EQ(s[1], 3.0 * 1.5);
  common.channel.weights.clear();
  common.channel.index = 2;
  common.radiometry.wavelength_m = 850e-9;  // photons per joule: lambda / (h c)
  pixelSignal(v, common, 0, 0, s);
  EXPECT_NEAR(s[1] / (3.0 * 4.0) / (850e-9 / (6.62607015e-34 * 299792458.0)), 1.0, 1e-12);
  common.channel.index = 3;
  EXPECT_THROW(checkChannelSelection(common.channel, v), InputError);
}

TEST(CommonTest, GaussianKernelHasConfiguredWidth) {
  const double sigma = 4.0;
  const BinKernel k = gaussianKernel(sigma, 1.0);
  double s = 0.0, m = 0.0, m2 = 0.0;
  for (std::size_t j = 0; j < k.weights.size(); ++j) {
    const double d = k.first + static_cast<double>(j);
    s += k.weights[j];
    m += d * k.weights[j];
    m2 += d * d * k.weights[j];
  }
  EXPECT_NEAR(s, 1.0, 1e-12);
  EXPECT_NEAR(m, 0.0, 1e-9);
  // Source uniform in its bin and detection binned: + 1/12 + 1/12.
  EXPECT_NEAR(m2, sigma * sigma + 1.0 / 6.0, 1e-3);
  EXPECT_NEAR(fwhmToSigma(2.0 * std::sqrt(2.0 * std::log(2.0))), 1.0, 1e-15);
}

}  // namespace
}  // namespace tofsim::sensors
