#pragma once
// Closed-form quantities the renderer tests check against: where a camera
// ray meets a plane, which bin an optical path falls in, a pixel's peak bin.

#include <cmath>
#include <optional>

#include <glm/glm.hpp>

#include "tofsim/capture/Camera.h"
#include "tofsim/volume/PhysicalConstants.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::test {

/// Intersection of the camera ray through pixel (x, y) with the plane z = z0.
inline glm::dvec3 hitOnPlane(const capture::Camera& camera, int x, int y, double z0 = 0.0) {
  const glm::dvec3 o(camera.position_world);
  const glm::dvec3 d(camera.pixelDirection(x, y));
  return o + d * ((z0 - o.z) / d.z);
}

/// The bin with the most energy in channel c, or -1 when the pixel is dark.
inline int peakBin(const TransientVolume& v, int y, int x, int c = 0) {
  int best = -1;
  float bestValue = 0.0f;
  for (int t = 0; t < v.bins(); ++t) {
    if (v.at(y, x, t, c) > bestValue) {
      bestValue = v.at(y, x, t, c);
      best = t;
    }
  }
  return best;
}

/// The bin of an optical path, or nullopt within 2% of a bin edge, where
/// float rounding of the hit point may pick either side.
inline std::optional<int> unambiguousBin(const TimeAxis& axis, double path_m) {
  const double f = (path_m / kSpeedOfLight_m_per_s - axis.start_s) / axis.bin_width_s;
  const double frac = f - std::floor(f);
  if (frac < 0.02 || frac > 0.98) return std::nullopt;
  return static_cast<int>(std::floor(f));
}

/// sum |a - b| / sum |b| over all values.
inline double relativeL1(const Image& a, const Image& b) {
  double diff = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < a.data.size(); ++i) {
    diff += std::abs(a.data[i] - b.data[i]);
    norm += std::abs(b.data[i]);
  }
  return diff / norm;
}

}  // namespace tofsim::test
