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

namespace {

// A read-only pass, at memory speed: whether a component needs its copy.
bool allFinite(const float* values, std::size_t count) {
  bool finite = true;
  for (std::size_t i = 0; i < count; ++i) finite &= std::isfinite(values[i]);
  return finite;
}

}  // namespace

FiniteSegments::FiniteSegments(capture::SegmentSink& next, int32_t bins,
                               std::vector<int32_t> bounces)
    : next_(next), bins_(bins), bounces_(std::move(bounces)), bounceCopies_(bounces_.size()) {}

const float* FiniteSegments::finite(const float* values, std::size_t count,
                                    std::vector<float>& copy, bool counted) {
  if (allFinite(values, count)) return values;  // the renderer's own buffer, uncopied
  copy.assign(values, values + count);
  const std::size_t rejected = zeroNonFinite(copy.data(), count);
  if (!counted) nonFinite_ += rejected;
  return copy.data();
}

void FiniteSegments::consume(const capture::Segment& segment) {
  const std::size_t floats =
      segment.pixelCount * static_cast<std::size_t>(bins_) * capture::kChannels;
  const float* direct = finite(segment.component(capture::kDirect), floats, direct_, false);
  const float* indirect = finite(segment.component(capture::kIndirect), floats, indirect_, false);
  if (totalSize_ < floats) {  // uninitialised: every value is written just below
    total_.reset(new float[floats]);
    totalSize_ = floats;
  }
  // total = direct + indirect in float, so each component file adds up to it.
  for (std::size_t i = 0; i < floats; ++i) total_[i] = direct[i] + indirect[i];
  nonFinite_ += zeroNonFinite(total_.get(), floats);  // two finite floats can overflow
  capture::Segment clean{
      segment.firstPixel,
      segment.pixelCount,
      {{capture::kDirect, direct}, {capture::kIndirect, indirect}, {kTotal, total_.get()}}};
  for (std::size_t i = 0; i < bounces_.size(); ++i) {
    const std::string_view name = capture::bounceComponent(bounces_[i]);
    // Already counted in indirect's.
    clean.components.push_back(
        {name, finite(segment.component(name), floats, bounceCopies_[i], true)});
  }
  next_.consume(clean);
}

}  // namespace tofsim::pipeline
