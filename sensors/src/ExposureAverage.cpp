#include "ExposureAverage.h"

#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

ExposureAverage::ExposureAverage(const VolumeShape& shape, std::size_t samples)
    : shape_(shape), samples_(samples) {
  TOFSIM_CHECK(samples_ >= 1);
}

void ExposureAverage::beginPass(std::size_t count) {
  TOFSIM_CHECK(next_ == 0 || next_ == shape_.pixelCount());
  if (count == 0) {
    weight_ = 0;
    return;
  }
  if (sum_.empty()) sum_.assign(shape_.pixelCount() * shape_.pixelFloats(), 0.0);
  weight_ = count;
  seen_ += count;
  next_ = 0;
  TOFSIM_CHECK(seen_ <= samples_);
}

void ExposureAverage::add(const PixelSpan& span) {
  if (weight_ == 0) return;  // a pass at none of the exposure's times
  TOFSIM_CHECK(span.firstPixel == next_);
  const std::size_t n = span.pixelCount * shape_.pixelFloats();
  double* sum = sum_.data() + span.firstPixel * shape_.pixelFloats();
  const auto w = static_cast<double>(weight_);
  for (std::size_t i = 0; i < n; ++i) sum[i] += w * span.volume[i];
  next_ += span.pixelCount;
}

PixelSpan ExposureAverage::mean() {
  TOFSIM_CHECK(seen_ == samples_ && next_ == shape_.pixelCount());
  mean_.resize(sum_.size());
  const auto S = static_cast<double>(samples_);
  for (std::size_t i = 0; i < sum_.size(); ++i) mean_[i] = static_cast<float>(sum_[i] / S);
  std::vector<double>().swap(sum_);
  PixelSpan span;
  span.pixelCount = shape_.pixelCount();
  span.volume = mean_.data();
  return span;
}

}  // namespace tofsim::sensors::detail
