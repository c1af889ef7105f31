#include "tofsim/scene/TextureSampling.h"

#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::scene {

namespace {
// GL_REPEAT: texel index modulo size, also for negative indices.
int wrap(int i, int size) {
  const int m = i % size;
  return m < 0 ? m + size : m;
}
}  // namespace

glm::vec3 sampleBilinear(const Texture& texture, const glm::vec2& uv) {
  TOFSIM_CHECK(texture.width > 0 && texture.height > 0);
  TOFSIM_CHECK(texture.rgb.size() == static_cast<std::size_t>(texture.width) * texture.height * 3);
  // Continuous texel coordinates whose integer points are texel centres.
  const float s = uv.x * static_cast<float>(texture.width) - 0.5f;
  const float t = uv.y * static_cast<float>(texture.height) - 0.5f;
  const float s0 = std::floor(s), t0 = std::floor(t);
  const float fs = s - s0, ft = t - t0;
  const auto texel = [&](int i, int j) {
    const std::size_t k = (static_cast<std::size_t>(wrap(j, texture.height)) * texture.width +
                           static_cast<std::size_t>(wrap(i, texture.width))) *
                          3;
    return glm::vec3(texture.rgb[k], texture.rgb[k + 1], texture.rgb[k + 2]);
  };
  const int i0 = static_cast<int>(s0), j0 = static_cast<int>(t0);
  const glm::vec3 top = glm::mix(texel(i0, j0), texel(i0 + 1, j0), fs);
  const glm::vec3 bottom = glm::mix(texel(i0, j0 + 1), texel(i0 + 1, j0 + 1), fs);
  return glm::mix(top, bottom, ft);
}

glm::vec3 baseColorTexel(const Scene& scene, int32_t material, const glm::vec2& uv) {
  const Material& m = scene.materials.at(static_cast<std::size_t>(material));
  if (m.albedoTexture < 0) return glm::vec3(1.0f);
  return sampleBilinear(scene.textures.at(static_cast<std::size_t>(m.albedoTexture)), uv);
}

glm::vec2 metallicRoughnessTexel(const Scene& scene, int32_t material, const glm::vec2& uv) {
  const Material& m = scene.materials.at(static_cast<std::size_t>(material));
  if (m.metallicRoughnessTexture < 0) return glm::vec2(1.0f);
  const glm::vec3 t =
      sampleBilinear(scene.textures.at(static_cast<std::size_t>(m.metallicRoughnessTexture)), uv);
  return glm::vec2(t.b, t.g);
}

}  // namespace tofsim::scene
