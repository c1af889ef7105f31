#pragma once
// Where a raster's beams and a multizone sensor's zones look (LidarSpec's
// ScanGrid): cell (row, column) of a pinhole's image plane at unit distance
// in front of the device, u = tan(fov_h / 2) (2 (column + 1/2) / columns - 1)
// to the right, v = tan(fov_v / 2) (2 (row + 1/2) / rows - 1) up, so that a
// camera of columns x rows pixels over the same field of view has exactly
// the zones as its pixels (its row y = rows - 1 - row).
//
// A zone (scan: zones) is lit by a flood emitter at the device whose power
// fills the field of view uniformly in solid angle (intensity power /
// Omega_fov), and its receiver integrates the zone's solid angle with
// zone_rays^2 rays through the centres of its sub-cells (a camera's
// pixel_samples places its samples there), each weighted by its sub-cell's
// solid angle dA cos^3(theta) (Camera::pixelSolidAngle_sr's form). A ray's
// share of the power is its solid angle over the field's (the shares of all
// zones sum to 1), so a zone is a beam (DirectWaveforms.h) whose receiver
// rays tile the zone: its waveform is the radiance the flood returns,
// integrated over the zone's solid angle (W m^-2 per pulse).

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "tofsim/lidar/BeamPattern.h"
#include "tofsim/lidar/LidarSpec.h"

namespace tofsim::lidar {

/// The device's frame for a grid scan: forward (the look direction), right
/// and up (orthogonalised).
struct GridFrame {
  glm::dvec3 forward, right, up;
};
GridFrame gridFrame(const LidarSpec& spec);

/// The image-plane point (u right, v up, at unit distance) of grid position
/// (row, column) in cells, continuous: cell (r, c) spans [r, r + 1) x
/// [c, c + 1), its centre at (r + 1/2, c + 1/2).
glm::dvec2 gridPlanePoint(const LidarSpec& spec, double row, double column);

/// The unit world direction through image-plane point p.
glm::vec3 gridDirection(const GridFrame& frame, const glm::dvec2& p);

/// The direction of cell (row, column)'s centre: a raster beam's axis, a zone's centre.
glm::vec3 gridCellDirection(const LidarSpec& spec, int32_t row, int32_t column);

/// The horizontal angle (degrees, positive to the right of forward) of
/// column `column`'s centre: the point clouds' azimuth for a grid scan.
double gridAzimuth_deg(const LidarSpec& spec, int32_t column);

/// The solid angle (sr) of the sub-cell of a zone_rays x zone_rays split
/// centred at image-plane point p: its area times cos^3 of its angle.
double subCellSolidAngle_sr(const LidarSpec& spec, const glm::dvec2& p);

/// The whole field of view's solid angle, the sum of every zone's sub-cells'.
double fieldSolidAngle_sr(const LidarSpec& spec);

/// Zone (row, column)'s receiver rays, as offsets in beamFrame(its centre
/// direction, up) with shares = their solid angle / fieldSolidAngle_sr, in
/// sub-cell order (sub-row j from the bottom, sub-column i: entry j N + i).
std::vector<BeamRay> zoneRays(const LidarSpec& spec, int32_t row, int32_t column, double field_sr);

}  // namespace tofsim::lidar
