// The scene part of a batch run's content key: which files a glTF reads, and
// that a change of any of them changes the digest.

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>

#include "support/TempDir.h"
#include "tofsim/pipeline/RunContentKey.h"

namespace tofsim::pipeline {
namespace {

namespace fs = std::filesystem;

const char* kGltf = R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": 4, "uri": "data:application/octet-stream;base64,AAAAAA=="},
              {"byteLength": 4, "uri": "mesh%20data.bin"}],
  "images": [{"uri": "tex/a%2Bb.png"}, {"bufferView": 0, "mimeType": "image/png"}]})";

void put32(std::string& bytes, uint32_t v) {
  for (int i = 0; i < 4; ++i) bytes += static_cast<char>((v >> (8 * i)) & 0xff);
}

class RunContentKeyTest : public test::TempDirTest {};

TEST_F(RunContentKeyTest, GltfListsItsExternalFilesDecoded) {
  std::ofstream(dir_ / "scene.gltf") << kGltf;
  const std::vector<fs::path> files = sceneInputFiles(dir_ / "scene.gltf");
  ASSERT_EQ(files.size(), 3u);  // not the data: buffer, not the bufferView image
  EXPECT_EQ(files[0], dir_ / "scene.gltf");
  EXPECT_EQ(files[1], dir_ / "mesh data.bin");
  EXPECT_EQ(files[2], dir_ / "tex/a+b.png");
}

TEST_F(RunContentKeyTest, GlbListsItselfAndExternalImages) {
  std::string json = R"({"asset": {"version": "2.0"}, "images": [{"uri": "t.png"}]})";
  while (json.size() % 4 != 0) json += ' ';
  std::string glb = "glTF";
  put32(glb, 2);
  put32(glb, static_cast<uint32_t>(20 + json.size()));
  put32(glb, static_cast<uint32_t>(json.size()));
  glb += "JSON" + json;
  std::ofstream(dir_ / "scene.glb", std::ios::binary) << glb;
  const std::vector<fs::path> files = sceneInputFiles(dir_ / "scene.glb");
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[1], dir_ / "t.png");
}

TEST_F(RunContentKeyTest, DigestFollowsEveryInputFile) {
  std::ofstream(dir_ / "scene.gltf") << kGltf;
  fs::create_directories(dir_ / "tex");
  std::ofstream(dir_ / "mesh data.bin") << "abcd";
  std::ofstream(dir_ / "tex/a+b.png") << "png1";
  const std::string first = sceneInputsDigest(dir_ / "scene.gltf");
  EXPECT_EQ(sceneInputsDigest(dir_ / "scene.gltf"), first);  // deterministic
  std::ofstream(dir_ / "tex/a+b.png") << "png2";
  const std::string second = sceneInputsDigest(dir_ / "scene.gltf");
  EXPECT_NE(second, first);
  std::ofstream(dir_ / "mesh data.bin") << "abce";
  const std::string third = sceneInputsDigest(dir_ / "scene.gltf");
  EXPECT_NE(third, second);
  fs::remove(dir_ / "mesh data.bin");  // missing is a state too, not an error
  EXPECT_NE(sceneInputsDigest(dir_ / "scene.gltf"), third);
}

}  // namespace
}  // namespace tofsim::pipeline
