#pragma once
// Transient instant radiosity on OpenGL 4.5 (Pan, Arellano, Jarabo 2019):
// the camera's G-buffer, the light's shadow map and, for indirect light, VPLs
// from a reflective shadow map with imperfect-shadow-map visibility. Every
// contribution lands in the time bin of its full optical path.
//
// The volume is produced in segments sized by the memory budget and the GL
// implementation's limits and handed to a SegmentSink as soon as each is done.

#include <cstddef>
#include <functional>
#include <string>

#include "tofsim/render/Camera.h"
#include "tofsim/render/Light.h"
#include "tofsim/render/RenderSettings.h"
#include "tofsim/render/SegmentSink.h"
#include "tofsim/scene/Scene.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::gl {
class Context;
}

namespace tofsim::render {

struct RenderJob {
  const scene::Scene* scene = nullptr;
  Camera camera;
  Light light;
  RenderSettings settings;
};

/// Per-pixel facts of the first surface each pixel sees (ground truth for
/// sensor studies), and what the render did.
struct RenderResult {
  Image depth_m;  ///< camera-to-surface distance, 1 channel; 0 where no surface
  std::size_t segments = 0;
  std::size_t vpls = 0;
  std::size_t vplBatches = 0;
  std::size_t peakGpuBytes = 0;
  double seconds = 0.0;
  /// Radiance that arrived outside the time axis (summed over channels); it is
  /// in neither the volume nor the steady image.
  double energyOutsideAxis = 0.0;
};

/// Called after each unit of work: (done, total, what).
using ProgressCallback = std::function<void(std::size_t, std::size_t, const std::string&)>;

class TransientRenderer {
 public:
  explicit TransientRenderer(gl::Context& context);
  RenderResult render(const RenderJob& job, SegmentSink& sink,
                      const ProgressCallback& progress = {}) const;

 private:
  gl::Context& context_;
};

/// A sink that keeps the whole volume in memory (tests, small renders).
class VolumeCollector : public SegmentSink {
 public:
  VolumeCollector(int32_t width, int32_t height, const TimeAxis& axis, int32_t channels);
  void consume(const Segment& segment) override;
  TransientVolume direct;
  TransientVolume indirect;
  /// direct + indirect, computed in float: total == direct + indirect exactly.
  TransientVolume total() const;
};

}  // namespace tofsim::render
