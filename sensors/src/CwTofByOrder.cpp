#include "CwTofByOrder.h"

#include <cmath>
#include <limits>

#include "tofsim/util/Error.h"

namespace tofsim::sensors {

OrderDepths::OrderDepths(const Correlator& correlator, const SensorCommon& common,
                         const VolumeShape& shape, int32_t bounces, double unwrapRange_m)
    : correlator_(correlator),
      common_(common),
      shape_(shape),
      orders_(bounces + 1),
      unwrapRange_m_(unwrapRange_m) {
  TOFSIM_CHECK(bounces >= 0);
  depth_m_.assign(static_cast<std::size_t>(orders_) * shape.pixelCount(),
                  std::numeric_limits<double>::quiet_NaN());
}

void OrderDepths::pixel(const PixelSpan& span, std::size_t offset, std::size_t px) {
  TOFSIM_CHECK(span.directOnly != nullptr);
  TOFSIM_CHECK_EQ(span.bounces.size(), static_cast<std::size_t>(orders_ - 1));
  // No ambient: it adds the same to every phase step, so it moves no phase,
  // and a pixel without light keeps a zero amplitude (no made-up depth).
  for (int32_t k = 0; k < orders_; ++k) {
    const float* values = k == 0 ? span.directOnly : span.bounces[k - 1];
    pixelSignal(values + offset, shape_.axis.bins, shape_.channels, common_, signal_);
    correlator_.raw(signal_, 0.0, raw_);
    if (k == 0) sum_.assign(raw_.size(), 0.0);
    for (std::size_t j = 0; j < raw_.size(); ++j) sum_[j] += raw_[j];
    const double depth = correlator_.depth(sum_, phases_, amplitudes_, unwrapRange_m_);
    if (amplitudes_[0] > 0.0) depth_m_[k * shape_.pixelCount() + px] = depth;
  }
}

std::vector<float> OrderDepths::errors(const Image& gt, double range_m) const {
  const std::size_t HW = shape_.pixelCount();
  std::vector<float> out(depth_m_.size(), std::numeric_limits<float>::quiet_NaN());
  for (std::size_t px = 0; px < HW; ++px) {
    const float truth =
        gt.at(static_cast<int32_t>(px / shape_.width), static_cast<int32_t>(px % shape_.width), 0);
    if (!(std::isfinite(truth) && truth > 0.0f)) continue;
    for (int32_t k = 0; k < orders_; ++k) {
      const double d = depth_m_[k * HW + px];
      if (std::isfinite(d)) out[k * HW + px] = static_cast<float>(wrapSigned(d - truth, range_m));
    }
  }
  return out;
}

}  // namespace tofsim::sensors
