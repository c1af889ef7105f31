#pragma once
// Bounds on when light can arrive, from the scene's bounding box alone: the
// shortest and longest optical path a render of `job` can bin. They let a run
// say before rendering that a time axis cannot hold the scene, and suggest an
// axis that holds everything a render lost. They are bounds, not estimates:
// every path the renderers trace lies within them, but they may be loose
// (the box is larger than the surfaces, and the spot cone and occlusion are
// ignored), so light near them need not exist.

#include <cstdint>

#include "tofsim/capture/RenderJob.h"

namespace tofsim::capture {

struct ArrivalBounds {
  bool any = false;         ///< false: no surface and no visible light, nothing can arrive
  double shortest_m = 0.0;  ///< optical path (index of refraction x length), metres
  double longest_m = 0.0;   ///< optical path, metres
  /// The materials' scattering delays past the longest path (issue 41; set
  /// by the caller that knows the loss it tolerates: apps/pipeline
  /// AxisReport), seconds; longest_s includes it.
  double delay_s = 0.0;

  double shortest_s() const;
  double longest_s() const;
};

/// Paths of light -> x1 -> ... -> xn -> camera with 1 <= n <= surfaceVertices
/// and every x in the scene's box (n = 1: direct light; 2: one bounce), plus
/// the light seen straight by the camera when it lies in the field of view.
/// With camera_unwarp the xn -> camera leg is left out, as the renderers do.
///   shortest: max(|l - c|, dist(l, box) + dist(box, c)), by the triangle
///     inequality (any path through the box is at least the straight line and
///     at least the way into and out of the box); dist(l, box) with unwarp.
///   longest: the path length is a convex function of (x1 .. xn), so its
///     maximum over box^n is at a vertex, a tuple of box corners: exact for the
///     box, found by dynamic programming over the corners.
ArrivalBounds arrivalBounds(const RenderJob& job, int32_t surfaceVertices);

}  // namespace tofsim::capture
