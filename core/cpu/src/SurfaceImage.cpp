#include "SurfaceImage.h"

#include "ParallelFor.h"
#include "tofsim/util/Error.h"

namespace tofsim::cpu {

SurfaceImage traceSurfaces(const reference::RayScene& scene, const capture::Camera& camera,
                           int threads, int32_t samplesPerSide) {
  SurfaceImage image;
  image.width = camera.width;
  image.height = camera.height;
  const int32_t n = samplesPerSide;
  const std::size_t perPixel = static_cast<std::size_t>(n) * n;
  const std::size_t pixelCount = static_cast<std::size_t>(camera.width) * camera.height;
  image.side.assign(pixelCount, n);
  image.firstSample.resize(pixelCount + 1);
  for (std::size_t p = 0; p <= pixelCount; ++p) image.firstSample[p] = p * perPixel;
  const std::size_t pixels = pixelCount * perPixel;
  image.position.assign(pixels, glm::vec4(0.0f));
  image.normal.assign(pixels, glm::vec4(0.0f));
  image.albedo.assign(pixels, glm::vec4(0.0f));
  image.geometric.assign(pixels, glm::vec3(0.0f));
  image.metallicRoughness.assign(pixels, glm::vec2(0.0f));
  const capture::PixelRays rays(camera);
  parallelFor(static_cast<std::size_t>(camera.height), threads, [&](std::size_t row) {
    const auto y = static_cast<int32_t>(row);
    for (int32_t x = 0; x < camera.width; ++x) {
      for (std::size_t s = 0; s < perPixel; ++s) {
        const auto sx = static_cast<float>(s % n), sy = static_cast<float>(s / n);
        const glm::vec2 offset((sx + 0.5f) / n - 0.5f, (sy + 0.5f) / n - 0.5f);
        const glm::vec3 direction = n == 1 ? rays.direction(x, y) : rays.direction(x, y, offset);
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

SurfaceImage adaptiveSurfaces(const SurfaceImage& centres, const SurfaceImage& subSamples,
                              const std::vector<uint8_t>& sampled) {
  const std::size_t pixels = sampled.size();
  TOFSIM_CHECK(centres.side.size() == pixels && subSamples.side.size() == pixels);
  SurfaceImage image;
  image.width = centres.width;
  image.height = centres.height;
  image.side.resize(pixels);
  image.firstSample.resize(pixels + 1);
  for (std::size_t p = 0; p < pixels; ++p) {
    const SurfaceImage& from = sampled[p] ? subSamples : centres;
    image.side[p] = from.side[p];
    image.firstSample[p + 1] = image.firstSample[p] + from.samplesOf(p);
  }
  const std::size_t total = image.firstSample[pixels];
  image.position.resize(total);
  image.normal.resize(total);
  image.albedo.resize(total);
  image.geometric.resize(total);
  image.metallicRoughness.resize(total);
  for (std::size_t p = 0; p < pixels; ++p) {
    const SurfaceImage& from = sampled[p] ? subSamples : centres;
    for (std::size_t k = 0; k < from.samplesOf(p); ++k) {
      const std::size_t to = image.firstSample[p] + k, at = from.firstSample[p] + k;
      image.position[to] = from.position[at];
      image.normal[to] = from.normal[at];
      image.albedo[to] = from.albedo[at];
      image.geometric[to] = from.geometric[at];
      image.metallicRoughness[to] = from.metallicRoughness[at];
    }
  }
  return image;
}

}  // namespace tofsim::cpu
