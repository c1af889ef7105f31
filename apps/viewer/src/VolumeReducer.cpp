#include "VolumeReducer.h"

#include <algorithm>

namespace tofsim::viewer {

VolumeReducer::VolumeReducer(std::size_t height, std::size_t width, std::size_t bins,
                             std::size_t channels, std::size_t budget)
    : height_(height),
      width_(width),
      bins_(bins),
      channels_(channels),
      reduction_(planReduction(height, width, bins, channels, budget)),
      sums_(reducedHeight() * reducedWidth() * reducedBins() * channels, 0.0),
      timeSum_(height * width * channels, 0.0f) {}

void VolumeReducer::addPixel(std::size_t y, std::size_t x, const float* values) {
  const std::size_t block =
      (y / reduction_.pixelBlock) * reducedWidth() + x / reduction_.pixelBlock;
  double* out = sums_.data() + block * reducedBins() * channels_;
  float* steady = timeSum_.data() + (y * width_ + x) * channels_;
  for (std::size_t t = 0; t < bins_; ++t) {
    for (std::size_t c = 0; c < channels_; ++c) {
      const float v = values[t * channels_ + c];
      out[(t / reduction_.binRun) * channels_ + c] += v;
      steady[c] += v;
    }
  }
}

std::vector<float> VolumeReducer::reduced() const {
  const std::size_t b = reduction_.pixelBlock, perBlock = reducedBins() * channels_;
  std::vector<float> out(sums_.size());
  for (std::size_t by = 0; by < reducedHeight(); ++by) {
    for (std::size_t bx = 0; bx < reducedWidth(); ++bx) {
      // A partial block at the image's edge averages the pixels it has.
      const std::size_t pixels =
          (std::min(height_, (by + 1) * b) - by * b) * (std::min(width_, (bx + 1) * b) - bx * b);
      const std::size_t at = (by * reducedWidth() + bx) * perBlock;
      for (std::size_t i = 0; i < perBlock; ++i) {
        out[at + i] = static_cast<float>(sums_[at + i] / static_cast<double>(pixels));
      }
    }
  }
  return out;
}

}  // namespace tofsim::viewer
