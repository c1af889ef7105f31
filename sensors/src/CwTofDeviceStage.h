#pragma once
// Private to the CW-ToF model: the device stage of one pixel, from its
// noise-free tap charges to its raws in e- (gains, dark current, shot noise,
// ambient suppression, full well, read noise, the difference of two taps,
// offset). The ADC is cwtofAdc (CwTofDevice.h).

#include <cstddef>
#include <vector>

#include "tofsim/sensors/CwTof.h"
#include "tofsim/sensors/CwTofDevice.h"
#include "tofsim/sensors/Random.h"

namespace tofsim::sensors {

class CwTofDeviceStage {
 public:
  CwTofDeviceStage(const CwTofParams& p, int32_t height, int32_t width);

  const CwTofFixedPattern& pattern() const { return pattern_; }
  /// The pixel's fixed-pattern time offset, s (0 without one).
  double delay_s(std::size_t px) const {
    return pattern_.delay_s.empty() ? 0.0 : pattern_.delay_s[px];
  }

  /// v holds the pixel's noise-free charges (Correlator::taps: tap A's F * N,
  /// then tap B's with two taps) and becomes its F * N raws in e-, the noise
  /// drawn from rng in today's order per raw (tap A's Poisson, tap B's, then
  /// the read noise of A and of B), so that with every default the values
  /// are the ideal model's. taps (when not null) gets each tap's charge as
  /// read (F * N * taps: raw-major, tap-minor). True when a tap reached the
  /// full well.
  bool pixel(std::vector<double>& v, std::size_t px, Rng& rng, double* taps) const;

 private:
  double gain(const std::vector<double>& map, double global, std::size_t px) const {
    return map.empty() ? global : map[px];
  }
  /// pixel() with noise_model: table.
  bool tablePixel(std::vector<double>& v, std::size_t px, Rng& rng, double* taps) const;
  /// The charge of a tap whose mean is `mean` (Poisson when shot_noise).
  double draw(double mean, Rng& rng) const;
  /// The full well: a charge at or above it is clipped to it and saturates.
  double well(double charge, bool& saturated) const;

  const CwTofParams& p_;
  CwTofFixedPattern pattern_;
};

}  // namespace tofsim::sensors
