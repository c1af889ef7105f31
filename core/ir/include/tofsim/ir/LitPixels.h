#pragma once
// Which pixel centres the light reaches, for render.adaptive_pixel_samples: a
// shadow's edge or a hard spot's rim inside a flat pixel is a step in its
// direct light that the G-buffer's geometry does not show, and one sample at
// the centre gives the pixel all of its light or none. The driver traces these
// rays itself (its RayScene) for every backend, so both sample the same pixels.

#include <cstdint>
#include <vector>

#include "tofsim/capture/Light.h"
#include "tofsim/capture/RenderJob.h"
#include "tofsim/ir/IrBackend.h"

namespace tofsim::rays {
class RayScene;
}  // namespace tofsim::rays

namespace tofsim::ir {

/// One entry per pixel of `centres`: 1 where its centre is a surface that
/// faces the light within its profile (physics::lightArrival, as the direct
/// gathers) and a ray from just off the surface reaches the light, else 0.
std::vector<uint8_t> litPixels(const CentreSurfaces& centres, const capture::Light& light,
                               const rays::RayScene& rays, int threads);

/// The pixels the driver gives N x N samples under render.adaptive_pixel_samples:
/// sampledPixels of the centres with their litPixels (render.indirect.trace_threads).
std::vector<uint8_t> adaptiveSampledPixels(const CentreSurfaces& centres,
                                           const capture::RenderJob& job,
                                           const rays::RayScene& rays);

}  // namespace tofsim::ir
