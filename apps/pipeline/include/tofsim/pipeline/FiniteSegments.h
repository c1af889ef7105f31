#pragma once
// The first stage behind a renderer: NaN and infinity never reach the outputs
// silently. Each segment's direct and indirect light, their float sum (the
// total, component kTotal) and the bounces asked for are handed on as one
// segment to the consumers (files, sensors, arrays) with every value that is
// not finite written as 0 and counted (nonFiniteValues()): a component that
// has such values is copied and cleaned, the others (nearly always all) go
// on as the renderer made them, uncopied. The one rule for every output
// path: the CLI's files and the Python module's arrays.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "tofsim/capture/SegmentSink.h"

namespace tofsim::pipeline {

/// The component direct + indirect, in float, that FiniteSegments adds:
/// transient.npy's values.
inline constexpr std::string_view kTotal = "total";

/// Replaces NaN and +-inf by 0 in place; returns how many there were.
std::size_t zeroNonFinite(float* values, std::size_t count);

class FiniteSegments : public capture::SegmentSink {
 public:
  /// bounces: the bounce components (k of capture::bounceComponent) the
  /// consumers read, cleaned too (their values are counted in indirect's).
  FiniteSegments(capture::SegmentSink& next, int32_t bins, std::vector<int32_t> bounces);
  void consume(const capture::Segment& segment) override;
  /// How many values were NaN or infinite and replaced by 0 so far.
  std::size_t nonFiniteValues() const { return nonFinite_; }

 private:
  /// `values`, or where some are not finite `copy` of them cleaned (and
  /// counted unless `counted` already).
  const float* finite(const float* values, std::size_t count, std::vector<float>& copy,
                      bool counted);
  /// total_ = direct + indirect; whether every sum is finite.
  bool addComponents(const float* direct, const float* indirect, std::size_t count);

  capture::SegmentSink& next_;
  int32_t bins_;
  std::vector<int32_t> bounces_;
  std::vector<float> direct_, indirect_;  ///< copies, only where needed
  std::unique_ptr<float[]> total_;        ///< direct + indirect, totalSize_ floats
  std::size_t totalSize_ = 0;
  std::vector<std::vector<float>> bounceCopies_;  ///< one per bounces_ entry
  std::size_t nonFinite_ = 0;
};

}  // namespace tofsim::pipeline
