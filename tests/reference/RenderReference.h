#pragma once
// Renders a job with the reference path tracer into memory.

#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/reference/ReferenceRenderer.h"

namespace tofsim::test {

inline capture::VolumeCollector renderReference(const capture::RenderJob& job,
                                                const reference::ReferenceSettings& settings,
                                                capture::RenderResult* result = nullptr) {
  capture::VolumeCollector collector(job.camera.width, job.camera.height, job.settings.time, 3);
  const capture::RenderResult r = reference::ReferenceRenderer(settings).render(job, collector);
  if (result != nullptr) *result = r;
  return collector;
}

}  // namespace tofsim::test
