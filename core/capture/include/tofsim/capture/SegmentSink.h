#pragma once
// Receives the transient volume in segments: runs of consecutive pixels in row
// order, each pixel holding T bins x C channels (the (H, W, T, C) layout), so
// every segment is one contiguous slice of transient.npy. Segments arrive in
// order and cover the image exactly once; nothing needs the whole volume in
// memory.

#include <cstddef>

namespace tofsim::capture {

struct Segment {
  std::size_t firstPixel = 0;  ///< y * width + x of the first pixel
  std::size_t pixelCount = 0;
  const float* direct = nullptr;    ///< pixelCount * T * C floats
  const float* indirect = nullptr;  ///< same size; all zero when indirect light is off
};

class SegmentSink {
 public:
  virtual ~SegmentSink() = default;
  virtual void consume(const Segment& segment) = 0;
};

}  // namespace tofsim::capture
