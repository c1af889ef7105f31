#include "tofsim/ir/SurfaceImage.h"

#include <optional>

#include "tofsim/capture/ThinLens.h"
#include "tofsim/ir/HitVertex.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::ir {

namespace {

// An image of `sides[p]` x `sides[p]` x `apertureSamples` samples for pixel
// p, all empty.
SurfaceImage emptyImage(const capture::Imager& imager, std::vector<int32_t> sides,
                        int32_t apertureSamples) {
  SurfaceImage image;
  image.width = capture::imageWidth(imager);
  image.height = capture::imageHeight(imager);
  image.apertureSamples = apertureSamples;
  const std::size_t pixelCount = sides.size();
  const auto k = static_cast<std::size_t>(apertureSamples);
  image.firstSample.resize(pixelCount + 1);
  image.firstSample[0] = 0;
  for (std::size_t p = 0; p < pixelCount; ++p) {
    image.firstSample[p + 1] = image.firstSample[p] + static_cast<std::size_t>(sides[p]) *
                                                          static_cast<std::size_t>(sides[p]) * k;
  }
  image.side = std::move(sides);
  const std::size_t samples = image.firstSample[pixelCount];
  image.position.assign(samples, glm::vec4(0.0f));
  image.normal.assign(samples, glm::vec4(0.0f));
  image.vertex.assign(
      samples, physics::scatterVertex(physics::VERTEX_LAMBERTIAN, glm::vec3(0.0f), 0.0f, 0.0f));
  image.geometric.assign(samples, glm::vec3(0.0f));
  // Each sample's own camera end: a defocused camera's aperture point, or
  // the origin of a ray that has its own.
  if (apertureSamples > 1 || !capture::raysShareOrigin(imager))
    image.aperture.assign(samples, glm::vec4(0.0f));
  return image;
}

// Traces every sample of `image` (its layout set), row by row on `threads`.
void traceInto(SurfaceImage& image, const rays::RayScene& scene, const capture::Imager& imager,
               int threads, int vertexModel) {
  const capture::PrimaryRays rays(imager);
  const int32_t k = image.apertureSamples;
  std::optional<capture::ThinLens> lens;
  if (k > 1) lens.emplace(*capture::cameraOf(imager));
  const std::vector<physics::ScatterVertex> materials =
      materialVertices(scene.scene(), vertexModel);
  parallelFor(static_cast<std::size_t>(image.height), threads, [&](std::size_t row) {
    const auto y = static_cast<int32_t>(row);
    for (int32_t x = 0; x < image.width; ++x) {
      const std::size_t p = row * image.width + x;
      const int32_t n = image.side[p];
      for (std::size_t e = 0; e < image.samplesOf(p); ++e) {
        const capture::ApertureRay through =
            sampleRay(rays, lens ? &*lens : nullptr, x, y, n, k, e);
        const capture::PrimaryRay& ray = through.ray;
        const std::size_t i = image.firstSample[p] + e;
        // Without a lens, no lens path after the origin.
        if (!image.aperture.empty()) image.aperture[i] = glm::vec4(ray.origin, through.lensPath_m);
        const auto hit = scene.intersect(ray.origin, ray.direction);
        if (!hit) continue;
        image.position[i] = glm::vec4(hit->position_world, 1.0f);
        image.normal[i] = glm::vec4(hit->normal_world, 0.0f);
        image.vertex[i] = hitVertex(*hit, materials);
        image.geometric[i] = hit->geometric_world;
      }
    }
  });
}

}  // namespace

capture::ApertureRay sampleRay(const capture::PrimaryRays& rays, const capture::ThinLens* lens,
                               int32_t x, int32_t y, int32_t side, int32_t apertureSamples,
                               std::size_t e) {
  const std::size_t s = e / static_cast<std::size_t>(apertureSamples);  // the sub-pixel
  const int32_t n = side;
  const auto sx = static_cast<float>(s % n), sy = static_cast<float>(s / n);
  const glm::vec2 offset((sx + 0.5f) / n - 0.5f, (sy + 0.5f) / n - 0.5f);
  const capture::PrimaryRay ray = n == 1 ? rays.ray(x, y) : rays.ray(x, y, offset);
  if (lens == nullptr) return {ray, 0.0f};
  return lens->through(
      ray, capture::aperturePoint(static_cast<int32_t>(e % apertureSamples), apertureSamples));
}

SurfaceImage traceSurfaces(const rays::RayScene& scene, const capture::Imager& imager, int threads,
                           int32_t samplesPerSide, int32_t apertureSamples, int vertexModel) {
  const std::size_t pixels =
      static_cast<std::size_t>(capture::imageWidth(imager)) * capture::imageHeight(imager);
  SurfaceImage image =
      emptyImage(imager, std::vector<int32_t>(pixels, samplesPerSide), apertureSamples);
  traceInto(image, scene, imager, threads, vertexModel);
  return image;
}

SurfaceImage traceSampledPixels(const rays::RayScene& scene, const capture::Imager& imager,
                                int threads, int32_t samplesPerSide,
                                const std::vector<uint8_t>& sampled, int32_t apertureSamples,
                                int vertexModel) {
  TOFSIM_CHECK_EQ(sampled.size(), static_cast<std::size_t>(capture::imageWidth(imager)) *
                                      capture::imageHeight(imager));
  std::vector<int32_t> sides(sampled.size());
  for (std::size_t p = 0; p < sampled.size(); ++p) sides[p] = sampled[p] ? samplesPerSide : 1;
  SurfaceImage image = emptyImage(imager, std::move(sides), apertureSamples);
  traceInto(image, scene, imager, threads, vertexModel);
  return image;
}

CentreSurfaces centresOf(const SurfaceImage& centres) {
  TOFSIM_CHECK_EQ(centres.size(), static_cast<std::size_t>(centres.width) * centres.height);
  CentreSurfaces out;
  out.positions.resize(centres.size() * 4);
  out.normals.resize(centres.size() * 4);
  for (std::size_t i = 0; i < centres.size(); ++i) {
    for (int k = 0; k < 4; ++k) {
      out.positions[i * 4 + k] = centres.position[i][k];
      out.normals[i * 4 + k] = centres.normal[i][k];
    }
  }
  return out;
}

}  // namespace tofsim::ir
