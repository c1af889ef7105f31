#pragma once
// Private to the CW-ToF model: the outputs of the device stage, filled pixel
// by pixel in finish(): the raws in DN, the phases, amplitude and depth the
// device computes from them, the saturation mask, the per-tap charges and
// the fixed pattern.

#include <cstddef>
#include <vector>

#include "CwTofCorrelator.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/sensors/SensorOutput.h"

namespace tofsim::sensors {

class CwTofDeviceImages {
 public:
  CwTofDeviceImages(const CwTofParams& p, std::size_t pixels);

  /// Where the pixel's per-tap charges go (CwTofDeviceStage::pixel), or
  /// nullptr without output_taps.
  double* taps() { return taps_.empty() ? nullptr : scratchTaps_.data(); }

  /// Pixel px of raws `raw_e` (F * N, e-), `saturated` from the full well:
  /// its DN, the device's phases and depth (NaN when any raw saturated).
  void pixel(std::size_t px, const std::vector<double>& raw_e, bool saturated,
             const Correlator& correlator, double unwrapRange_m);

  /// The outputs (only those the parameters ask for), appended to outs.
  void add(std::vector<SensorOutput>& outs, int32_t H, int32_t W, double depthRange_m,
           const CwTofFixedPattern& pattern);

 private:
  const CwTofParams& p_;
  std::size_t HW_, FN_;
  bool adc_, flagged_;
  std::vector<float> dn_, phase_, amplitude_, depth_, saturated_, taps_;  // (F, N[, 2], H, W) ...
  std::vector<double> scratchTaps_, code_, phases_, amps_;                // per pixel
};

}  // namespace tofsim::sensors
