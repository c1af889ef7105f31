#pragma once
// The camera's vignetting (capture::Vignetting) applied to the renderer's
// segments before anything reads them: each pixel's light times its gain,
// direct and every bounce; the indirect light is the float sum of the scaled
// bounces in bounce order, as the renderers add it, so the components still
// add up exactly (FiniteSegments then adds the total).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tofsim/capture/SegmentSink.h"

namespace tofsim::pipeline {

class VignettedSegments : public capture::SegmentSink {
 public:
  /// gains: one per image pixel (capture::vignettingGains), not empty.
  VignettedSegments(capture::SegmentSink& next, int32_t bins, std::vector<float> gains);
  void consume(const capture::Segment& segment) override;
  /// The direct and indirect light consumed so far before the gains (its
  /// finite values), in the renderer's terms like its light off the time
  /// axis (capture::RenderResult::offAxis), which no gain touches.
  double lightBeforeGain() const { return lightBeforeGain_; }

 private:
  capture::SegmentSink& next_;
  int32_t bins_;
  std::vector<float> gains_;
  std::vector<std::vector<float>> copies_;  ///< one per component of the segment
  double lightBeforeGain_ = 0.0;
};

}  // namespace tofsim::pipeline
