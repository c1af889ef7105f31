// The scattering vertex (shaders/scatter_vertex.glsl): scatter() returns, bit
// for bit, the factors the gathers multiplied by before it existed (albedo /
// pi, gltfBrdf), and 1 / (4 pi) of the albedo for a medium point from any
// pair of directions; vplScatter is 1 where the VPL's flux holds its scatter
// and the clamped BRDF otherwise; a medium point takes light with no cosine.

#include <gtest/gtest.h>

#include "tofsim/physics/ScatterVertex.h"

namespace tofsim::physics {
namespace {

const glm::vec3 kN(0.0f, 0.0f, 1.0f);
const glm::vec3 kIn = glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f));
const glm::vec3 kOut = glm::normalize(glm::vec3(-0.5f, 0.1f, 0.6f));
const glm::vec3 kColor(0.6f, 0.5f, 0.4f);

TEST(ScatterVertexTest, EachModelScattersByTheFactorOfBefore) {
  const Scattered lambert =
      scatter(scatterVertex(VERTEX_LAMBERTIAN, kColor, 0.3f, 0.4f), kN, kIn, kOut);
  EXPECT_EQ(lambert.f, kColor / PI);
  EXPECT_EQ(lambert.response, RESPONSE_INSTANT);
  const Scattered gltf = scatter(scatterVertex(VERTEX_GLTF, kColor, 0.3f, 0.4f), kN, kIn, kOut);
  EXPECT_EQ(gltf.f, gltfBrdf(kN, kIn, kOut, kColor, 0.3f, 0.4f));
  EXPECT_NE(gltf.f, lambert.f);
}

TEST(ScatterVertexTest, AMediumPointIsAnIsotropicPhaseFunctionWithNoCosine) {
  const ScatterVertex medium = scatterVertex(VERTEX_MEDIUM, kColor, 0.0f, 1.0f);
  const glm::vec3 expected = kColor / (4.0f * PI);
  EXPECT_EQ(scatter(medium, glm::vec3(0.0f), kIn, kOut).f, expected);
  EXPECT_EQ(scatter(medium, glm::vec3(0.0f), -kIn, kIn).f, expected);  // backward too
  EXPECT_TRUE(scatterIsConstant(medium));
  EXPECT_EQ(receiverCosine(medium, glm::vec3(0.0f), kIn), 1.0f);
  const ScatterVertex surface = scatterVertex(VERTEX_LAMBERTIAN, kColor, 0.0f, 1.0f);
  EXPECT_EQ(receiverCosine(surface, kN, kIn), glm::dot(kN, kIn));
  // The light below the point: a medium takes it, a surface facing up not.
  const glm::vec3 x(0.0f), below(0.0f, 0.0f, -2.0f);
  const LightArrival m =
      vertexLightArrival(medium, x, glm::vec3(0.0f), below, LIGHT_POINT, kN, 0.0f, 1.0f);
  EXPECT_EQ(m.cosX, 1.0f);
  EXPECT_EQ(m.profile, 1.0f);
  EXPECT_EQ(vertexLightArrival(surface, x, kN, below, LIGHT_POINT, kN, 0.0f, 1.0f).profile, 0.0f);
}

// The lanes' branch-free receiver cosine (receiverCosineOffset plus the dot
// with receiverNormal) is receiverCosine: bit for bit on a surface, 1 in a
// medium whatever normal it was given; the footprint's plane is a surface's
// tangent plane and a medium point's cross-section of the ray.
TEST(ScatterVertexTest, TheLanesReceiverCosineAndFootprintPlaneFollowTheVertex) {
  const ScatterVertex medium = scatterVertex(VERTEX_MEDIUM, kColor, 0.0f, 1.0f);
  const ScatterVertex surface = scatterVertex(VERTEX_GLTF, kColor, 0.0f, 1.0f);
  EXPECT_FALSE(vertexOnSurface(medium));
  EXPECT_TRUE(vertexOnSurface(surface));
  for (const glm::vec3& w : {kIn, kOut, -kIn, glm::vec3(1.0f, 0.0f, 0.0f)}) {
    const float lane = receiverCosineOffset(surface) - glm::dot(receiverNormal(surface, kN), -w);
    EXPECT_EQ(lane, receiverCosine(surface, kN, w));
    EXPECT_EQ(receiverCosineOffset(medium) + glm::dot(receiverNormal(medium, kN), w), 1.0f);
  }
  EXPECT_EQ(footprintPlaneNormal(surface, kN, kOut), kN);
  EXPECT_EQ(footprintPlaneNormal(medium, glm::vec3(0.0f), kOut), kOut);
}

TEST(ScatterVertexTest, AVplScattersByOneWhereItsFluxHoldsItElseByItsClampedBrdf) {
  const ScatterVertex lambert = scatterVertex(VERTEX_LAMBERTIAN, kColor, 0.0f, 1.0f);
  EXPECT_TRUE(vplFluxHoldsScatter(lambert));
  EXPECT_EQ(vplScatter(lambert, kN, kIn, kOut, 0.5f), glm::vec3(1.0f));
  const ScatterVertex metal = scatterVertex(VERTEX_GLTF, kColor, 1.0f, 0.05f);
  const glm::vec3 mirror(-kIn.x, -kIn.y, kIn.z);  // the lobe's peak
  EXPECT_EQ(vplScatter(metal, kN, kIn, mirror, 0.0f),
            gltfVplBrdf(kN, kIn, mirror, kColor, 1.0f, 0.05f, 0.0f));
  EXPECT_GT(vplScatter(metal, kN, kIn, mirror, 0.0f).r, 2.0f);
  EXPECT_EQ(vplScatter(metal, kN, kIn, mirror, 2.0f), glm::vec3(2.0f));
}

}  // namespace
}  // namespace tofsim::physics
