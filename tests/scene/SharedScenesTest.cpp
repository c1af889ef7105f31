// Loads the real glTF files in ../shared/scenes (see its README).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "tofsim/scene/AnimatedScene.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/Error.h"

namespace tofsim::scene {
namespace {

const std::filesystem::path kShared = TOFSIM_SHARED_SCENES_DIR;

class SharedScenesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::is_directory(kShared)) {
      GTEST_SKIP() << "shared scenes folder " << kShared << " is missing";
    }
  }
};

TEST_F(SharedScenesTest, BoxGltfAndGlbBothLoad) {
  for (const char* name : {"loader/Box.gltf", "loader/Box.glb"}) {
    LoadReport report;
    const Scene scene = loadGltf(kShared / name, &report);
    EXPECT_EQ(scene.triangleCount(), 12u) << name;
    const Bounds b = scene.bounds();
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(b.min[i], -0.5f, 1e-5f) << name;
      EXPECT_NEAR(b.max[i], 0.5f, 1e-5f) << name;
    }
    for (const Mesh& m : scene.meshes) {
      ASSERT_EQ(m.normals_world.size(), m.positions_world.size());
      for (const glm::vec3& n : m.normals_world) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    }
  }
}

TEST_F(SharedScenesTest, CornellGlbHasItsNodeRotationApplied) {
  const Scene scene = loadGltf(kShared / "cornell-box/cornell_box.glb");
  EXPECT_EQ(scene.triangleCount(), 32u);
  const Bounds b = scene.bounds();
  EXPECT_NEAR(b.min.y, 0.0f, 0.02f);
  EXPECT_NEAR(b.max.y, 1.99f, 0.02f);
  EXPECT_NEAR(b.min.x, -1.02f, 0.03f);
  EXPECT_NEAR(b.max.z, 0.99f, 0.03f);
}

TEST_F(SharedScenesTest, TexturedBoxHasALinearTexture) {
  for (const char* name : {"loader/BoxTextured/BoxTextured.gltf", "loader/BoxTextured.glb"}) {
    const Scene scene = loadGltf(kShared / name);
    EXPECT_EQ(scene.triangleCount(), 12u);
    ASSERT_EQ(scene.textures.size(), 1u) << name;
    const Texture& t = scene.textures[0];
    ASSERT_GT(t.width, 0);
    ASSERT_EQ(t.rgb.size(), std::size_t(t.width) * t.height * 3);
    float lo = 1.0f, hi = 0.0f;
    for (const float v : t.rgb) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    EXPECT_GE(lo, 0.0f);
    EXPECT_LE(hi, 1.0f);
    EXPECT_GT(hi, lo);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.materials[scene.meshes[0].material].albedoTexture, 0);
    EXPECT_EQ(scene.meshes[0].uvs.size(), scene.meshes[0].positions_world.size());
  }
}

