// render.adaptive_pixel_samples' edge test on hand-made centre G-buffers: a
// flat plane has no edge pixels, and a depth step, a crease and a silhouette
// against the background mark exactly the pixels whose 3 x 3 neighbourhood
// crosses them.

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "tofsim/ir/SampledPixels.h"

namespace tofsim::ir {
namespace {

constexpr int32_t kSide = 8;

// A centre G-buffer whose pixel (x, y) sees surface(x, y) -> (position, normal)
// (a zero normal means background).
template <typename Surface>
CentreSurfaces gbuffer(Surface surface) {
  CentreSurfaces g;
  g.positions.resize(kSide * kSide * 4);
  g.normals.resize(kSide * kSide * 4);
  for (int32_t y = 0; y < kSide; ++y) {
    for (int32_t x = 0; x < kSide; ++x) {
      const auto [p, n] = surface(x, y);
      const std::size_t i = static_cast<std::size_t>(y * kSide + x) * 4;
      const bool hit = glm::length(n) > 0.0f;
      for (int k = 0; k < 3; ++k) {
        g.positions[i + k] = hit ? p[k] : 0.0f;
        g.normals[i + k] = n[k];
      }
      g.positions[i + 3] = hit ? 1.0f : 0.0f;
    }
  }
  return g;
}

// Columns x whose pixels are marked, checked to be the same on every row.
std::vector<int32_t> markedColumns(const std::vector<uint8_t>& sampled) {
  std::vector<int32_t> columns;
  for (int32_t x = 0; x < kSide; ++x) {
    for (int32_t y = 1; y < kSide; ++y) EXPECT_EQ(sampled[y * kSide + x], sampled[x]) << x;
    if (sampled[x]) columns.push_back(x);
  }
  return columns;
}

const glm::vec3 kUp(0.0f, 0.0f, 1.0f);

TEST(SampledPixelsTest, ATiltedPlaneHasNoEdges) {
  // A plane z = 0.3 x + 0.1 y seen in perspective: unequal steps, one plane.
  const glm::vec3 n = glm::normalize(glm::vec3(-0.3f, -0.1f, 1.0f));
  const auto g = gbuffer([&](int32_t x, int32_t y) {
    const float u = 0.01f * static_cast<float>(x * x + x), v = 0.013f * static_cast<float>(y);
    return std::pair{glm::vec3(u, v, 0.3f * u + 0.1f * v), n};
  });
  EXPECT_TRUE(markedColumns(sampledPixels(g, kSide, kSide)).empty());
}

TEST(SampledPixelsTest, ADepthStepMarksTheColumnsBesideIt) {
  const auto g = gbuffer([&](int32_t x, int32_t y) {
    const float depth = x < 4 ? 0.0f : -0.5f;  // columns 0-3 in front of 4-7
    return std::pair{glm::vec3(0.01f * x, 0.01f * y, depth), kUp};
  });
  EXPECT_EQ(markedColumns(sampledPixels(g, kSide, kSide)), (std::vector<int32_t>{3, 4}));
}

TEST(SampledPixelsTest, ACreaseMarksTheColumnsBesideIt) {
  // A floor (columns 0-4) meets a wall rising at 90 degrees from x = 4.
  const auto g = gbuffer([&](int32_t x, int32_t y) {
    if (x <= 4) return std::pair{glm::vec3(0.01f * x, 0.01f * y, 0.0f), kUp};
    return std::pair{glm::vec3(0.04f, 0.01f * y, 0.01f * (x - 4)), glm::vec3(-1.0f, 0.0f, 0.0f)};
  });
  // Column 4 sees the crease line itself, on the floor: column 3 has only
  // floor around it; 4 and 5 each see the other's normal turned by 90 degrees.
  EXPECT_EQ(markedColumns(sampledPixels(g, kSide, kSide)), (std::vector<int32_t>{4, 5}));
}

TEST(SampledPixelsTest, ASilhouetteAgainstTheBackgroundMarksBothSides) {
  const auto g = gbuffer([&](int32_t x, int32_t y) {
    return std::pair{glm::vec3(0.01f * x, 0.01f * y, 0.0f), x < 5 ? kUp : glm::vec3(0.0f)};
  });
  EXPECT_EQ(markedColumns(sampledPixels(g, kSide, kSide)), (std::vector<int32_t>{4, 5}));
}

TEST(SampledPixelsTest, AShallowCreaseIsAnEdgeBeyondTheTolerance) {
  // A floor, then from column 4 on a plane tilted up by 3 degrees (flat
  // enough) or 8 degrees (an edge).
  for (const float degrees : {3.0f, 8.0f}) {
    const float a = glm::radians(degrees);
    const auto g = gbuffer([&](int32_t x, int32_t y) {
      if (x <= 4) return std::pair{glm::vec3(0.01f * x, 0.01f * y, 0.0f), kUp};
      const float run = 0.01f * static_cast<float>(x - 4);
      return std::pair{glm::vec3(0.04f + run, 0.01f * y, run * std::tan(a)),
                       glm::vec3(-std::sin(a), 0.0f, std::cos(a))};
    });
    const std::vector<int32_t> marked = markedColumns(sampledPixels(g, kSide, kSide));
    if (degrees < kFlatNeighbourAngle_deg) {
      EXPECT_TRUE(marked.empty()) << degrees;
    } else {
      // Column 4 (the crease line, on the floor) sees column 5 off its plane,
      // column 5 sees column 4's normal turned.
      EXPECT_EQ(marked, (std::vector<int32_t>{4, 5})) << degrees;
    }
  }
}

TEST(SampledPixelsTest, AShadowEdgeOnAFlatPlaneMarksTheColumnsBesideIt) {
  // One flat plane: no edge in its geometry, but the light reaches only the
  // centres of columns x < 5.
  const auto g = gbuffer([&](int32_t x, int32_t y) {
    return std::pair{glm::vec3(0.1f * static_cast<float>(x), 0.1f * static_cast<float>(y), 0.0f), kUp};
  });
  std::vector<uint8_t> lit(kSide * kSide);
  for (std::size_t p = 0; p < lit.size(); ++p) lit[p] = p % kSide < 5 ? 1 : 0;
  EXPECT_TRUE(markedColumns(sampledPixels(g, kSide, kSide)).empty());
  EXPECT_EQ(markedColumns(sampledPixels(g, kSide, kSide, lit)), (std::vector<int32_t>{4, 5}));
}

}  // namespace
}  // namespace tofsim::ir
