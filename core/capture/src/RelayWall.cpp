#include "tofsim/capture/RelayWall.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tofsim/scene/Scene.h"
#include "tofsim/util/Error.h"

namespace tofsim::capture {

glm::vec3 RelayWall::at(float u, float v) const {
  return centre_world + (u - 0.5f) * width_m * x_axis + (v - 0.5f) * height_m * y_axis;
}

float RelayWall::heightAbove(const glm::vec3& p) const {
  return glm::dot(p - centre_world, normal);
}

RelayWall relayWallOf(const scene::Scene& scene, const std::string& name) {
  std::vector<const scene::Mesh*> meshes;
  for (const scene::Mesh& m : scene.meshes) {
    if (m.node == name || m.name == name) meshes.push_back(&m);
  }
  if (meshes.empty()) {
    if (std::find(scene.arealess.begin(), scene.arealess.end(), name) != scene.arealess.end()) {
      throw InputError("relay wall '" + name +
                       "' has no area (every triangle of it is degenerate: the scene dropped it)");
    }
    throw InputError("no node or mesh named '" + name + "' in the scene for the relay wall");
  }
  // The plane: the area-weighted normal of every triangle. Triangles facing
  // opposite ways cancel in it (a closed box sums to 0): then the largest
  // triangle's normal stands in, so that the plane test below says "not
  // planar" for a solid, and a flat wall wound both ways has no front face.
  glm::dvec3 areaNormal(0.0), largest(0.0);
  glm::dvec3 anyPoint(0.0);
  double totalTwiceArea = 0.0;
  for (const scene::Mesh* m : meshes) {
    for (std::size_t t = 0; t + 2 < m->indices.size(); t += 3) {
      const glm::dvec3 a = m->positions_world[m->indices[t]];
      const glm::dvec3 b = m->positions_world[m->indices[t + 1]];
      const glm::dvec3 c = m->positions_world[m->indices[t + 2]];
      const glm::dvec3 n = glm::cross(b - a, c - a);
      areaNormal += n;
      totalTwiceArea += glm::length(n);
      if (glm::length(n) > glm::length(largest)) largest = n;
      anyPoint = a;
    }
  }
  if (!(totalTwiceArea > 0.0)) throw InputError("relay wall '" + name + "' has no area");
  const bool cancelled = !(glm::length(areaNormal) > 1e-6 * totalTwiceArea);
  if (cancelled) areaNormal = largest;
  const double twiceArea = glm::length(areaNormal);
  RelayWall wall;
  wall.name = name;
  wall.normal = glm::vec3(areaNormal / twiceArea);
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  glm::vec3 y = up - glm::dot(up, wall.normal) * wall.normal;
  if (glm::length(y) < 1e-3f) {  // a horizontal wall: its first edge is x
    const scene::Mesh& m = *meshes.front();
    const glm::vec3 edge = m.positions_world[m.indices[1]] - m.positions_world[m.indices[0]];
    y = glm::cross(wall.normal, edge);
  }
  wall.y_axis = glm::normalize(y);
  wall.x_axis = glm::cross(wall.y_axis, wall.normal);
  double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  double hi[2] = {-lo[0], -lo[1]};
  double offPlane = 0.0, extent = 0.0;
  const glm::dvec3 x(wall.x_axis), yAxis(wall.y_axis), n(wall.normal);
  for (const scene::Mesh* m : meshes) {
    for (const glm::vec3& p : m->positions_world) {
      const glm::dvec3 d = glm::dvec3(p) - anyPoint;
      lo[0] = std::min(lo[0], glm::dot(d, x));
      hi[0] = std::max(hi[0], glm::dot(d, x));
      lo[1] = std::min(lo[1], glm::dot(d, yAxis));
      hi[1] = std::max(hi[1], glm::dot(d, yAxis));
      offPlane = std::max(offPlane, std::fabs(glm::dot(d, n)));
      extent = std::max(extent, glm::length(d));
    }
  }
  if (offPlane > 1e-4 * std::max(extent, 1e-6)) {
    throw InputError("relay wall '" + name + "' is not planar (a vertex lies " +
                     std::to_string(offPlane) + " m off its plane)");
  }
  if (cancelled) {
    throw InputError("relay wall '" + name +
                     "' has no front face: its triangles are wound both ways (glTF's "
                     "counter-clockwise winding says which side faces the scene)");
  }
  wall.width_m = static_cast<float>(hi[0] - lo[0]);
  wall.height_m = static_cast<float>(hi[1] - lo[1]);
  if (!(wall.width_m > 0.0f && wall.height_m > 0.0f)) {
    throw InputError("relay wall '" + name + "' has no area");
  }
  wall.centre_world =
      glm::vec3(anyPoint + 0.5 * (lo[0] + hi[0]) * x + 0.5 * (lo[1] + hi[1]) * yAxis);
  return wall;
}

std::vector<glm::vec3> wallGrid(const RelayWall& wall, int nx, int ny, glm::vec2 uv_start,
                                glm::vec2 uv_end) {
  std::vector<glm::vec3> points;
  if (nx < 1 || ny < 1) return points;
  points.reserve(static_cast<std::size_t>(nx) * ny);
  const glm::vec2 size = uv_end - uv_start;
  for (int ix = 0; ix < nx; ++ix) {
    for (int iy = 0; iy < ny; ++iy) {
      const float u =
          uv_start.x + (static_cast<float>(ix) + 0.5f) * size.x / static_cast<float>(nx);
      const float v =
          uv_start.y + (static_cast<float>(iy) + 0.5f) * size.y / static_cast<float>(ny);
      points.push_back(wall.at(u, v));
    }
  }
  return points;
}

}  // namespace tofsim::capture
