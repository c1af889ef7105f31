#pragma once
// Splits the image's pixels into segments whose GPU buffers fit both the
// memory budget and the largest shader storage block the implementation
// allows. Segments depend only on these sizes, and every pixel is computed
// the same way whatever segment it is in, so the volume's bytes do not depend
// on the budget.

#include <cstddef>

namespace tofsim::render {

struct SegmentPlan {
  std::size_t pixelsPerSegment = 0;
  std::size_t segmentCount = 0;
  std::size_t bytesPerSegment = 0;  ///< GPU bytes of one segment's buffers
};

/// `floatsPerPixel`: T * C. `buffersPerPixel`: how many volumes (direct,
/// indirect) a segment holds. Throws InputError when not even one pixel fits.
SegmentPlan planSegments(std::size_t pixelCount, std::size_t floatsPerPixel, int buffersPerPixel,
                         std::size_t budgetBytes, std::size_t maxStorageBlockBytes,
                         std::size_t maxPixelsPerDispatch);

}  // namespace tofsim::render
