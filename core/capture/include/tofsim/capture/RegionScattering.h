#pragma once
// Whether a render's per-region media scatter (issue 42's `media:`, sigma_s
// > 0 in some region): what turns on instant radiosity's region passes (the
// single scattering along the camera rays, the medium VPLs in the regions,
// the VPLs' light in the rays' stretches inside them; CPU backend) and the
// refusals of what does not build them (the GL backend, an untimed camera
// leg).

#include "tofsim/capture/RenderSettings.h"

namespace tofsim::capture {

/// Whether some region's medium scatters (sigma_s > 0 in a channel).
inline bool regionsScatter(const RenderSettings& settings) {
  for (const RegionMedium& r : settings.media) {
    if (r.medium.scatters()) return true;
  }
  return false;
}

}  // namespace tofsim::capture
