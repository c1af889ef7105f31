#include "MemoryPlan.h"

#include <algorithm>
#include <string>

#include "tofsim/capture/SegmentSink.h"
#include "tofsim/ir/MediumRayVpls.h"
#include "tofsim/ir/MediumVpl.h"
#include "tofsim/util/Error.h"

namespace tofsim::ir {

namespace {

// VPLs per batch: all of them for exact visibility (no maps), else as many
// maps as fit the bytes set aside for them and one buffer.
std::size_t vplsPerBatch(std::size_t vplCount, std::size_t bytesPerVpl, std::size_t budgetBytes,
                         std::size_t maxBufferBytes) {
  if (bytesPerVpl == 0) return vplCount;
  const std::size_t limit = std::min(budgetBytes, maxBufferBytes);
  if (bytesPerVpl > limit) {
    throw InputError("one VPL's imperfect shadow map (" + std::to_string(bytesPerVpl) +
                     " bytes) does not fit the memory left for ISMs (" + std::to_string(limit) +
                     " bytes); raise render.memory_budget or lower render.indirect.ism_resolution");
  }
  return std::min(vplCount, limit / bytesPerVpl);
}

}  // namespace

MemoryPlan planMemory(const capture::RenderJob& job, const DeviceLimits& limits,
                      std::size_t fixedBytes, std::size_t vplCount,
                      std::size_t visibilityBytesPerVpl, std::size_t responseBuffers) {
  const std::size_t total = job.settings.memory_budget_bytes;
  if (fixedBytes >= total) {
    throw InputError("render.memory_budget (" + std::to_string(total) +
                     " bytes) does not exceed what the scene, G-buffer, shadow map and VPLs "
                     "need (" +
                     std::to_string(fixedBytes) +
                     " bytes) before any volume "
                     "segment; raise render.memory_budget");
  }
  MemoryPlan plan;
  std::size_t budget = total - fixedBytes;  // > 0, checked above
  if (vplCount > 0) {
    // Visibility batches get what all maps need, up to half of what is left;
    // the volume segments get the rest.
    const std::size_t allMaps = visibilityBytesPerVpl * vplCount;
    plan.vplsPerBatch = vplsPerBatch(vplCount, visibilityBytesPerVpl, std::min(allMaps, budget / 2),
                                     limits.maxBufferBytes);
    plan.batchCount = (vplCount + plan.vplsPerBatch - 1) / plan.vplsPerBatch;
    budget -= plan.vplsPerBatch * visibilityBytesPerVpl;
  }
  const std::size_t pixelCount =
      static_cast<std::size_t>(imageWidth(job.imager)) * imageHeight(job.imager);
  capture::PixelBuffers pixel;
  pixel.floatsPerPixel = static_cast<std::size_t>(job.settings.time.bins) * capture::kChannels;
  // With delayed response classes the footprint buffer exists also without
  // the pixel footprint (GL's region 0, which the classes' regions follow).
  pixel.footprintBuffers =
      static_cast<int>((job.settings.pixel_footprint || responseBuffers > 0 ? 1 : 0) +
                       responseBuffers);
  // The stage's running sums between chunks (GL: 16 doubles a pixel) and,
  // per class, the first bin written (CPU).
  if (responseBuffers > 0) {
    pixel.otherBytes = 16 * sizeof(double) + responseBuffers * sizeof(int32_t);
  }
  // A scattering medium's (or region's) VPL light along the camera rays: its
  // own histogram and off-axis sums per pixel (the backends' medium VPL pass).
  if (vplCount > 0 && vplsLightCameraRays(job.settings)) {
    pixel.otherBytes += pixel.floatsPerPixel * sizeof(float) + 2 * sizeof(float);
  }
  plan.segments =
      capture::planSegments(pixelCount, pixel, budget, limits.maxBufferBytes, limits.maxPixelsPerPass);
  plan.peakBytes = total - budget + plan.segments.bytesPerSegment;
  return plan;
}

}  // namespace tofsim::ir
