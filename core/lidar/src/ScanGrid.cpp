#include "tofsim/lidar/ScanGrid.h"

#include <cmath>

namespace tofsim::lidar {

GridFrame gridFrame(const LidarSpec& spec) {
  const glm::dvec3 forward = glm::normalize(glm::dvec3(spec.forward_world));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(spec.up_world)));
  return {forward, right, glm::cross(right, forward)};
}

glm::dvec2 gridPlanePoint(const LidarSpec& spec, double row, double column) {
  const ScanGrid& g = spec.grid;
  const double tu = std::tan(glm::radians(0.5 * g.fov_horizontal_deg));
  const double tv = std::tan(glm::radians(0.5 * g.fov_vertical_deg));
  return {tu * (2.0 * column / g.columns - 1.0), tv * (2.0 * row / g.rows - 1.0)};
}

glm::vec3 gridDirection(const GridFrame& frame, const glm::dvec2& p) {
  return glm::vec3(glm::normalize(frame.forward + p.x * frame.right + p.y * frame.up));
}

glm::vec3 gridCellDirection(const LidarSpec& spec, int32_t row, int32_t column) {
  return gridDirection(gridFrame(spec), gridPlanePoint(spec, row + 0.5, column + 0.5));
}

double gridAzimuth_deg(const LidarSpec& spec, int32_t column) {
  return glm::degrees(std::atan(gridPlanePoint(spec, 0.5, column + 0.5).x));
}

double subCellSolidAngle_sr(const LidarSpec& spec, const glm::dvec2& p) {
  const ScanGrid& g = spec.grid;
  const double n = g.zone_rays;
  const double du = 2.0 * std::tan(glm::radians(0.5 * g.fov_horizontal_deg)) / (g.columns * n);
  const double dv = 2.0 * std::tan(glm::radians(0.5 * g.fov_vertical_deg)) / (g.rows * n);
  const double r2 = 1.0 + p.x * p.x + p.y * p.y;
  return du * dv / (r2 * std::sqrt(r2));
}

namespace {

// Sub-cell (i, j) of zone (row, column): its centre on the image plane.
glm::dvec2 subCellCentre(const LidarSpec& spec, int32_t row, int32_t column, int32_t i, int32_t j) {
  const double n = spec.grid.zone_rays;
  return gridPlanePoint(spec, row + (j + 0.5) / n, column + (i + 0.5) / n);
}

}  // namespace

double fieldSolidAngle_sr(const LidarSpec& spec) {
  const int32_t n = spec.grid.zone_rays;
  double sum = 0.0;
  for (int32_t row = 0; row < spec.grid.rows; ++row) {
    for (int32_t column = 0; column < spec.grid.columns; ++column) {
      for (int32_t j = 0; j < n; ++j) {
        for (int32_t i = 0; i < n; ++i) {
          sum += subCellSolidAngle_sr(spec, subCellCentre(spec, row, column, i, j));
        }
      }
    }
  }
  return sum;
}

std::vector<BeamRay> zoneRays(const LidarSpec& spec, int32_t row, int32_t column, double field_sr) {
  const GridFrame grid = gridFrame(spec);
  const BeamFrame beam = beamFrame(gridCellDirection(spec, row, column), spec.up_world);
  const glm::dvec3 axis(beam.axis), u(beam.u), v(beam.v);
  const int32_t n = spec.grid.zone_rays;
  std::vector<BeamRay> rays;
  rays.reserve(static_cast<std::size_t>(n * n));
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t i = 0; i < n; ++i) {
      const glm::dvec2 p = subCellCentre(spec, row, column, i, j);
      // The ray's offset in the beam's frame: rayDirection(beam, offset)
      // gives back its direction (angle atan(lateral / axial), towards it).
      const glm::dvec3 d = glm::normalize(grid.forward + p.x * grid.right + p.y * grid.up);
      const glm::dvec2 lateral(glm::dot(d, u), glm::dot(d, v));
      const double sideways = glm::length(lateral);
      const double angle = std::atan2(sideways, glm::dot(d, axis));
      const glm::dvec2 offset = sideways > 0.0 ? lateral * (angle / sideways) : glm::dvec2(0.0);
      rays.push_back(
          {glm::vec2(offset), static_cast<float>(subCellSolidAngle_sr(spec, p) / field_sr)});
    }
  }
  return rays;
}

}  // namespace tofsim::lidar
