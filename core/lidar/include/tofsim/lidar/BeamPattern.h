#pragma once
// Where a lidar's beams point and how a beam's receiver samples its
// divergence cone. Each beam (ring x azimuth) is a laser spot from the
// lidar's position; its receiver integrates the same cone with `beam_rays`
// rays laid out deterministically in rings of equal power (the profile's
// radial CDF split into equal parts) and equal sectors: every ray carries
// the same share of the beam's power (1 / rays), and a beam over an edge
// splits its rays, and so its energy, between the two sides as its profile
// does.

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "tofsim/lidar/LidarSpec.h"

namespace tofsim::lidar {

/// The unit direction of beam (ring, azimuth) in the world; for a raster or
/// zone scan, cell (row, column)'s centre (ScanGrid.h).
glm::vec3 beamDirection(const LidarSpec& spec, int32_t ring, int32_t azimuth);

/// One receiver ray of a beam: its angular offset from the beam's axis
/// (radians, along the beam frame's u and v) and its share of the beam's
/// power (the shares sum to 1).
struct BeamRay {
  glm::vec2 offset_rad{0.0f};
  float share = 1.0f;
};

/// The layout of `count` rays over a beam of full divergence `divergence_rad`
/// with `profile`: count = 1 is the axis alone; otherwise rings =
/// max(1, round(sqrt(count) / 2)) of count / rings sectors each (alternate
/// rings turned by half a sector), each ray at its ring's median power radius.
std::vector<BeamRay> beamRays(int32_t count, double divergence_rad, BeamProfile profile);

/// The radius (rad) within which `fraction` of the beam's power lies: the
/// profile's inverse radial CDF.
double powerRadius_rad(double fraction, double divergence_rad, BeamProfile profile);

/// A beam's frame: its axis and two unit vectors normal to it (u horizontal,
/// along up x axis; v = axis x u), so the receiver rays are
/// normalize(axis + tan|o| (o.x u + o.y v) / |o|).
struct BeamFrame {
  glm::vec3 axis, u, v;
};
BeamFrame beamFrame(const glm::vec3& axis, const glm::vec3& up);
glm::vec3 rayDirection(const BeamFrame& frame, const glm::vec2& offset_rad);

/// A ray's offset as rayDirection uses it, worked out once for every beam
/// (a frame's beams share their rays' offsets): the offset's unit
/// direction and the tangent of its angle; the same directions to the bit.
struct RayTilt {
  glm::vec2 unit{0.0f};
  float tangent = 0.0f;
  bool onAxis = true;
};
RayTilt rayTilt(const glm::vec2& offset_rad);
glm::vec3 rayDirection(const BeamFrame& frame, const RayTilt& tilt);

}  // namespace tofsim::lidar
