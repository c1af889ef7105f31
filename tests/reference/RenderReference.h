#pragma once
// Renders a job with the reference path tracer into memory.

#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/reference/ReferenceRenderer.h"

namespace tofsim::test {

inline capture::VolumeCollector renderReference(const capture::RenderJob& job,
                                                const reference::ReferenceSettings& settings,
                                                capture::RenderResult* result = nullptr) {
  capture::VolumeCollector collector(job.camera().width, job.camera().height, job.settings.time, 3);
  const capture::RenderResult r = reference::ReferenceRenderer(settings).render(job, collector);
  if (result != nullptr) *result = r;
  return collector;
}

/// The reference with `interactions` surface interactions per path
/// (reference.bounces: 2 = IR's one indirect bounce), `samples` paths per
/// pixel through `filter` (Point: pixel centres, as IR's point pixels; Box:
/// the pixel's area, as IR's footprint), 2 threads.
inline capture::VolumeCollector renderReference(const capture::RenderJob& job, int32_t interactions,
                                                int32_t samples, reference::PixelFilter filter) {
  reference::ReferenceSettings settings;
  settings.pixel_filter = filter;
  settings.bounces = interactions;
  settings.samples_per_pixel = samples;
  settings.threads = 2;
  return renderReference(job, settings);
}

/// Sum of every value (bins and channels) of a volume, in double.
inline double energy(const TransientVolume& v) {
  double sum = 0.0;
  for (const float x : v.values()) sum += x;
  return sum;
}

}  // namespace tofsim::test
