// The CPU albedo lookup follows GL_LINEAR + GL_REPEAT with glTF's top-left uv
// origin, like the GL G-buffer.

#include <gtest/gtest.h>

#include "tofsim/scene/TextureSampling.h"

namespace tofsim::scene {
namespace {

// 2 x 2 texture, red channel = 1, 2 (top row), 3, 4 (bottom row).
Texture twoByTwo() {
  Texture t;
  t.width = 2;
  t.height = 2;
  t.rgb = {1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 0};
  return t;
}

TEST(TextureSamplingTest, TexelCentresReturnTexels) {
  const Texture t = twoByTwo();
  EXPECT_FLOAT_EQ(sampleBilinear(t, {0.25f, 0.25f}).r, 1.0f);
  EXPECT_FLOAT_EQ(sampleBilinear(t, {0.75f, 0.25f}).r, 2.0f);
  EXPECT_FLOAT_EQ(sampleBilinear(t, {0.25f, 0.75f}).r, 3.0f);
  EXPECT_FLOAT_EQ(sampleBilinear(t, {0.75f, 0.75f}).r, 4.0f);
}

TEST(TextureSamplingTest, InterpolatesBetweenCentresAndWraps) {
  const Texture t = twoByTwo();
  EXPECT_FLOAT_EQ(sampleBilinear(t, {0.5f, 0.5f}).r, 2.5f);
  EXPECT_FLOAT_EQ(sampleBilinear(t, {0.5f, 0.25f}).r, 1.5f);
  // u = 0: halfway between the last column (wrapped) and the first.
  EXPECT_FLOAT_EQ(sampleBilinear(t, {0.0f, 0.25f}).r, 1.5f);
  EXPECT_FLOAT_EQ(sampleBilinear(t, {1.25f, -0.75f}).r, 1.0f);
}

TEST(TextureSamplingTest, BaseColorTexelIsTheTextureOrOne) {
  Scene scene;
  scene.textures.push_back(twoByTwo());
  Material plain;
  plain.albedo = glm::vec3(0.5f, 0.25f, 1.0f);
  Material textured = plain;
  textured.albedoTexture = 0;
  scene.materials = {plain, textured};
  EXPECT_EQ(baseColorTexel(scene, 0, {0.75f, 0.75f}), glm::vec3(1.0f));
  EXPECT_EQ(baseColorTexel(scene, 1, {0.75f, 0.75f}),
            sampleBilinear(scene.textures[0], {0.75f, 0.75f}));
  EXPECT_EQ(baseColorTexel(scene, 1, {0.75f, 0.75f}), glm::vec3(4.0f, 0.0f, 0.0f));
}

TEST(TextureSamplingTest, MetallicRoughnessTexelIsBlueAndGreenOrOne) {
  Scene scene;
  Texture t;
  t.width = t.height = 1;
  t.rgb = {0.9f, 0.5f, 0.25f};  // R unused, G roughness, B metallic (glTF)
  scene.textures.push_back(t);
  Material plain;
  plain.metallic = 0.8f;
  plain.roughness = 0.6f;
  Material textured = plain;
  textured.metallicRoughnessTexture = 0;
  scene.materials = {plain, textured};
  EXPECT_EQ(metallicRoughnessTexel(scene, 0, {0.5f, 0.5f}), glm::vec2(1.0f));
  EXPECT_EQ(metallicRoughnessTexel(scene, 1, {0.5f, 0.5f}), glm::vec2(0.25f, 0.5f));
}

}  // namespace
}  // namespace tofsim::scene
