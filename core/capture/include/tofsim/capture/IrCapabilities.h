#pragma once
// What each instant-radiosity backend gathers beyond the work every backend
// does, stated once: the backends report it (ir::IrBackend::capabilities),
// the driver and the config refuse a render its backend cannot gather, and
// render.backend: auto picks a backend that can (apps/pipeline).

#include "tofsim/capture/Camera.h"
#include "tofsim/capture/RenderSettings.h"

namespace tofsim::capture {

struct IrCapabilities {
  /// A defocused camera's aperture samples (Camera::defocused, ThinLens.h).
  bool defocus = false;
  /// render.indirect.merge_pixel_samples with pixel_samples > 1.
  bool merged_pixel_samples = false;
  /// render.indirect.gather_pairs > 0: the surface gather's pair roulette.
  bool sampled_gather = false;
};

/// The GL backend (core/render): what every backend gathers, nothing more.
inline constexpr IrCapabilities kGlCapabilities{};
/// The CPU backend (core/cpu).
inline constexpr IrCapabilities kCpuCapabilities{.defocus = true, .merged_pixel_samples = true,
                                                   .sampled_gather = true};

/// What a render needs: `camera` null for an imager that is not a camera.
inline IrCapabilities irNeeds(const Camera* camera, const RenderSettings& settings) {
  return {
      .defocus = camera != nullptr && camera->defocused(),
      .merged_pixel_samples = settings.indirect.merge_pixel_samples && settings.pixel_samples > 1,
      .sampled_gather = settings.indirect.enabled && settings.indirect.gather_pairs > 0};
}

/// Whether a backend with `have` gathers everything `need` asks for.
constexpr bool covers(const IrCapabilities& have, const IrCapabilities& need) {
  return (have.defocus || !need.defocus) &&
         (have.merged_pixel_samples || !need.merged_pixel_samples) &&
         (have.sampled_gather || !need.sampled_gather);
}

}  // namespace tofsim::capture
