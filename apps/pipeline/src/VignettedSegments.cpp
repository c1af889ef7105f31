#include "tofsim/pipeline/VignettedSegments.h"

#include <cmath>
#include <string_view>
#include <utility>

#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {
bool isBounce(std::string_view name) { return name.rfind("bounce", 0) == 0; }
}  // namespace

VignettedSegments::VignettedSegments(capture::SegmentSink& next, int32_t bins,
                                     std::vector<float> gains)
    : next_(next), bins_(bins), gains_(std::move(gains)) {
  TOFSIM_CHECK(!gains_.empty());
}

void VignettedSegments::consume(const capture::Segment& segment) {
  TOFSIM_CHECK(segment.firstPixel + segment.pixelCount <= gains_.size());
  const std::size_t perPixel = static_cast<std::size_t>(bins_) * capture::kChannels;
  const std::size_t floats = segment.pixelCount * perPixel;
  copies_.resize(segment.components.size());
  capture::Segment scaled{segment.firstPixel, segment.pixelCount, {}};
  std::vector<float>* indirect = nullptr;
  bool bounces = false;
  for (std::size_t c = 0; c < segment.components.size(); ++c) {
    const capture::SegmentComponent& in = segment.components[c];
    std::vector<float>& out = copies_[c];
    out.resize(floats);
    for (std::size_t p = 0; p < segment.pixelCount; ++p) {
      const float gain = gains_[segment.firstPixel + p];
      const float* from = in.values + p * perPixel;
      float* to = out.data() + p * perPixel;
      for (std::size_t i = 0; i < perPixel; ++i) to[i] = from[i] * gain;
    }
    if (in.name == capture::kDirect || in.name == capture::kIndirect) {
      // The light as the renderer gave it (what it counts off the axis too);
      // a value that is not finite is written as 0 (FiniteSegments).
      double sum = 0.0;
      for (std::size_t i = 0; i < floats; ++i)
        sum += std::isfinite(in.values[i]) ? in.values[i] : 0.0f;
      lightBeforeGain_ += sum;
    }
    if (in.name == capture::kIndirect) indirect = &out;
    bounces = bounces || isBounce(in.name);
    scaled.components.push_back({in.name, out.data()});
  }
  if (indirect != nullptr && bounces) {
    // The renderers' indirect is the float sum of the bounces in order.
    std::fill(indirect->begin(), indirect->end(), 0.0f);
    for (const capture::SegmentComponent& b : scaled.components) {
      if (!isBounce(b.name)) continue;
      for (std::size_t i = 0; i < floats; ++i) (*indirect)[i] += b.values[i];
    }
  }
  next_.consume(scaled);
}

}  // namespace tofsim::pipeline
