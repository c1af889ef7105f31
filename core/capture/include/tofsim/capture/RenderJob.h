#pragma once
// What a renderer is asked to do and what it reports back, independent of how
// it renders (GL transient instant radiosity or the CPU reference).

#include <cstddef>
#include <functional>
#include <string>

#include "tofsim/capture/Camera.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/capture/Light.h"
#include "tofsim/capture/RenderSettings.h"
#include "tofsim/scene/Scene.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::capture {

struct RenderJob {
  const scene::Scene* scene = nullptr;
  Imager imager;  ///< what the pixels see; a pinhole camera by default
  Light light;
  RenderSettings settings;

  /// The imager's pinhole camera, for code that only knows cameras (the GL
  /// rasterizer, the reference's pixel filter, the pipeline's camera
  /// metadata); std::bad_variant_access for any other imager.
  Camera& camera() { return std::get<Camera>(imager); }
  const Camera& camera() const { return std::get<Camera>(imager); }
};

/// Wall seconds of instant radiosity's passes: where a render's time goes
/// (all 0 for the reference). The GL backend's passes run asynchronously, so
/// there their time shows where the driver waits, mostly in readBack.
struct PassSeconds {
  double surfaces = 0.0;    ///< scene, camera G-buffer, shadow map; the adaptive samples' mask
  double vpls = 0.0;        ///< RSM VPLs, later bounces, making them resident
  double visibility = 0.0;  ///< the VPL batches' ISMs
  double direct = 0.0;      ///< direct gathers
  double indirect = 0.0;    ///< indirect gathers
  double readBack = 0.0;    ///< segments and bounces read out, bounces summed
  /// The rest of RenderResult::seconds: the plan, allocation, and the sinks
  /// (files, sensors) that consume the segments.
  double other = 0.0;
};

/// Ground truth of the first surface each pixel sees, and what the render did.
struct RenderResult {
  Image depth_m;  ///< camera-to-surface distance, 1 channel; 0 where no surface
  std::size_t segments = 0;
  std::size_t vpls = 0;
  std::size_t vplBatches = 0;
  /// Pixels that took N x N sub-pixel samples (render.adaptive_pixel_samples;
  /// 0 otherwise).
  std::size_t sampledPixels = 0;
  std::size_t peakGpuBytes = 0;
  double seconds = 0.0;
  PassSeconds passSeconds;
  /// Radiance that arrived before the first or after the last bin (summed over
  /// channels); it is in neither the volume nor the steady image.
  AxisLoss offAxis;
  /// Radiance summed over pixels, bins and channels that landed on the axis,
  /// before the camera's vignetting as offAxis is; filled by the output
  /// stage, so offAxis can be given as a fraction.
  double onAxisEnergy = 0.0;
  /// Volume values that were NaN or infinite (degenerate geometry, overflow)
  /// and were written as 0 instead; counted by the output stage.
  std::size_t nonFiniteRejected = 0;
};

/// Called after each unit of work: (done, total, what).
using ProgressCallback = std::function<void(std::size_t, std::size_t, const std::string&)>;

}  // namespace tofsim::capture
