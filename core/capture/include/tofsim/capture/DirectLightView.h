#pragma once
// Light that travels straight from the source into the camera. A point source
// is a delta in angle, so its radiance is spread over the pixel it projects
// into: L = I / (d^2 * pixel solid angle), arriving after eta * d / c.

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "tofsim/capture/RenderJob.h"

namespace tofsim::capture {

struct DirectLightView {
  bool visible = false;
  std::size_t pixel = 0;  ///< y * width + x
  int32_t bin = kBeforeAxis;  ///< TimeAxis::binOf of its arrival (negative: off the axis)
  glm::vec3 radiance{0.0f};

  /// Adds the term to a segment's direct buffer when the pixel is in it;
  /// returns the radiance (summed over channels) that fell off the axis.
  AxisLoss addTo(std::size_t firstPixel, std::size_t pixelCount, const TimeAxis& axis, int channels,
               float* direct) const;
};

/// `positions`: the G-buffer's RGBA world positions, row 0 at the top.
DirectLightView directLightView(const RenderJob& job, const std::vector<float>& positions);

/// The first surface point seen through pixel (x, y), if any.
using FirstSurface = std::function<std::optional<glm::vec3>(int32_t x, int32_t y)>;
/// Same, for renderers without a G-buffer: asks for the light's pixel only.
DirectLightView directLightView(const RenderJob& job, const FirstSurface& firstSurface);

}  // namespace tofsim::capture
