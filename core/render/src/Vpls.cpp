#include "Vpls.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "GpuScene.h"
#include "SurfaceMaps.h"
#include "tofsim/ir/RsmTexels.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::render {

std::vector<Vpl> generateVpls(const GpuScene& scene, const capture::Light& light, int resolution,
                              double indexOfRefraction, const glm::vec3& lo, const glm::vec3& hi,
                              bool gltf) {
  std::vector<Vpl> vpls;
  const glm::vec2 range = depthRange(lo, hi, light.position_world);
  SurfaceMaps rsm(resolution, resolution, gltf);
  const std::size_t texels = static_cast<std::size_t>(resolution) * resolution;
  std::vector<float> position(texels * 4), normal(texels * 4), albedo(texels * 4);
  std::vector<float> metallicRoughness(gltf ? texels * 2 : 0);
  for (const ir::RsmView& v : ir::rsmViews(light)) {
    throwIfInterrupted();
    const glm::mat4 projection = glm::perspective(2.0f * v.halfAngle_rad, 1.0f, range.x, range.y);
    rsm.render(scene, projection * v.viewMatrix(light.position_world), light.position_world);
    rsm.position.download(GL_RGBA, GL_FLOAT, position.size() * sizeof(float), position.data());
    rsm.normal.download(GL_RGBA, GL_FLOAT, normal.size() * sizeof(float), normal.data());
    rsm.albedo.download(GL_RGBA, GL_FLOAT, albedo.size() * sizeof(float), albedo.data());
    if (gltf) {
      rsm.metallicRoughness.download(GL_RG, GL_FLOAT, metallicRoughness.size() * sizeof(float),
                                     metallicRoughness.data());
    }
    for (int y = 0; y < resolution; ++y) {
      for (int x = 0; x < resolution; ++x) {
        const float* at = &position[(static_cast<std::size_t>(y) * resolution + x) * 4];
        if (at[3] == 0.0f) continue;
        const std::size_t i = static_cast<std::size_t>(at - position.data());
        ir::RsmTexelSurface surface{glm::vec3(at[0], at[1], at[2]),
                                    glm::vec3(normal[i], normal[i + 1], normal[i + 2]),
                                    glm::vec3(albedo[i], albedo[i + 1], albedo[i + 2])};
        if (gltf) {
          surface.metallic = metallicRoughness[i / 2];
          surface.roughness = metallicRoughness[i / 2 + 1];
        }
        if (const auto vpl =
                ir::rsmTexelVpl(light, v, resolution, x, y, surface, indexOfRefraction, gltf)) {
          vpls.push_back(*vpl);
        }
      }
    }
  }
  return vpls;
}

}  // namespace tofsim::render
