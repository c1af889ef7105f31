#pragma once
// Private to the CW-ToF model: cwtof_psf_error, the noise-free depth with the
// lens's stray light (camera.psf) minus the noise-free depth without it, per
// pixel. The sharp depth comes either from the light before the PSF
// (SensorStream::consumeBeforePsf, the PSF on the transient) or from the
// sensor's own charges before it convolves them (StreamOptions::psfOnRaws).

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "CwTofCorrelator.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

class CwTofPsfError {
 public:
  explicit CwTofPsfError(std::size_t pixels)
      : sharp_(pixels, std::numeric_limits<double>::quiet_NaN()), lit_(pixels, 0) {}

  /// The pixel's noise-free depth without the PSF; lit: its light had an
  /// amplitude (a depth), else the error there is NaN.
  void sharp(std::size_t px, double depth_m, bool lit) {
    sharp_[px] = lit ? depth_m : std::numeric_limits<double>::quiet_NaN();
    ++sharpPixels_;
  }
  /// Whether the pixel's light with the PSF has an amplitude.
  void blurred(std::size_t px, bool lit) { lit_[px] = lit ? 1 : 0; }

  /// blurred - sharp per pixel, folded into the depth's range as the other
  /// errors are (a whole number of wraps is not stray light); NaN where
  /// either has no depth.
  std::vector<float> errors(const std::vector<double>& blurredDepth_m, double range_m) const {
    TOFSIM_CHECK_EQ(sharpPixels_, sharp_.size());  // every pixel's light before the PSF came
    std::vector<float> e(sharp_.size(), std::numeric_limits<float>::quiet_NaN());
    for (std::size_t px = 0; px < e.size(); ++px) {
      if (!lit_[px] || std::isnan(sharp_[px])) continue;
      e[px] = static_cast<float>(wrapSigned(blurredDepth_m[px] - sharp_[px], range_m));
    }
    return e;
  }

 private:
  std::vector<double> sharp_;  // (H, W), m; NaN: no light before the PSF
  std::vector<char> lit_;      // (H, W): the light with the PSF has an amplitude
  std::size_t sharpPixels_ = 0;
};

}  // namespace tofsim::sensors
