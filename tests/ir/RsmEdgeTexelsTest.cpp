// render.indirect.rsm_edge_samples' bookkeeping on hand-made sub-texels: the
// sub-texels on one flat surface become one VPL with their summed flux, at
// the member nearest their centroid, its patch their bounding box shrunk to
// their area; the
// edge texels are the RSM's silhouettes and creases; only they are split.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tofsim/ir/RsmEdgeTexels.h"
#include "tofsim/ir/SampledPixels.h"

namespace tofsim::ir {
namespace {

// A sub-texel's VPL: on the floor y = 0 (normal +y) or on the wall z = 0
// (normal +z), with a unit patch and flux `flux` in every channel.
Vpl subTexel(bool wall, float u, float v, float flux) {
  Vpl vpl{};
  vpl.positionPath = wall ? glm::vec4(u, v, 0.0f, 1.0f) : glm::vec4(u, 0.0f, v, 1.0f);
  vpl.normal = wall ? glm::vec4(0, 0, 1, 0) : glm::vec4(0, 1, 0, 0);
  vpl.flux = glm::vec4(flux, flux, flux, 0.0f);
  vpl.patchU = glm::vec4(0.01f, 0.0f, 0.0f, 0.002f);
  vpl.patchV = glm::vec4(0.0f, 0.0f, 0.01f, 0.003f);
  return vpl;
}

TEST(RsmEdgeTexelsTest, SubTexelsOnTwoSurfacesMakeTwoVplsWithTheirFlux) {
  // 4 x 4 sub-texels of a texel across a crease: the left 3 columns on the
  // wall, the right one on the floor, the top-left one missing.
  constexpr int n = 4;
  std::vector<std::optional<Vpl>> subs(n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (i == 0 && j == n - 1) continue;
      const float flux = 1.0f + 0.1f * static_cast<float>(j * n + i);
      subs[j * n + i] = subTexel(i < 3, 0.01f * i, 0.01f * (j + 1), flux);
    }
  }
  const std::vector<Vpl> merged = mergeSubTexelVpls(subs, n);
  ASSERT_EQ(merged.size(), 2u);
  float wallFlux = 0.0f, floorFlux = 0.0f;
  for (int s = 0; s < n * n; ++s) {
    if (subs[s]) (s % n < 3 ? wallFlux : floorFlux) += subs[s]->flux.r;
  }
  // The wall's 11 sub-texels: centroid (13/11, 15/11) in sub-texel units, nearest member (1, 1).
  EXPECT_EQ(merged[0].normal, glm::vec4(0, 0, 1, 0));
  EXPECT_FLOAT_EQ(merged[0].flux.g, wallFlux);
  EXPECT_EQ(merged[0].positionPath, subs[1 * n + 1]->positionPath);
  // Its patch: its 3 x 4 bounding box, shrunk to 11 sub-texels' area.
  EXPECT_FLOAT_EQ(merged[0].patchU.x, 0.01f * 3.0f * std::sqrt(11.0f / 12.0f));
  EXPECT_FLOAT_EQ(merged[0].patchV.w, 0.003f * 4.0f * std::sqrt(11.0f / 12.0f));
  // The floor's column of 4: centroid (3, 1.5), nearest member (3, 1), the first of two.
  EXPECT_EQ(merged[1].normal, glm::vec4(0, 1, 0, 0));
  EXPECT_FLOAT_EQ(merged[1].flux.b, floorFlux);
  EXPECT_EQ(merged[1].positionPath, subs[1 * n + 3]->positionPath);
  // A strip one sub-texel wide along the crease keeps that width.
  EXPECT_FLOAT_EQ(merged[1].patchU.x, 0.01f);
  EXPECT_FLOAT_EQ(merged[1].patchV.z, 0.04f);
}

TEST(RsmEdgeTexelsTest, NoSubTexelHitsNoVpl) {
  EXPECT_TRUE(mergeSubTexelVpls(std::vector<std::optional<Vpl>>(9), 3).empty());
}

TEST(RsmEdgeTexelsTest, TheSubTexelSideKeepsTheFinerRsmWithinItsLimit) {
  EXPECT_EQ(rsmEdgeSamples(4, 32), 4);
  EXPECT_EQ(rsmEdgeSamples(4, 1024), 2);
  EXPECT_EQ(rsmEdgeSamples(16, 300), 6);
  EXPECT_EQ(rsmEdgeSamples(4, 4096), 1);
  EXPECT_EQ(rsmEdgeSamples(1, 8), 1);
}

// An 8 x 8 view whose texels x < 5 see the floor and the rest nothing.
TexelVpls halfFloor() {
  constexpr int side = 8;
  TexelVpls texels(side);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < 5; ++x) {
      texels.add(static_cast<std::size_t>(y * side + x),
                 subTexel(false, 0.1f * x, 0.1f * y, 1.0f));
    }
  }
  return texels;
}

