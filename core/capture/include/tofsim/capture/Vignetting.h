#pragma once
// A camera's vignetting: the irradiance a lens gives its image falls towards
// the rim, so each pixel records its radiance times a gain. `cos4` is a thin
// lens's natural fall-off, cos^4 of the angle between the pixel's ray (with a
// lens, its undistorted ray) and the optical axis; a map is a measured flat
// field, one gain per pixel. The renderers' volumes stay radiance; the gain
// is applied behind them, to every output and sensor alike
// (pipeline::VignettedSegments).

#include <cstdint>
#include <string>
#include <vector>

#include "tofsim/capture/Camera.h"

namespace tofsim::capture {

struct Vignetting {
  enum class Kind { None, Cos4, Map };
  Kind kind = Kind::None;
  /// Kind::Map: width x height gains >= 0, row-major (y = 0 at the top),
  /// and the file they came from.
  std::vector<float> map;
  int32_t width = 0, height = 0;
  std::string file;
};

/// Each pixel's gain (width x height, row-major); empty for Kind::None.
std::vector<float> vignettingGains(const Camera& camera, const Vignetting& vignetting);

}  // namespace tofsim::capture
