// The one place a material becomes a scattering vertex (ir::materialVertex,
// the scene's table ir::materialVertices) and the per-point texture step
// (physics::texturedVertex, through ir::hitVertex on the CPU and
// surface_samples.glsl on GL): the factors, times the texels where the
// material has textures, exactly the products the G-buffer and the CPU hit
// computed before the table (factor x texture; the factor alone without one).

#include <gtest/gtest.h>

#include "tofsim/ir/HitVertex.h"
#include "tofsim/ir/MaterialVertex.h"

namespace tofsim::ir {
namespace {

scene::Scene twoMaterials() {
  scene::Scene s;
  scene::Material plain;
  plain.albedo = glm::vec3(0.6f, 0.5f, 0.4f);
  plain.metallic = 0.3f;
  plain.roughness = 0.7f;
  scene::Material other = plain;
  other.albedo = glm::vec3(0.1f, 0.2f, 0.3f);
  s.materials = {plain, other};
  return s;
}

TEST(MaterialVertexTest, TheTableHoldsEachMaterialsVertexInOrder) {
  const scene::Scene s = twoMaterials();
  const auto table = materialVertices(s, physics::VERTEX_GLTF);
  ASSERT_EQ(table.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(glm::vec3(table[i].color), s.materials[i].albedo);
    EXPECT_EQ(table[i].color.w, s.materials[i].metallic);
    EXPECT_EQ(table[i].roughness, s.materials[i].roughness);
    EXPECT_EQ(table[i].model, physics::VERTEX_GLTF);
    EXPECT_EQ(table[i].response, physics::RESPONSE_INSTANT);
  }
}

TEST(MaterialVertexTest, AHitsVertexIsItsMaterialsTimesItsTexels) {
  const scene::Scene s = twoMaterials();
  const auto table = materialVertices(s, physics::VERTEX_GLTF);
  rays::SurfaceHit hit;
  hit.material = 1;
  // No texture: the factors, bit for bit.
  physics::ScatterVertex v = hitVertex(hit, table);
  EXPECT_EQ(glm::vec3(v.color), s.materials[1].albedo);
  EXPECT_EQ(v.color.w, s.materials[1].metallic);
  EXPECT_EQ(v.roughness, s.materials[1].roughness);
  // Textured: factor x texel, the product of before.
  hit.baseColorTexel = glm::vec3(0.5f, 0.25f, 3.0f);
  hit.metallicRoughnessTexel = glm::vec2(0.25f, 0.5f);
  v = hitVertex(hit, table);
  EXPECT_EQ(glm::vec3(v.color), s.materials[1].albedo * hit.baseColorTexel);
  EXPECT_EQ(v.color.w, s.materials[1].metallic * 0.25f);
  EXPECT_EQ(v.roughness, s.materials[1].roughness * 0.5f);
  EXPECT_EQ(v.model, physics::VERTEX_GLTF);
}

}  // namespace
}  // namespace tofsim::ir
