#include "tofsim/pipeline/SteadySink.h"

#include <algorithm>

#include "tofsim/pipeline/FiniteSegments.h"

namespace tofsim::pipeline {

namespace {
constexpr int32_t kChannels = capture::kChannels;
}  // namespace

SteadySink::SteadySink(int32_t width, int32_t height, int32_t bins)
    : width_(width),
      height_(height),
      bins_(bins),
      sum_(static_cast<std::size_t>(width) * height * kChannels, 0.0) {}

void SteadySink::consume(const capture::Segment& segment) {
  const std::size_t pixelFloats = static_cast<std::size_t>(bins_) * kChannels;
  const float* total = segment.component(kTotal);
  for (std::size_t p = 0; p < segment.pixelCount; ++p) {
    double* out = &sum_[(segment.firstPixel + p) * kChannels];
    const float* in = &total[p * pixelFloats];
    for (int32_t t = 0; t < bins_; ++t) {
      for (int32_t c = 0; c < kChannels; ++c) out[c] += in[t * kChannels + c];
    }
  }
}

Image SteadySink::steady() const {
  Image image(width_, height_, kChannels);
  std::transform(sum_.begin(), sum_.end(), image.data.begin(),
                 [](double v) { return static_cast<float>(v); });
  return image;
}

}  // namespace tofsim::pipeline
