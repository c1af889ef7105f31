#include "tofsim/pipeline/PixelSpanSink.h"

#include <utility>

#include "tofsim/pipeline/FiniteSegments.h"

namespace tofsim::pipeline {

PixelSpanSink::PixelSpanSink(Forward forward, int32_t bounces)
    : forward_(std::move(forward)), bounces_(bounces) {}

void PixelSpanSink::consume(const capture::Segment& segment) {
  sensors::PixelSpan span{segment.firstPixel,
                          segment.pixelCount,
                          segment.component(kTotal),
                          segment.component(capture::kDirect),
                          {}};
  if (bounces_ == 1) span.bounces.push_back(segment.component(capture::kIndirect));
  if (bounces_ >= 2) {
    for (int32_t k = 1; k <= bounces_; ++k) {
      span.bounces.push_back(segment.component(capture::bounceComponent(k)));
    }
  }
  forward_(span);
}

}  // namespace tofsim::pipeline
