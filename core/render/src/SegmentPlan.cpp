#include "SegmentPlan.h"

#include <algorithm>
#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::render {

SegmentPlan planSegments(std::size_t pixelCount, std::size_t floatsPerPixel, int buffersPerPixel,
                         std::size_t budgetBytes, std::size_t maxStorageBlockBytes,
                         std::size_t maxPixelsPerDispatch) {
  const std::size_t pixelVolumeBytes = floatsPerPixel * sizeof(float);
  const std::size_t pixelBytes = pixelVolumeBytes * buffersPerPixel + sizeof(float);
  if (pixelVolumeBytes > maxStorageBlockBytes) {
    throw InputError("one pixel's histogram (" + std::to_string(pixelVolumeBytes) +
                     " bytes) exceeds the GL implementation's largest storage block (" +
                     std::to_string(maxStorageBlockBytes) + " bytes); lower time.bins");
  }
  if (pixelBytes > budgetBytes) {
    throw InputError("render.memory_budget (" + std::to_string(budgetBytes) +
                     " bytes left after the scene and maps) cannot hold one pixel's histogram (" +
                     std::to_string(pixelBytes) + " bytes); raise render.memory_budget or lower "
                     "time.bins");
  }
  SegmentPlan plan;
  plan.pixelsPerSegment = std::min({budgetBytes / pixelBytes, maxStorageBlockBytes / pixelVolumeBytes,
                                    maxPixelsPerDispatch, pixelCount});
  plan.segmentCount = (pixelCount + plan.pixelsPerSegment - 1) / plan.pixelsPerSegment;
  plan.bytesPerSegment = plan.pixelsPerSegment * pixelBytes;
  return plan;
}

}  // namespace tofsim::render
