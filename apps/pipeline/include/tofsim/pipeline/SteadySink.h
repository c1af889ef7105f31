#pragma once
// The steady image: the total volume (component kTotal, FiniteSegments.h)
// summed over time, accumulated in double as segments arrive.

#include <vector>

#include "tofsim/capture/SegmentSink.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::pipeline {

class SteadySink : public capture::SegmentSink {
 public:
  SteadySink(int32_t width, int32_t height, int32_t bins);
  void consume(const capture::Segment& segment) override;
  /// sum over t of the total so far (transient.npy's once all arrived).
  Image steady() const;

 private:
  int32_t width_, height_, bins_;
  std::vector<double> sum_;
};

}  // namespace tofsim::pipeline
