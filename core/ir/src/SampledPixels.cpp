#include "tofsim/ir/SampledPixels.h"

#include <cmath>
#include <glm/glm.hpp>

#include "tofsim/util/Error.h"

namespace tofsim::ir {

namespace {

glm::vec4 texel(const std::vector<float>& image, std::size_t pixel) {
  const float* p = &image[pixel * 4];
  return {p[0], p[1], p[2], p[3]};
}

}  // namespace

bool onFlatSurface(const glm::vec3& p, const glm::vec3& n, const glm::vec3& q,
                   const glm::vec3& m) {
  const float sinTolerance = std::sin(glm::radians(kFlatNeighbourAngle_deg));
  const float cosTolerance = std::cos(glm::radians(kFlatNeighbourAngle_deg));
  const glm::vec3 d = q - p;
  return std::abs(glm::dot(n, d)) <= sinTolerance * glm::length(d) && glm::dot(n, m) >= cosTolerance;
}

std::vector<uint8_t> sampledPixels(const CentreSurfaces& surfaces, int32_t width, int32_t height,
                                   const std::vector<uint8_t>& lit) {
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  TOFSIM_CHECK(surfaces.positions.size() == pixels * 4 && surfaces.normals.size() == pixels * 4);
  TOFSIM_CHECK(lit.empty() || lit.size() == pixels);
  std::vector<uint8_t> sampled(pixels, 0);
  for (int32_t y = 0; y < height; ++y) {
    for (int32_t x = 0; x < width; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * width + x;
      const glm::vec4 position = texel(surfaces.positions, p);
      const glm::vec3 normal(texel(surfaces.normals, p));
      const bool surface = position.w != 0.0f;
      bool edge = false;
      for (int32_t dy = -1; dy <= 1 && !edge; ++dy) {
        for (int32_t dx = -1; dx <= 1 && !edge; ++dx) {
          const int32_t nx = x + dx, ny = y + dy;
          if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          const std::size_t q = static_cast<std::size_t>(ny) * width + nx;
          const glm::vec4 other = texel(surfaces.positions, q);
          if ((other.w != 0.0f) != surface) {
            edge = true;  // a silhouette against the background
          } else if (surface) {
            edge = !onFlatSurface(glm::vec3(position), normal, glm::vec3(other),
                                  glm::vec3(texel(surfaces.normals, q))) ||
                   (!lit.empty() && lit[p] != lit[q]);
          }
        }
      }
      sampled[p] = edge ? 1 : 0;
    }
  }
  return sampled;
}

}  // namespace tofsim::ir
