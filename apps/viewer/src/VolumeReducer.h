#pragma once
// A volume (height, width, bins, channels) reduced pixel by pixel for the
// page: pixels averaged over blocks and bins summed in runs (Downsample.h),
// and its sum over time kept at full resolution (the steady image).

#include <cstddef>
#include <nlohmann/json.hpp>
#include <vector>

#include "Downsample.h"

namespace tofsim::viewer {

class VolumeReducer {
 public:
  VolumeReducer(std::size_t height, std::size_t width, std::size_t bins, std::size_t channels,
                std::size_t budget);
  const Reduction& reduction() const { return reduction_; }
  /// The pixel (y, x): bins x channels values, channel fastest.
  void addPixel(std::size_t y, std::size_t x, const float* values);
  /// The reduced volume, C order (h, w, bins, channels).
  std::vector<float> reduced() const;
  /// The full-resolution (height, width, channels) sum over time.
  const std::vector<float>& timeSum() const { return timeSum_; }
  std::size_t height() const { return height_; }
  std::size_t width() const { return width_; }
  std::size_t reducedHeight() const { return reducedSize(height_, reduction_.pixelBlock); }
  std::size_t reducedWidth() const { return reducedSize(width_, reduction_.pixelBlock); }
  std::size_t reducedBins() const { return reducedSize(bins_, reduction_.binRun); }

 private:
  std::size_t height_, width_, bins_, channels_;
  Reduction reduction_;
  std::vector<double> sums_;
  std::vector<float> timeSum_;
};

}  // namespace tofsim::viewer
