#pragma once
// Private to the CW-ToF model: the multipath error of each bounce order
// (CwTofParams::multipath_by_order). The correlation is linear in the
// transient, so each pixel's noise-free raw values of the direct component
// and of each bounce are correlated once and prefix-summed: order k holds
// direct + bounces 1..k, and order N the whole light. Only the N + 1 depths
// per pixel are kept; the ground truth they are compared with comes in
// finish().

#include <cstddef>
#include <cstdint>
#include <vector>

#include "CwTofCorrelator.h"
#include "tofsim/sensors/SensorStream.h"

namespace tofsim::sensors {

class OrderDepths {
 public:
  /// `bounces` = N; the depths of orders 0..N are kept for `pixels` pixels.
  OrderDepths(const Correlator& correlator, const SensorCommon& common, const VolumeShape& shape,
              int32_t bounces, double unwrapRange_m);

  int32_t orders() const { return orders_; }
  /// Pixel px of the image, at `offset` floats into the span's arrays.
  void pixel(const PixelSpan& span, std::size_t offset, std::size_t px);
  /// (N + 1, H, W): depth of order k - truth, folded into [-R/2, R/2] of
  /// range_m; NaN where the truth is unknown (<= 0, NaN) or the order's light
  /// is zero (its amplitude at the first frequency is 0: no phase).
  std::vector<float> errors(const Image& groundTruthDepth_m, double range_m) const;

 private:
  const Correlator& correlator_;
  const SensorCommon& common_;
  VolumeShape shape_;
  int32_t orders_;
  double unwrapRange_m_;
  std::vector<double> depth_m_;  // (N + 1, H, W), NaN where the order has no light
  std::vector<double> signal_, raw_, sum_, phases_, amplitudes_;  // per-pixel scratch
};

}  // namespace tofsim::sensors
