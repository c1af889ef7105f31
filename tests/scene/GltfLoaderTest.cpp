// Loader behaviour on tiny hand-written files.
#include "tofsim/scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "GltfTestFiles.h"
#include "support/TempDir.h"
#include "tofsim/util/Error.h"

namespace tofsim::scene {
namespace {

using test::appendBytes;
using test::dataUri;
using test::triangleGltf;
using test::writeText;

class GltfLoaderTest : public test::TempDirTest {
 protected:
  std::string errorOf(const std::filesystem::path& p) {
    try {
      loadGltf(p);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

TEST_F(GltfLoaderTest, NodeTranslationMovesGeometry) {
  const auto path = writeText(dir_ / "t.gltf", triangleGltf(
      R"("nodes": [{"mesh": 0, "translation": [10, 0, -2]}], "scenes": [{"nodes": [0]}])"));
  LoadReport report;
  const Scene scene = loadGltf(path, &report);
  ASSERT_EQ(scene.triangleCount(), 1u);
  const Bounds b = scene.bounds();
  EXPECT_FLOAT_EQ(b.min.x, 10.0f);
  EXPECT_FLOAT_EQ(b.max.x, 11.0f);
  EXPECT_FLOAT_EQ(b.min.z, -2.0f);
  EXPECT_EQ(report.flatNormalPrimitives, 1u);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "default");
  EXPECT_FLOAT_EQ(scene.materials[0].albedo.g, 0.8f);
}

// tofsim info lists, per material, what no renderer reads.
TEST_F(GltfLoaderTest, IgnoredMaterialPartsAreNamedPerMaterial) {
  const auto path = writeText(dir_ / "m.gltf", triangleGltf(R"("nodes": [{"mesh": 0}],
      "scenes": [{"nodes": [0]}],
      "materials": [
        {"name": "plain", "pbrMetallicRoughness": {"metallicFactor": 0.0}},
        {"name": "fancy", "emissiveFactor": [1, 0, 0], "alphaMode": "BLEND",
         "extensions": {"KHR_materials_ior": {"ior": 1.7},
                        "KHR_materials_specular": {"specularFactor": 0.5},
                        "KHR_materials_clearcoat": {"clearcoatFactor": 1.0}}}])"));
  LoadReport report;
  const Scene scene = loadGltf(path, &report);
  ASSERT_EQ(report.ignoredMaterialParts.size(), 2u);
  EXPECT_TRUE(report.ignoredMaterialParts[0].empty());
  const std::vector<std::string> expected = {"emission", "alphaMode BLEND (rendered opaque)",
                                             "KHR_materials_clearcoat",
                                             "KHR_materials_ior (dielectric F0 stays 0.04)",
                                             "KHR_materials_specular (dielectric F0 stays 0.04)"};
  EXPECT_EQ(report.ignoredMaterialParts[1], expected);
  EXPECT_EQ(report.emissiveMaterials, 1u);
  EXPECT_EQ(scene.materials.at(1).name, "fancy");
}

TEST_F(GltfLoaderTest, HierarchyComposesParentScaleAndChildTranslation) {
  const auto path = writeText(dir_ / "h.gltf", triangleGltf(
      R"("nodes": [{"scale": [2, 2, 2], "children": [1]}, {"mesh": 0, "translation": [1, 0, 0]}],
         "scenes": [{"nodes": [0]}])"));
  const Bounds b = loadGltf(path).bounds();
  EXPECT_FLOAT_EQ(b.min.x, 2.0f);  // 2 * (1 + 0)
  EXPECT_FLOAT_EQ(b.max.x, 4.0f);  // 2 * (1 + 1)
  EXPECT_FLOAT_EQ(b.max.y, 2.0f);
}

TEST_F(GltfLoaderTest, MatrixNodeAndRootsWithoutScene) {
  // Column-major matrix translating by (0, 5, 0); no "scenes": roots are used.
  const auto path = writeText(dir_ / "m.gltf", triangleGltf(
      R"("nodes": [{"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,5,0,1]}])"));
  const Bounds b = loadGltf(path).bounds();
  EXPECT_FLOAT_EQ(b.min.y, 5.0f);
  EXPECT_FLOAT_EQ(b.max.y, 6.0f);
}

TEST_F(GltfLoaderTest, InstancingPlacesOneMeshTwice) {
  const auto path = writeText(dir_ / "i.gltf", triangleGltf(
      R"("nodes": [{"mesh": 0}, {"mesh": 0, "translation": [0, 0, 3]}], "scenes": [{"nodes": [0, 1]}])"));
  const Scene scene = loadGltf(path);
  EXPECT_EQ(scene.triangleCount(), 2u);
  EXPECT_FLOAT_EQ(scene.bounds().max.z, 3.0f);
}

TEST_F(GltfLoaderTest, MirroringFlipsWindingSoFlatNormalStaysOnTheFrontSide) {
  const auto path = writeText(dir_ / "neg.gltf", triangleGltf(
      R"("nodes": [{"mesh": 0, "scale": [-1, 1, 1]}], "scenes": [{"nodes": [0]}])"));
  const Scene scene = loadGltf(path);
  ASSERT_EQ(scene.triangleCount(), 1u);
  const Mesh& m = scene.meshes[0];
  EXPECT_NEAR(m.normals_world[0].z, 1.0f, 1e-6f);
  const glm::vec3 a = m.positions_world[m.indices[0]], b = m.positions_world[m.indices[1]],
                  c = m.positions_world[m.indices[2]];
  EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f);
}

TEST_F(GltfLoaderTest, DegenerateTrianglesAreDroppedAndCounted) {
  const auto path = writeText(dir_ / "d.gltf", triangleGltf(
      R"("nodes": [{"mesh": 0}])", {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 1, 2, 2, 2}));
  LoadReport report;
  EXPECT_EQ(loadGltf(path, &report).triangleCount(), 1u);
  EXPECT_EQ(report.degenerateTriangles, 1u);
}

TEST_F(GltfLoaderTest, NanPositionIsAnError) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const auto path = writeText(dir_ / "nan.gltf",
                              triangleGltf(R"("nodes": [{"mesh": 0}])", {0, 0, 0, nan, 0, 0, 0, 1, 0}));
  const std::string e = errorOf(path);
  EXPECT_NE(e.find("nan.gltf"), std::string::npos) << e;
  EXPECT_NE(e.find("NaN"), std::string::npos) << e;
}

// Issue 39: a static scene is bound like an animated one (Scene.h,
// kMaxSceneCoordinate_m): 1e30 m fits a float but not the tracers.
TEST_F(GltfLoaderTest, PositionBeyondTheSceneBoundIsAnError) {
  const auto path = writeText(
      dir_ / "far.gltf", triangleGltf(R"("nodes": [{"mesh": 0}])", {0, 0, 0, 1e30f, 0, 0, 0, 1, 0}));
  const std::string e = errorOf(path);
  EXPECT_NE(e.find("far.gltf"), std::string::npos) << e;
  EXPECT_NE(e.find("POSITION element 1 lies 1e+30 m from the origin (at most 1e+06 m)"),
            std::string::npos)
      << e;
  const auto camera = writeText(
      dir_ / "far_camera.gltf",
      triangleGltf(R"("nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 2e6]}],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1}}])",
                   {0, 0, 0, 1, 0, 0, 0, 1, 0}));
  const std::string c = errorOf(camera);
  EXPECT_NE(c.find("node[1]"), std::string::npos) << c;
  EXPECT_NE(c.find("2e+06 m from the origin"), std::string::npos) << c;
}