TEST(RsmEdgeTexelsTest, TheSilhouetteTexelsAreTheEdges) {
  const std::vector<uint8_t> edges = rsmEdgeTexels(halfFloor(), 8);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) EXPECT_EQ(edges[y * 8 + x], x == 4 || x == 5) << x << "," << y;
  }
}

// rsmEdgeTexels visits only the texels with a VPL; on views of scattered
// texels on two planes and nothing it marks what sampledPixels does.
TEST(RsmEdgeTexelsTest, TheSparseTestIsSampledPixels) {
  constexpr int side = 12;
  std::mt19937 random(5);
  for (int trial = 0; trial < 50; ++trial) {
    TexelVpls texels(side);
    CentreSurfaces surfaces;
    surfaces.positions.assign(side * side * 4, 0.0f);
    surfaces.normals.assign(side * side * 4, 0.0f);
    for (int t = 0; t < side * side; ++t) {
      const unsigned what = random() % 4;  // nothing, floor, wall, floor
      if (what == 0) continue;
      const Vpl v = subTexel(what == 2, 0.1f * (t % side), 0.1f * (t / side), 1.0f);
      texels.add(static_cast<std::size_t>(t), v);
      for (int c = 0; c < 3; ++c) {
        surfaces.positions[t * 4 + c] = v.positionPath[c];
        surfaces.normals[t * 4 + c] = v.normal[c];
      }
      surfaces.positions[t * 4 + 3] = 1.0f;
    }
    EXPECT_EQ(rsmEdgeTexels(texels, side), sampledPixels(surfaces, side, side)) << trial;
  }
}

TEST(RsmEdgeTexelsTest, OnlyTheEdgeTexelsAreSplit) {
  constexpr int side = 8, n = 2;
  int calls = 0;
  // Every edge texel's sub-texels: the left column on the floor, flux 0.25 each.
  const SubTexelSource source = [&](const std::vector<uint8_t>& edges, int subSide) {
    ++calls;
    EXPECT_EQ(subSide, n);
    std::vector<std::optional<Vpl>> subs;
    for (std::size_t t = 0; t < edges.size(); ++t) {
      if (!edges[t]) continue;
      for (int s = 0; s < n * n; ++s) {
        subs.push_back(s % n == 0 ? std::optional<Vpl>(subTexel(false, 0.5f, 0.1f * (t / side),
                                                                0.25f))
                                  : std::nullopt);
      }
    }
    return subs;
  };
  const std::vector<Vpl> vpls = rsmViewVpls(halfFloor(), side, n, source);
  EXPECT_EQ(calls, 1);
  // Per row: texels 0..3 as they were (flux 1), edges 4 and 5 one VPL each of flux 0.5.
  ASSERT_EQ(vpls.size(), 8u * 6u);
  for (int y = 0; y < side; ++y) {
    for (int k = 0; k < 6; ++k) EXPECT_FLOAT_EQ(vpls[y * 6 + k].flux.r, k < 4 ? 1.0f : 0.5f);
  }
  // n = 1: the texels' own VPLs, and no sub-texel is asked for.
  EXPECT_EQ(rsmViewVpls(halfFloor(), side, 1, source).size(), 8u * 5u);
  EXPECT_EQ(calls, 1);
}

}  // namespace
}  // namespace tofsim::ir
