#pragma once
// The relay wall of a non-line-of-sight capture: a planar glTF node whose
// points the laser lights and the sensor looks at, in y-tal's wall frame
// (x to the right seen from the front, y up, the normal out of the front face).

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tofsim::scene {
struct Scene;
}

namespace tofsim::capture {

struct RelayWall {
  std::string name;
  glm::vec3 centre_world{0.0f};                ///< the centre of the rectangle the wall spans
  glm::vec3 x_axis{1, 0, 0}, y_axis{0, 1, 0};  ///< unit, in the plane; x cross y = normal
  glm::vec3 normal{0, 0, 1};  ///< unit, out of the front face (glTF's counter-clockwise winding)
  float width_m = 0.0f, height_m = 0.0f;  ///< extent along x_axis and y_axis
  /// The point at (u, v) in [0, 1]^2: 0 is the -x / -y edge.
  glm::vec3 at(float u, float v) const;
  /// Signed distance of p in front of the wall's plane.
  float heightAbove(const glm::vec3& p) const;
};

/// The wall made of every mesh the glTF node (or mesh) `name` placed. Its y
/// axis is the world's +y projected into the plane (the first edge where the
/// wall is horizontal). Throws InputError naming the wall when nothing has
/// that name, when its triangles are not in one plane (a solid: "not planar"),
/// when it has no area or when its triangles face both ways (no front face).
RelayWall relayWallOf(const scene::Scene& scene, const std::string& name);

/// tal's grid (`get_grid_xyz`): nx x ny points at the centres of the cells of
/// the wall's sub-rectangle [uv_start, uv_end] (in the units of RelayWall::at),
/// x index major: point (ix, iy) is element ix * ny + iy.
std::vector<glm::vec3> wallGrid(const RelayWall& wall, int nx, int ny,
                                glm::vec2 uv_start = glm::vec2(0.0f),
                                glm::vec2 uv_end = glm::vec2(1.0f));

}  // namespace tofsim::capture
