#pragma once
// Cleaned segments (FiniteSegments.h) handed on as the sensors' pixel spans
// (sensors/SensorStream.h): the total, its direct component and, when asked,
// bounces 1..N. The sensors and the video's bin-major copy take them.

#include <cstdint>
#include <functional>

#include "tofsim/capture/SegmentSink.h"
#include "tofsim/sensors/SensorStream.h"

namespace tofsim::pipeline {

class PixelSpanSink : public capture::SegmentSink {
 public:
  using Forward = std::function<void(const sensors::PixelSpan&)>;

  /// bounces N >= 1: the spans carry bounces 1..N too (bounce 1 is the
  /// indirect light when N = 1: the IR's bounce1, the reference's one
  /// bounce; for N >= 2 the segments must carry the cleaned bounce1..N).
  PixelSpanSink(Forward forward, int32_t bounces);
  void consume(const capture::Segment& segment) override;

 private:
  Forward forward_;
  int32_t bounces_;
};

}  // namespace tofsim::pipeline
