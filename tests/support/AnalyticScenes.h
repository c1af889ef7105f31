#pragma once
// Small scenes with closed-form answers, built in code.

#include <glm/glm.hpp>

#include "tofsim/scene/Scene.h"

namespace tofsim::test {

/// Adds a square of side `size_m` centred at `center`, facing `normal`.
void addQuad(scene::Scene& scene, const glm::vec3& center, const glm::vec3& normal, float size_m,
             const glm::vec3& albedo);

/// One diffuse square facing +z at z = 0, `size_m` wide.
scene::Scene makePlane(float size_m, const glm::vec3& albedo = glm::vec3(0.5f));

}  // namespace tofsim::test
