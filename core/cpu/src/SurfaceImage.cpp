#include "SurfaceImage.h"

#include "ParallelFor.h"

namespace tofsim::cpu {

SurfaceImage traceSurfaces(const reference::RayScene& scene, const capture::Camera& camera,
                           int threads) {
  SurfaceImage image;
  image.width = camera.width;
  image.height = camera.height;
  const std::size_t pixels = static_cast<std::size_t>(camera.width) * camera.height;
  image.position.assign(pixels, glm::vec4(0.0f));
  image.normal.assign(pixels, glm::vec4(0.0f));
  image.albedo.assign(pixels, glm::vec4(0.0f));
  image.geometric.assign(pixels, glm::vec3(0.0f));
  parallelFor(static_cast<std::size_t>(camera.height), threads, [&](std::size_t row) {
    const auto y = static_cast<int32_t>(row);
    for (int32_t x = 0; x < camera.width; ++x) {
      const auto hit = scene.intersect(camera.position_world, camera.pixelDirection(x, y));
      if (!hit) continue;
      const std::size_t i = row * camera.width + x;
      image.position[i] = glm::vec4(hit->position_world, 1.0f);
      image.normal[i] = glm::vec4(hit->normal_world, 0.0f);
      image.albedo[i] = glm::vec4(hit->albedo, 1.0f);
      image.geometric[i] = hit->geometric_world;
    }
  });
  return image;
}

}  // namespace tofsim::cpu
