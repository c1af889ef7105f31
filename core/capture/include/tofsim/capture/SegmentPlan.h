#pragma once
// Splits the image's pixels into segments: runs of consecutive pixels whose
// buffers fit the memory budget and the device's limits. Segments depend only
// on these sizes, and every pixel is computed the same way whatever segment it
// is in, so the volume's bytes do not depend on the budget.

#include <cstddef>

namespace tofsim::capture {

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

/// What one pixel of a segment holds: `volumes` float histograms of
/// `floatsPerPixel` (T * C) floats (direct, indirect), `footprintBuffers`
/// difference buffers of as many doubles (the pixel footprint's, each delayed
/// response class's and a cascades' scratch: regions of one buffer on GL,
/// core/physics/temporal_response.md), `otherBytes` more (the response
/// stage's running sums), and two floats for the light off the axis (before
/// it, after it).
struct PixelBuffers {
  std::size_t floatsPerPixel = 0;
  int volumes = 2;
  int footprintBuffers = 0;
  std::size_t otherBytes = 0;

  std::size_t bytes() const;
  /// The largest single buffer's bytes per pixel (a histogram, or the
  /// footprint buffer's regions of doubles together): one pixel of it must
  /// fit `maxBufferBytes` (a histogram's is validated before, by the driver).
  std::size_t largestBufferBytes() const;
};

/// Segments as large as the budget, the device's buffer limit and pass limit
/// allow. Throws InputError when the budget cannot hold one pixel, or one
/// pixel's footprint buffer (every response class's region) exceeds the
/// buffer limit.
SegmentPlan planSegments(std::size_t pixelCount, const PixelBuffers& pixel, std::size_t budgetBytes,
                         std::size_t maxBufferBytes, std::size_t maxPixelsPerPass);

}  // namespace tofsim::capture
