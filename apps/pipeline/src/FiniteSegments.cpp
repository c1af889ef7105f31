#include "tofsim/pipeline/FiniteSegments.h"

#include <cmath>
#include <utility>

namespace tofsim::pipeline {

std::size_t zeroNonFinite(float* values, std::size_t count) {
  std::size_t rejected = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (!std::isfinite(values[i])) {
      values[i] = 0.0f;
      ++rejected;
    }
  }
  return rejected;
}

FiniteSegments::FiniteSegments(capture::SegmentSink& next, int32_t bins,
                               std::vector<int32_t> bounces)
    : next_(next), bins_(bins), bounces_(std::move(bounces)), bounceCopies_(bounces_.size()) {}

void FiniteSegments::consume(const capture::Segment& segment) {
  const std::size_t floats =
      segment.pixelCount * static_cast<std::size_t>(bins_) * capture::kChannels;
  const float* direct = segment.component(capture::kDirect);
  const float* indirect = segment.component(capture::kIndirect);
  direct_.assign(direct, direct + floats);
  indirect_.assign(indirect, indirect + floats);
  nonFinite_ += zeroNonFinite(direct_.data(), floats);
  nonFinite_ += zeroNonFinite(indirect_.data(), floats);
  total_.resize(floats);
  // total = direct + indirect in float, so each component file adds up to it.
  for (std::size_t i = 0; i < floats; ++i) total_[i] = direct_[i] + indirect_[i];
  nonFinite_ += zeroNonFinite(total_.data(), floats);  // two finite floats can overflow
  capture::Segment clean{segment.firstPixel,
                         segment.pixelCount,
                         {{capture::kDirect, direct_.data()},
                          {capture::kIndirect, indirect_.data()},
                          {kTotal, total_.data()}}};
  for (std::size_t i = 0; i < bounces_.size(); ++i) {
    const std::string_view name = capture::bounceComponent(bounces_[i]);
    const float* bounce = segment.component(name);
    bounceCopies_[i].assign(bounce, bounce + floats);
    zeroNonFinite(bounceCopies_[i].data(), floats);  // already counted in indirect's
    clean.components.push_back({name, bounceCopies_[i].data()});
  }
  next_.consume(clean);
}

}  // namespace tofsim::pipeline
