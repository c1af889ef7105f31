#pragma once
// How far from the origin a scene may reach: checked where a glTF is loaded
// (static positions and cameras, every keyframe of an animation), so that the
// renderers never see coordinates they cannot trace.

#include <glm/glm.hpp>
#include <string>

namespace tofsim::scene {

/// The farthest (m, along any axis) a vertex or camera may lie from the
/// origin, at rest and at every keyframe of an animation; a file beyond it is
/// an InputError at load. Positions are stored as float: at 1e6 m one float
/// step is 6 cm, already coarser than a ToF bin's light path, and far below
/// where the tracers' products leave float's range (Embree asserts on ray
/// origins past 1.8e18; squared lengths overflow past 1.8e19).
inline constexpr double kMaxSceneCoordinate_m = 1e6;

/// Every coordinate of p within kMaxSceneCoordinate_m (false for NaN).
inline bool withinSceneBound(const glm::dvec3& p) {
  const auto in = [](double v) { return v >= -kMaxSceneCoordinate_m && v <= kMaxSceneCoordinate_m; };
  return in(p.x) && in(p.y) && in(p.z);
}

/// "1e+30 m from the origin (at most 1e+06 m)": p's farthest coordinate, for
/// the errors of withinSceneBound.
std::string sceneBoundText(const glm::dvec3& p);

}  // namespace tofsim::scene