TEST_F(GltfLoaderTest, MissingFileNamesIt) {
  const std::string e = errorOf(dir_ / "absent.glb");
  EXPECT_NE(e.find("absent.glb"), std::string::npos) << e;
}

TEST_F(GltfLoaderTest, MissingExternalBufferNamesFileAndUri) {
  const auto path = writeText(dir_ / "nobuf.gltf", R"({"asset": {"version": "2.0"},
    "buffers": [{"byteLength": 36, "uri": "nope.bin"}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "nodes": [{"mesh": 0}]})");
  const std::string e = errorOf(path);
  EXPECT_NE(e.find("nobuf.gltf"), std::string::npos) << e;
  EXPECT_NE(e.find("nope.bin"), std::string::npos) << e;
}

/// Positions (3 vertices) plus uint16 indices, with the index values given.
std::string indexedGltf(const std::vector<uint16_t>& indices, std::size_t positionViewBytes = 36) {
  std::vector<uint8_t> bytes;
  appendBytes(bytes, std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  appendBytes(bytes, indices);
  while (bytes.size() % 4) bytes.push_back(0);
  return R"({"asset": {"version": "2.0"},
    "buffers": [{"byteLength": )" + std::to_string(bytes.size()) + R"(, "uri": ")" + dataUri(bytes) + R"("}],
    "bufferViews": [{"buffer": 0, "byteLength": )" + std::to_string(positionViewBytes) + R"(},
                    {"buffer": 0, "byteOffset": 36, "byteLength": )" + std::to_string(2 * indices.size()) + R"(}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                  {"bufferView": 1, "componentType": 5123, "count": )" + std::to_string(indices.size()) + R"(, "type": "SCALAR"}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "nodes": [{"mesh": 0}]})";
}

