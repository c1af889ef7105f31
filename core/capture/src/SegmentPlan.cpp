#include "tofsim/capture/SegmentPlan.h"

#include <algorithm>
#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::capture {

PixelRange SegmentPlan::segment(std::size_t s) const {
  TOFSIM_CHECK_LT(s, segmentCount);
  const std::size_t first = s * pixelsPerSegment;
  return {first, std::min(pixelsPerSegment, pixelCount - first)};
}

SegmentPlan fixedSegments(std::size_t pixelCount, std::size_t pixelsPerSegment,
                          std::size_t bytesPerPixel) {
  TOFSIM_CHECK_GT(pixelsPerSegment, 0u);
  SegmentPlan plan;
  plan.pixelCount = pixelCount;
  plan.pixelsPerSegment = pixelsPerSegment;
  plan.segmentCount = (pixelCount + pixelsPerSegment - 1) / pixelsPerSegment;
  plan.bytesPerSegment = pixelsPerSegment * bytesPerPixel;
  return plan;
}

std::size_t PixelBuffers::bytes() const {
  // Plus the light off the axis: one float before it, one after (AxisLoss).
  return floatsPerPixel * (sizeof(float) * volumes + sizeof(double) * footprintBuffers) +
         otherBytes + 2 * sizeof(float);
}

std::size_t PixelBuffers::largestBufferBytes() const {
  return floatsPerPixel * std::max(sizeof(float), sizeof(double) * footprintBuffers);
}

SegmentPlan planSegments(std::size_t pixelCount, const PixelBuffers& pixel,
                         std::size_t budgetBytes, std::size_t maxBufferBytes,
                         std::size_t maxPixelsPerPass) {
  const std::size_t pixelBytes = pixel.bytes();
  const std::size_t largest = pixel.largestBufferBytes();
  // validateJob rejects time.bins whose histogram (or footprint buffer)
  // exceeds the buffer limit, naming the key; the response classes' regions
  // are known only here.
  TOFSIM_CHECK_GT(largest, 0u);
  if (largest > maxBufferBytes) {
    throw InputError("one pixel's " + std::to_string(pixel.footprintBuffers) +
                     " difference buffers (the footprint's and the delayed materials' response "
                     "classes, " + std::to_string(largest) +
                     " bytes) exceed the device's largest buffer (" +
                     std::to_string(maxBufferBytes) +
                     " bytes); lower time.bins, render.indirect.bounces or the delayed materials");
  }
  TOFSIM_CHECK_GT(pixelCount, 0u);
  TOFSIM_CHECK_GT(maxPixelsPerPass, 0u);
  if (pixelBytes > budgetBytes) {
    throw InputError("render.memory_budget (" + std::to_string(budgetBytes) +
                     " bytes left after the scene and maps) cannot hold one pixel's histogram (" +
                     std::to_string(pixelBytes) +
                     " bytes); raise render.memory_budget or lower "
                     "time.bins");
  }
  const std::size_t pixels = std::min(
      {budgetBytes / pixelBytes, maxBufferBytes / largest, maxPixelsPerPass, pixelCount});
  return fixedSegments(pixelCount, pixels, pixelBytes);
}

}  // namespace tofsim::capture
