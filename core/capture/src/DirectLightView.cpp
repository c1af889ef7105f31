#include "tofsim/capture/DirectLightView.h"

#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::capture {

DirectLightView directLightView(const RenderJob& job, const std::vector<float>& positions) {
  const int32_t width = imageWidth(job.imager);
  return directLightView(job, [&](int32_t x, int32_t y) -> std::optional<glm::vec3> {
    const float* p = &positions[(static_cast<std::size_t>(y) * width + x) * 4];
    if (p[3] == 0.0f) return std::nullopt;
    return glm::vec3(p[0], p[1], p[2]);
  });
}

DirectLightView directLightView(const RenderJob& job, const FirstSurface& firstSurface) {
  DirectLightView view;
  // Only a camera images the light itself; a point set's points are surfaces.
  if (cameraOf(job.imager) == nullptr) return view;
  const Camera& camera = job.camera();
  const glm::vec3 toCamera = camera.position_world - job.light.position_world;
  const float d = glm::length(toCamera);
  if (d <= 1e-6f) return view;  // a light at the camera's pinhole is not seen
  const glm::ivec2 xy = camera.project(job.light.position_world);
  if (xy.x < 0) return view;
  const float profile = job.light.angularProfile(toCamera / d);
  if (profile <= 0.0f) return view;
  view.pixel = static_cast<std::size_t>(xy.y) * camera.width + xy.x;
  const std::optional<glm::vec3> surface = firstSurface(xy.x, xy.y);
  if (surface && glm::length(*surface - camera.position_world) < d) {
    return view;  // a surface in front of the light hides it
  }
  view.visible = true;
  const double solidAngle = camera.pixelSolidAngle_sr(xy.x, xy.y);
  view.radiance = job.light.intensity_W_per_sr *
                  static_cast<float>(profile / (static_cast<double>(d) * d * solidAngle));
  // A medium filling the scene attenuates the light -> camera leg.
  const Medium& medium = job.settings.medium;
  if (medium.present()) view.radiance *= physics::mediumTransmittance(medium.sigmaT(), d);
  // Per-region media: the same leg through their regions.
  double extra_m = 0.0;
  if (!job.settings.media.empty() && job.scene != nullptr) {
    const RegionPassage leg =
        MediumRegions(job.settings.media, *job.scene, job.settings.time.index_of_refraction)
            .passage(glm::dvec3(job.light.position_world), glm::dvec3(camera.position_world));
    view.radiance *= glm::vec3(leg.transmittance());
    extra_m = leg.extraPath_m;
  }
  // Unwarped time is the time at the scene point; the source itself emits at 0.
  const double path_m = job.settings.time.camera_unwarp
                            ? 0.0
                            : job.settings.time.index_of_refraction * (d + extra_m);
  view.bin = job.settings.time.binOf(path_m / kSpeedOfLight_m_per_s);
  return view;
}

AxisLoss DirectLightView::addTo(std::size_t firstPixel, std::size_t pixelCount,
                                const TimeAxis& axis, int channels, float* direct) const {
  AxisLoss lost;
  if (!visible || pixel < firstPixel || pixel >= firstPixel + pixelCount) return lost;
  if (bin < 0) {
    lost.add(bin, static_cast<double>(radiance.r) + radiance.g + radiance.b);
    return lost;
  }
  float* out = direct + ((pixel - firstPixel) * axis.bins + bin) * channels;
  for (int c = 0; c < channels; ++c) out[c] += radiance[c];
  return lost;
}

}  // namespace tofsim::capture
