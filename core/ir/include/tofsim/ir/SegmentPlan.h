#pragma once
// Splits the image's pixels into segments: runs of consecutive pixels whose
// buffers fit the memory budget and the device's limits. Segments depend only
// on these sizes, and every pixel is computed the same way whatever segment it
// is in, so the volume's bytes do not depend on the budget.

#include <cstddef>

namespace tofsim::ir {

struct PixelRange {
  std::size_t first = 0;
  std::size_t count = 0;
};

struct SegmentPlan {
  std::size_t pixelCount = 0;        ///< of the whole image
  std::size_t pixelsPerSegment = 0;  ///< > 0
  std::size_t segmentCount = 0;
  std::size_t bytesPerSegment = 0;  ///< device bytes of one segment's buffers

  /// Pixels of segment s (the last one may be shorter).
  PixelRange segment(std::size_t s) const;
};

/// Segments of exactly `pixelsPerSegment` pixels (> 0; the last one shorter).
SegmentPlan fixedSegments(std::size_t pixelCount, std::size_t pixelsPerSegment,
                          std::size_t bytesPerPixel);

/// `floatsPerPixel`: T * C. `buffersPerPixel`: how many volumes (direct,
/// indirect) a segment holds; each pixel also costs two floats for the
/// light off the axis (before it, after it). One pixel's histogram must fit `maxBufferBytes`
/// (validated before, by the driver). Throws InputError when the budget cannot
/// hold one pixel.
SegmentPlan planSegments(std::size_t pixelCount, std::size_t floatsPerPixel, int buffersPerPixel,
                         std::size_t budgetBytes, std::size_t maxBufferBytes,
                         std::size_t maxPixelsPerPass);

}  // namespace tofsim::ir
