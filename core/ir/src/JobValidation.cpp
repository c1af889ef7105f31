#include "JobValidation.h"

#include <string>

#include "tofsim/capture/Imager.h"
#include "tofsim/capture/RegionScattering.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/util/Error.h"

namespace tofsim::ir {

using namespace capture;  // the job description types

namespace {

// The sides of the G-buffer, the shadow map and the RSM.
void validateImageSides(const RenderJob& job, const DeviceLimits& limits) {
  const int32_t width = imageWidth(job.imager), height = imageHeight(job.imager);
  const std::string maxTexture = std::to_string(limits.maxImageSide);
  if (width < 1 || height < 1) {
    throw InputError("the image has " + std::to_string(width) + "x" + std::to_string(height) +
                     " pixels: it needs at least one");
  }
  if (width > limits.maxImageSide || height > limits.maxImageSide) {
    throw InputError("camera.resolution " + std::to_string(width) + "x" + std::to_string(height) +
                     " exceeds the GL implementation's texture limit " + maxTexture);
  }
  checkLayout(job.imager);
  if (job.settings.shadow_map_resolution > limits.maxImageSide) {
    throw InputError("render.shadow_map_resolution " +
                     std::to_string(job.settings.shadow_map_resolution) +
                     " exceeds the GL texture limit " + maxTexture);
  }
  const IndirectSettings& s = job.settings.indirect;
  if (s.enabled && s.rsm_resolution > limits.maxImageSide) {
    throw InputError("render.indirect.rsm_resolution " + std::to_string(s.rsm_resolution) +
                     " exceeds the GL texture limit " + maxTexture);
  }
}

}  // namespace

void validateJob(const RenderJob& job, const DeviceLimits& limits) {
  TOFSIM_CHECK(job.scene != nullptr);
  validateImageSides(job, limits);
  const IndirectSettings& s = job.settings.indirect;
  if (s.bounces < 1 || s.bounces > 8 || s.vpls_per_bounce < 0) {
    throw InputError("render.indirect.bounces must be in [1, 8] (got " + std::to_string(s.bounces) +
                     ") and vpls_per_bounce >= 0 (got " + std::to_string(s.vpls_per_bounce) + ")");
  }
  // A scattering region's light is binned along the camera ray by its path,
  // which grows with s only while the camera leg is timed.
  if (regionsScatter(job.settings) &&
      (job.settings.time.camera_unwarp || !lastLegCounts(job.imager))) {
    throw InputError(
        "a scattering region (media: sigma_s > 0) with the camera leg untimed "
        "(time.camera_unwarp) is not built in instant radiosity: set time.camera_unwarp: "
        "false, or render.renderer: reference");
  }
  // One ISM (without its pull-push pyramid) is one buffer.
  const std::size_t ismBytes = std::size_t(s.ism_resolution) * s.ism_resolution * sizeof(float);
  if (s.enabled && ismBytes > limits.maxBufferBytes) {
    throw InputError("render.indirect.ism_resolution " + std::to_string(s.ism_resolution) +
                     " needs " + std::to_string(ismBytes) +
                     " bytes per VPL, over the GL storage-block limit " +
                     std::to_string(limits.maxBufferBytes));
  }
  // The footprint's difference buffer holds doubles: twice a histogram.
  const std::size_t valueBytes = job.settings.pixel_footprint ? sizeof(double) : sizeof(float);
  const std::size_t pixelBytes = std::size_t(job.settings.time.bins) * kChannels * valueBytes;
  if (pixelBytes > limits.maxBufferBytes) {
    throw InputError("time.bins " + std::to_string(job.settings.time.bins) + " x " +
                     std::to_string(kChannels) + " channels x " + std::to_string(valueBytes) +
                     " bytes" +
                     (job.settings.pixel_footprint ? " (the pixel footprint's buffer)" : "") +
                     " exceeds the GL storage-block limit " +
                     std::to_string(limits.maxBufferBytes) + " bytes; use fewer time bins" +
                     (job.settings.pixel_footprint ? " or render.pixel_footprint: false" : ""));
  }
}

}  // namespace tofsim::ir
