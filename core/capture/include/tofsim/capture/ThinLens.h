#pragma once
// Defocus by a thin lens (Camera::aperture_m, focus_distance_m): every ray of
// a pixel sample starts on the aperture disk and passes through the point
// where the sample's pinhole ray meets the plane in focus (the plane at
// focus_distance_m along the optical axis). A surface on that plane is
// sharp; one at depth z is spread over the circle of confusion
// A |z - z_f| / (z z_f) at unit distance, c / pixel_pitch pixels on the
// sensor (detector-models.md section 3: c = A f |z - z_f| / (z (z_f - f))).
// The blur depends on the surface's depth, not on the light's arrival time,
// so it is made where the rays are (ray generation), never on the transient.
// The camera leg of a sample's light is timed to its aperture point, plus
// the lens's own path from there to the pixel less the chief ray's: by
// Fermat's principle every path from a point in focus through the lens to
// its image is equally long, so an in-focus surface's light arrives as
// through the pinhole (without the lens's part, the aperture points' legs
// would spread it by up to A/2 sin(angle off the axis)).

#include <cstdint>
#include <glm/glm.hpp>

#include "tofsim/capture/Imager.h"

namespace tofsim::capture {

/// Point `index` of the `count`-point aperture pattern on the unit disk (+x
/// right, +y up): Vogel's sunflower spiral, radius sqrt((index + 1/2) /
/// count) and the golden angle between neighbours. Every point stands for an
/// equal area (stratified in radius, low discrepancy in angle) and it depends
/// only on (index, count), so the bytes do not depend on threads or budgets.
glm::vec2 aperturePoint(int32_t index, int32_t count);

/// Aperture samples per pixel sample of the imager: the camera's
/// aperture_samples when it has an aperture, else 1 (the pinhole's ray).
int32_t apertureSamplesOf(const Imager& imager);

/// One aperture point's ray of a pixel sample.
struct ApertureRay {
  PrimaryRay ray;  ///< from the aperture point towards the sample's point in focus F
  /// The lens's optical path from the aperture point a to the pixel, less
  /// the chief ray's from the centre c, in the scene's metres (times the
  /// index of refraction with it): |F - c| - |F - a|, which makes the path
  /// to an in-focus point the same through every point of the aperture.
  float lensPath_m = 0.0f;
};

/// A defocused camera's rays: each pinhole (chief) ray of the camera turned
/// into the ray from an aperture point through its point in focus.
class ThinLens {
 public:
  explicit ThinLens(const Camera& camera);
  /// The ray from aperture point `disk` (on the unit disk, aperturePoint)
  /// through the point where `chief`, a ray from the camera's position,
  /// meets the plane in focus.
  ApertureRay through(const PrimaryRay& chief, glm::vec2 disk) const;

 private:
  glm::vec3 centre_, forward_, right_, up_;
  float radius_m_ = 0.0f;
  float focus_m_ = 1.0f;
};

/// The circle of confusion's diameter, in pixels at the image centre, of a
/// fronto-parallel surface at depth_m (along the optical axis): A |z - z_f| /
/// (z z_f) over the angle one pixel spans there.
double circleOfConfusion_px(const Camera& camera, double depth_m);

}  // namespace tofsim::capture
