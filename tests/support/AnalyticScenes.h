#pragma once
// Small scenes with closed-form answers, built in code.

#include <string>

#include <glm/glm.hpp>

#include "tofsim/scene/Scene.h"

namespace tofsim::test {

/// Adds a square of side `size_m` centred at `center`, facing `normal`.
void addQuad(scene::Scene& scene, const glm::vec3& center, const glm::vec3& normal, float size_m,
             const glm::vec3& albedo);

/// Adds one closed mesh `name`, the box [lo, hi] (8 shared corners, 12
/// triangles wound outwards, or inwards; no material): a medium region's
/// interface once scene::takeRegionMesh takes it out of the scene's surfaces.
void addBox(scene::Scene& scene, const std::string& name, glm::vec3 lo, glm::vec3 hi,
            bool inwards = false);

/// One diffuse square facing +z at z = 0, `size_m` wide.
scene::Scene makePlane(float size_m, const glm::vec3& albedo = glm::vec3(0.5f));

/// A corner: floor y = 0 (x in [-1, 1], z in [0, 2]) facing +y and wall z = 0
/// (x in [-1, 1], y in [0, 2]) facing +z.
scene::Scene makeCorner(const glm::vec3& floorAlbedo, const glm::vec3& wallAlbedo);

/// A closed cube [-side/2, side/2]^3 of six inward-facing squares of one
/// albedo: no ray from inside leaves it.
scene::Scene makeClosedBox(float side_m, const glm::vec3& albedo);

}  // namespace tofsim::test
