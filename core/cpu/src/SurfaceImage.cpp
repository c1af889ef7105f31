#include "SurfaceImage.h"

#include "ParallelFor.h"

namespace tofsim::cpu {

SurfaceImage traceSurfaces(const reference::RayScene& scene, const capture::Camera& camera,
                           int threads, int32_t samplesPerSide) {
  SurfaceImage image;
  image.width = camera.width;
  image.height = camera.height;
  const int32_t n = samplesPerSide;
  image.samplesPerSide = n;
  const std::size_t perPixel = static_cast<std::size_t>(n) * n;
  const std::size_t pixels = static_cast<std::size_t>(camera.width) * camera.height * perPixel;
  image.position.assign(pixels, glm::vec4(0.0f));
  image.normal.assign(pixels, glm::vec4(0.0f));
  image.albedo.assign(pixels, glm::vec4(0.0f));
  image.geometric.assign(pixels, glm::vec3(0.0f));
  image.metallicRoughness.assign(pixels, glm::vec2(0.0f));
  parallelFor(static_cast<std::size_t>(camera.height), threads, [&](std::size_t row) {
    const auto y = static_cast<int32_t>(row);
    for (int32_t x = 0; x < camera.width; ++x) {
      for (std::size_t s = 0; s < perPixel; ++s) {
        const auto sx = static_cast<float>(s % n), sy = static_cast<float>(s / n);
        const glm::vec2 offset((sx + 0.5f) / n - 0.5f, (sy + 0.5f) / n - 0.5f);
        const glm::vec3 direction =
            n == 1 ? camera.pixelDirection(x, y) : camera.pixelDirection(x, y, offset);
        const auto hit = scene.intersect(camera.position_world, direction);
        if (!hit) continue;
        const std::size_t i = (row * camera.width + x) * perPixel + s;
        image.position[i] = glm::vec4(hit->position_world, 1.0f);
        image.normal[i] = glm::vec4(hit->normal_world, 0.0f);
        image.albedo[i] = glm::vec4(hit->albedo, 1.0f);
        image.geometric[i] = hit->geometric_world;
        image.metallicRoughness[i] = glm::vec2(hit->metallic, hit->roughness);
      }
    }
  });
  return image;
}

}  // namespace tofsim::cpu
