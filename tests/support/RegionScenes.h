#pragma once
// What the per-region media tests share (issue 42's `media:`;
// MediumRegionsTest, ScatteringRegionsTest, RegionTank.h): the box mesh to
// take out of the surfaces as a region (support/AnalyticScenes.h's addBox),
// the reference's render of a job at point pixels (and
// reference/RenderReference.h's volume energy).

#include "reference/RenderReference.h"
#include "support/AnalyticScenes.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::test {

/// The reference's render of `job` (point pixels, 2 threads).
inline capture::VolumeCollector renderReference(const capture::RenderJob& job, int32_t bounces,
                                                int32_t samples) {
  return renderReference(job, bounces, samples, reference::PixelFilter::Point);
}

}  // namespace tofsim::test
