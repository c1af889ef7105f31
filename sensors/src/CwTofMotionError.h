#pragma once
// Private to the CW-ToF model: cwtof_motion_error, in a frame of a capture
// sequence whose raws are taken at different times (capture_order,
// integration_time, readout_gap). Per pixel: the noise-free depth of the raws
// as the device takes them, each of the scene at its own times, minus the
// noise-free depth of the light at the frame's time alone through the same
// device (its delay, the lens's PSF): the motion artifact and nothing else
// (no noise, no multipath, which both depths share).

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "CwTofCorrelator.h"

namespace tofsim::sensors {

class CwTofMotionError {
 public:
  explicit CwTofMotionError(std::size_t pixels)
      : still_(pixels, std::numeric_limits<double>::quiet_NaN()),
        error_(pixels, std::numeric_limits<float>::quiet_NaN()) {}

  /// The pixel's depth at the frame's time; lit: its light had an amplitude.
  void still(std::size_t px, double depth_m, bool lit) {
    still_[px] = lit ? depth_m : std::numeric_limits<double>::quiet_NaN();
  }
  /// The depth of its raws as taken: the error, folded into the depth's
  /// range as the other errors are; NaN where either has no depth.
  void taken(std::size_t px, double depth_m, bool lit, double range_m) {
    if (!lit || std::isnan(still_[px])) return;
    error_[px] = static_cast<float>(wrapSigned(depth_m - still_[px], range_m));
  }
  std::vector<float> errors() const { return error_; }

 private:
  std::vector<double> still_;  // (H, W), m
  std::vector<float> error_;   // (H, W), m
};

}  // namespace tofsim::sensors