// metallicFactor / roughnessFactor as the file declares them, glTF's default
// 1 where it does not (Box.gltf's "Red" names no roughnessFactor).
TEST_F(SharedScenesTest, MaterialsCarryMetallicAndRoughness) {
  const Scene box = loadGltf(kShared / "loader/Box.gltf");
  ASSERT_EQ(box.materials.size(), 1u);
  EXPECT_EQ(box.materials[0].metallic, 0.0f);
  EXPECT_EQ(box.materials[0].roughness, 1.0f);
  EXPECT_EQ(box.materials[0].metallicRoughnessTexture, -1);
  const Scene room = loadGltf(kShared / "convergence-room/ConvergenceTest.gltf");
  int checked = 0;
  for (const Material& m : room.materials) {
    if (m.name == "Glossy Metal") {
      EXPECT_EQ(m.metallic, 1.0f);
      EXPECT_FLOAT_EQ(m.roughness, 0.2f);
      ++checked;
    } else if (m.name == "Diffuse") {
      EXPECT_EQ(m.metallic, 0.0f);
      EXPECT_EQ(m.roughness, 1.0f);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2);
}

TEST_F(SharedScenesTest, SparseAccessorFileLoads) {
  for (const char* name : {"loader/box_sparse.gltf", "loader/box_sparse.glb"}) {
    EXPECT_EQ(loadGltf(kShared / name).triangleCount(), 12u) << name;
  }
}

TEST_F(SharedScenesTest, MorphWeightAnimationIsCountedNotPlayed) {
  // box_sparse animates its morph-target weights only: nothing moves, the
  // rest scene is loadGltf's and the weights channel and morph mesh are counted.
  for (const char* name : {"loader/box_sparse.gltf", "loader/box_sparse.glb"}) {
    LoadReport report;
    const AnimatedScene animated = AnimatedScene::load(kShared / name, &report);
    EXPECT_FALSE(animated.animated()) << name;
    ASSERT_EQ(animated.animations().size(), 1u) << name;
    EXPECT_EQ(animated.animations()[0].ignoredWeightChannels, 1u) << name;
    EXPECT_EQ(report.morphTargetMeshes, 1u) << name;
    const Scene rest = loadGltf(kShared / name);
    ASSERT_EQ(animated.sceneAt(0.5).meshes.size(), rest.meshes.size()) << name;
    for (std::size_t m = 0; m < rest.meshes.size(); ++m) {
      EXPECT_EQ(animated.sceneAt(0.5).meshes[m].positions_world, rest.meshes[m].positions_world);
    }
  }
}

TEST_F(SharedScenesTest, AnimatedLoaderGivesLoadGltfsBytesOnStaticFiles) {
  // Node rotations (the Z-up Cornell box), cameras, textures, a glb.
  for (const char* name : {"cornell-box/cornell_box.glb", "loader/cameras/Cameras.gltf",
                           "loader/BoxTextured.glb", "loader/Box.gltf"}) {
    const Scene reference = loadGltf(kShared / name);
    const AnimatedScene animated = AnimatedScene::load(kShared / name);
    EXPECT_FALSE(animated.animated()) << name;
    const Scene at = animated.sceneAt(1.0);
    ASSERT_EQ(at.meshes.size(), reference.meshes.size()) << name;
    for (std::size_t m = 0; m < at.meshes.size(); ++m) {
      EXPECT_EQ(at.meshes[m].positions_world, reference.meshes[m].positions_world) << name;
      EXPECT_EQ(at.meshes[m].normals_world, reference.meshes[m].normals_world) << name;
      EXPECT_EQ(at.meshes[m].indices, reference.meshes[m].indices) << name;
    }
    ASSERT_EQ(at.cameras.size(), reference.cameras.size()) << name;
    for (std::size_t c = 0; c < at.cameras.size(); ++c) {
      EXPECT_EQ(at.cameras[c].position_world, reference.cameras[c].position_world) << name;
      EXPECT_EQ(at.cameras[c].forward_world, reference.cameras[c].forward_world) << name;
    }
  }
}

TEST_F(SharedScenesTest, PrimitiveModes) {
  // 00-03 and 07-10: points, lines, line loops, line strips (skipped);
  // 04/11 strips, 05/12 fans and 06/13/14/15 lists: two triangles each.
  for (int i = 0; i <= 15; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "loader/primitive-modes/Mesh_PrimitiveMode_%02d.gltf", i);
    LoadReport report;
    const Scene scene = loadGltf(kShared / name, &report);
    const bool lines = i <= 3 || (i >= 7 && i <= 10);
    EXPECT_EQ(scene.triangleCount(), lines ? 0u : 2u) << name;
    EXPECT_EQ(report.skippedPrimitives, lines ? 1u : 0u) << name;
  }
}

TEST_F(SharedScenesTest, PerspectiveCamerasAreReadOrthographicCounted) {
  LoadReport report;
  const Scene scene = loadGltf(kShared / "loader/cameras/Cameras.gltf", &report);
  ASSERT_EQ(scene.cameras.size(), 1u);
  EXPECT_EQ(report.orthographicCameras, 1u);
  const SceneCamera& c = scene.cameras[0];
  EXPECT_NEAR(c.position_world.x, 0.5f, 1e-6f);
  EXPECT_NEAR(c.position_world.y, 0.5f, 1e-6f);
  EXPECT_NEAR(c.position_world.z, 3.0f, 1e-6f);
  EXPECT_NEAR(c.forward_world.z, -1.0f, 1e-6f);
  EXPECT_NEAR(c.up_world.y, 1.0f, 1e-6f);
  EXPECT_NEAR(c.fov_y_deg, 0.7f * 180.0f / float(M_PI), 1e-4f);
  EXPECT_FLOAT_EQ(c.aspect, 1.0f);
  EXPECT_EQ(scene.triangleCount(), 2u);
}

TEST_F(SharedScenesTest, QuantizedPositionsAndNormals) {
  const Scene scene = loadGltf(kShared / "loader/quantized/triangle_mesh_quantized.gltf");
  ASSERT_EQ(scene.triangleCount(), 1u);
  const Bounds b = scene.bounds();
  EXPECT_FLOAT_EQ(b.max.x, 100.0f);
  EXPECT_FLOAT_EQ(b.max.y, 100.0f);
  // int8 normalized normals at a 4-byte stride: (0,0,127), (0,127,0), (127,0,0).
  const Mesh& m = scene.meshes[0];
  ASSERT_EQ(m.normals_world.size(), 3u);
  EXPECT_EQ(m.normals_world[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(m.normals_world[1], glm::vec3(0, 1, 0));
  EXPECT_EQ(m.normals_world[2], glm::vec3(1, 0, 0));
}

TEST_F(SharedScenesTest, InstancedEngineLoads) {
  LoadReport report;
  const Scene scene = loadGltf(kShared / "loader/2CylinderEngine.glb", &report);
  // README: 121,496 placed triangles; 11,160 of them have exactly zero area.
  EXPECT_EQ(scene.triangleCount() + report.degenerateTriangles, 121496u);
  EXPECT_EQ(report.degenerateTriangles, 11160u);
}

TEST_F(SharedScenesTest, DracoIsRejectedClearly) {
  try {
    loadGltf(kShared / "loader/draco/2CylinderEngine.gltf");
    FAIL() << "draco file loaded";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("required extension KHR_draco_mesh_compression is not supported"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("2CylinderEngine.gltf"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace tofsim::scene