TEST_F(GltfLoaderTest, IndexedTrianglesLoad) {
  EXPECT_EQ(loadGltf(writeText(dir_ / "ok.gltf", indexedGltf({0, 1, 2}))).triangleCount(), 1u);
}

TEST_F(GltfLoaderTest, OutOfRangeIndexIsAnError) {
  const std::string e = errorOf(writeText(dir_ / "idx.gltf", indexedGltf({0, 1, 7})));
  EXPECT_NE(e.find("idx.gltf"), std::string::npos) << e;
  EXPECT_NE(e.find("index 7 out of range"), std::string::npos) << e;
}

TEST_F(GltfLoaderTest, AccessorPastItsBufferViewIsAnError) {
  // The position view claims only 24 bytes; the accessor needs 36.
  const std::string e = errorOf(writeText(dir_ / "short.gltf", indexedGltf({0, 1, 2}, 24)));
  EXPECT_NE(e.find("short.gltf"), std::string::npos) << e;
  EXPECT_NE(e.find("accessor[0]"), std::string::npos) << e;
}

TEST_F(GltfLoaderTest, SparsePositionsAreApplied) {
  // Base positions are the unit triangle; sparse moves vertex 1 to (5, 0, 0).
  std::vector<uint8_t> bytes;
  appendBytes(bytes, std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  appendBytes(bytes, std::vector<uint32_t>{1});
  appendBytes(bytes, std::vector<float>{5, 0, 0});
  const auto path = writeText(dir_ / "sparse.gltf", R"({"asset": {"version": "2.0"},
    "buffers": [{"byteLength": 52, "uri": ")" + dataUri(bytes) + R"("}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 4},
                    {"buffer": 0, "byteOffset": 40, "byteLength": 12}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5125},
                              "values": {"bufferView": 2}}}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "nodes": [{"mesh": 0}]})");
  EXPECT_FLOAT_EQ(loadGltf(path).bounds().max.x, 5.0f);
}

TEST_F(GltfLoaderTest, UnsupportedRequiredExtensionInGlbJson) {
  const std::string json = R"({"asset": {"version": "2.0"}, "extensionsRequired": ["EXT_meshopt_compression"]})";
  std::string padded = json;
  while (padded.size() % 4) padded += ' ';
  std::string glb = "glTF";
  const auto u32 = [&](uint32_t v) { for (int i = 0; i < 4; ++i) glb += char(v >> (8 * i) & 0xFF); };
  u32(2);
  u32(12 + 8 + uint32_t(padded.size()));
  u32(uint32_t(padded.size()));
  u32(0x4E4F534A);
  glb += padded;
  const std::string e = errorOf(writeText(dir_ / "meshopt.glb", glb));
  EXPECT_NE(e.find("required extension EXT_meshopt_compression is not supported"), std::string::npos) << e;
}

}  // namespace
}  // namespace tofsim::scene
