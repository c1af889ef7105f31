#include "tofsim/pipeline/FiniteSegments.h"

#include <bit>
#include <cmath>
#include <cstdint>
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

// total = direct + indirect in float, so each component file adds up to it.
// Returns whether every sum is finite, which holds only when both terms are:
// inf + x, NaN + x and inf - inf are not finite. One pass over the three
// arrays is then all the check costs (the usual case).
bool FiniteSegments::addComponents(const float* direct, const float* indirect, std::size_t count) {
  if (totalSize_ < count) {  // uninitialised: every value is written just below
    total_.reset(new float[count]);
    totalSize_ = count;
  }
  float* total = total_.get();
  bool sumsFinite = true;
  for (std::size_t i = 0; i < count; ++i) {
    total[i] = direct[i] + indirect[i];
    // The exponent's bits all set: inf or NaN (a bit test, so the loop vectorises).
    sumsFinite &= (std::bit_cast<uint32_t>(total[i]) & 0x7f800000u) != 0x7f800000u;
  }
  return sumsFinite;
}

void FiniteSegments::consume(const capture::Segment& segment) {
  const std::size_t floats =
      segment.pixelCount * static_cast<std::size_t>(bins_) * capture::kChannels;
  const float* direct = segment.component(capture::kDirect);
  const float* indirect = segment.component(capture::kIndirect);
  if (!addComponents(direct, indirect, floats)) {
    // Some value is not finite: the components cleaned (copies) and counted,
    // their sum again, and what overflowed in it (two finite floats can).
    direct = finite(direct, floats, direct_, false);
    indirect = finite(indirect, floats, indirect_, false);
    addComponents(direct, indirect, floats);
    nonFinite_ += zeroNonFinite(total_.get(), floats);
  }
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
