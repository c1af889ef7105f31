// The APD's cell-averaging CFAR (Apd.h, `threshold_mode: ca_cfar`): each
// sample's threshold is its training cells' mean m_t (N a side beyond G
// guard cells) + z kappa sigma(m_t). Closed form (sensors/README.md,
// "CA-CFAR"): for Gaussian noise on a linear background the two windows'
// mean is the background's at t, and x_t - m_t is normal with variance
// kappa^2 sigma^2, kappa^2 = sum((c * h)^2) / sum(h^2) (c: 1 at t, -1 / 2N on
// the training cells; h the filter), 1 + 1 / (2 N) for white samples; so
// P(x_t > threshold) = Q(z) = false_alarm. Tested on a steep ramp whose
// noise is mostly the signal's own shot noise (sigma grows along it): the
// rate of samples above their thresholds against false_alarm (5 sigma);
// the receiver's noise-level CFAR on the same ramp fires on most samples.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "TestVolumes.h"
#include "tofsim/sensors/Apd.h"

namespace tofsim::sensors {
namespace {

// Unity gain (F = 1: Poisson primaries, Gaussian at 1e4 and more), white
// samples, a little TIA noise; 1 ns samples counting photo-electrons.
ApdParams rampApd() {
  ApdParams p;
  p.common = SensorCommon{};
  p.gain = 1.0;
  p.dark_current_bulk_A = 0.0;
  p.dark_current_surface_A = 0.0;
  p.tia_noise_A_per_rtHz = 5e-13;  // 11 nA a sample: below the shot noise
  p.bandwidth_Hz = 0.0;
  p.pulse_fwhm_s = 0.0;
  p.threshold_mode = ApdThreshold::CaCfar;
  p.cfar_guard_cells = 2;
  p.cfar_training_cells = 4;
  p.false_alarm = 1e-2;
  return p;
}

TEST(ApdCfarTest, KappaIsTheSpreadOfASampleLessItsTrainingMean) {
  ApdParams p = rampApd();
  const TimeAxis axis = test::makeVolume(1, 1, 0.0, 1e-9, 64).axis();
  const ApdReceiver white = apdReceiver(p, axis);
  EXPECT_NEAR(white.cfarKappa[32], std::sqrt(1.0 + 1.0 / 8.0), 1e-12);  // N = 4 a side
  EXPECT_NEAR(white.cfarKappa[0], std::sqrt(1.0 + 1.0 / 4.0), 1e-12);   // one side at the start
  EXPECT_NEAR(white.cfarZ, 2.3263478740, 1e-8);
  // A filter correlates neighbours: kappa from its kernel, between the
  // white value and sqrt(2) (the guard cells keep the CUT nearly apart).
  p.bandwidth_Hz = 150e6;
  const ApdReceiver filtered = apdReceiver(p, axis);
  EXPECT_GT(filtered.cfarKappa[32], white.cfarKappa[32]);
  EXPECT_LT(filtered.cfarKappa[32], std::sqrt(2.0));
  // The noise model at a mean current: Poisson primaries through unity gain.
  const double q = 1.602176634e-19, dt = 1e-9, n = 2.5e4;
  const double thermal2 = 2.5e-25 / (2.0 * dt);
  EXPECT_NEAR(apdNoiseSigma_A(white, q * n / dt), std::sqrt(q * q * n / (dt * dt) + thermal2),
              1e-9 * apdNoiseSigma_A(white, q * n / dt));
}

TEST(ApdCfarTest, FalseAlarmsOnASlopedBackgroundAreTheClosedForm) {
  const ApdParams p = rampApd();
  const int32_t W = 64, H = 64, T = 256;
  TransientVolume ramp = test::makeVolume(W, H, 0.0, 1e-9, T);
  // 1e4 .. 1e5 primaries a sample: the mean climbs 1 - 3.5 sigma a sample.
  for (int32_t y = 0; y < H; ++y) {
    for (int32_t x = 0; x < W; ++x) {
      for (int32_t t = 0; t < T; ++t) ramp.at(y, x, t, 0) = 1e4f + 9e4f * t / (T - 1);
    }
  }
  const ApdReceiver rx = apdReceiver(p, ramp.axis());
  const std::vector<SensorOutput> out = runApd(ramp, p, 23);
  const std::vector<float>& v = test::array(out, "apd_waveforms").data;
  const int32_t reach = p.cfar_guard_cells + p.cfar_training_cells;
  double above = 0.0, aboveNoiseLevel = 0.0, n = 0.0;
  std::vector<double> samples(T), thresholds;
  for (int32_t px = 0; px < W * H; ++px) {
    for (int32_t t = 0; t < T; ++t) samples[t] = v[static_cast<std::size_t>(px) * T + t];
    apdThresholds(p, rx, samples, thresholds);
    for (int32_t t = reach; t < T - reach; ++t, n += 1.0) {  // both windows whole
      above += samples[t] > thresholds[t] ? 1.0 : 0.0;
      aboveNoiseLevel += samples[t] > rx.threshold_A ? 1.0 : 0.0;
    }
  }
  const double expected = n * p.false_alarm;
  const double sigma = std::sqrt(expected * (1.0 - p.false_alarm));
  EXPECT_LT(std::fabs(above - expected), 5.0 * sigma) << above << " vs " << expected;
  EXPECT_GT(aboveNoiseLevel, 0.9 * n);  // the receiver's own CFAR follows no slope
}

}  // namespace
}  // namespace tofsim::sensors
