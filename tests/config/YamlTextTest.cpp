// Every YAML the config module reads goes through one pass (YamlText.h): the
// run config (a file, text from Python, --set values), a batch file and an
// OpenCV lens calibration. A key given twice in one mapping is an error that
// names both places (yaml-cpp kept the first without a word); aliases that
// would expand past kMaxAliasNodes (a "billion laughs" bomb) and an alias
// inside its own anchor (a cycle) are located errors, refused before any
// walk of the document; plain anchors and aliases still load.

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <string>

#include "YamlText.h"
#include "support/AliasBomb.h"
#include "support/TempDir.h"
#include "tofsim/config/BatchConfig.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {
namespace {

class YamlTextTest : public test::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    std::ofstream(dir_ / "scene.gltf") << "{}";
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  // The message of the InputError that `load` throws ("" when it loads).
  template <typename Load>
  static std::string errorOf(Load load) {
    try {
      load();
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(YamlTextTest, DuplicateKeyInAFlowMappingNamesBothPlaces) {
  write("c.yaml",
        "scene: scene.gltf\n"
        "sensors:\n"
        "  - {type: spad, irf: {file: a.csv, file: b.csv}}\n");
  const std::string m = errorOf([&] { loadRunConfig(dir_ / "c.yaml"); });
  EXPECT_NE(m.find("c.yaml:3:37"), std::string::npos) << m;
  EXPECT_NE(m.find("key 'file' appears twice in one mapping: line 3, column 24 and line 3, "
                   "column 37"),
            std::string::npos)
      << m;
}

TEST_F(YamlTextTest, DuplicateKeyInABlockMappingNamesBothLines) {
  write("c.yaml",
        "scene: scene.gltf\n"
        "camera:\n"
        "  fov_y: 40\n"
        "  resolution: [8, 8]\n"
        "  fov_y: 60\n");
  const std::string m = errorOf([&] { loadRunConfig(dir_ / "c.yaml"); });
  EXPECT_NE(m.find("c.yaml:5:3"), std::string::npos) << m;
  EXPECT_NE(m.find("'fov_y' appears twice in one mapping: line 3, column 3 and line 5, column 3"),
            std::string::npos)
      << m;
}

TEST_F(YamlTextTest, DuplicateTopLevelKeyAndAnAliasedKey) {
  write("c.yaml", "scene: scene.gltf\ntime: {bins: 8}\nscene: other.gltf\n");
  EXPECT_NE(errorOf([&] { loadRunConfig(dir_ / "c.yaml"); }).find("'scene' appears twice"),
            std::string::npos);
  // A key written through an alias of a scalar is the same key.
  write("a.yaml", "scene: scene.gltf\nx: &k bins\ntime: {bins: 8, *k : 9}\n");
  const std::string m = errorOf([&] { loadRunConfig(dir_ / "a.yaml"); });
  EXPECT_NE(m.find("'bins' appears twice"), std::string::npos) << m;
}

TEST_F(YamlTextTest, EqualKeysInDifferentMappingsAreFine) {
  write("c.yaml",
        "scene: scene.gltf\nlight: {}\ntime: {}\n"
        "camera: {resolution: [8, 8]}\n"
        "sensors:\n"
        "  - {type: streak, name: a}\n"
        "  - {type: streak, name: b}\n");
  EXPECT_EQ(loadRunConfig(dir_ / "c.yaml").sensors.size(), 2u);
}

TEST_F(YamlTextTest, DuplicateKeyInConfigTextAndInASetValue) {
  const std::string text = errorOf([&] {
    loadRunConfigText("scene: scene.gltf\ntime: {bins: 8, bins: 9}\n", dir_ / "text.yaml");
  });
  EXPECT_NE(text.find("text.yaml:2:17: key 'bins' appears twice"), std::string::npos) << text;
  const std::string set = errorOf([&] {
    write("c.yaml", "scene: scene.gltf\n");
    loadRunConfig(dir_ / "c.yaml", {parseOverride("camera={fov_y: 40, fov_y: 50}")});
  });
  EXPECT_NE(set.find("--set camera={fov_y: 40, fov_y: 50}"), std::string::npos) << set;
  EXPECT_NE(
      set.find("'fov_y' appears twice in one mapping: line 1, column 2 and line 1, column 13"),
      std::string::npos)
      << set;
}

TEST_F(YamlTextTest, DuplicateKeyInABatchFile) {
  write("c.yaml", "scene: scene.gltf\n");
  write("b.yaml",
        "base: c.yaml\n"
        "runs:\n"
        "  - name: a\n"
        "    set: {time.bins: 8}\n"
        "    name: b\n");
  const std::string m = errorOf([&] { loadBatchConfig(dir_ / "b.yaml", {}); });
  EXPECT_NE(m.find("b.yaml:5:5"), std::string::npos) << m;
  EXPECT_NE(m.find("'name' appears twice in one mapping: line 3, column 5 and line 5, column 5"),
            std::string::npos)
      << m;
}

TEST_F(YamlTextTest, DuplicateKeyInALensCalibration) {
  write("calib.yaml",
        "%YAML:1.0\n"
        "---\n"
        "image_width: 80\n"
        "image_height: 60\n"
        "camera_matrix: [70.5, 0., 39.25, 0., 71.0, 29.75, 0., 0., 1.]\n"
        "distortion_coefficients: [-0.21, 0.05, 0.001, -0.002]\n"
        "image_width: 640\n");
  write("c.yaml", "scene: scene.gltf\ncamera:\n  lens: {calibration: calib.yaml}\n");
  const std::string m = errorOf([&] { loadRunConfig(dir_ / "c.yaml"); });
  EXPECT_NE(m.find("camera.lens.calibration"), std::string::npos) << m;
  EXPECT_NE(m.find("calib.yaml:7:1: key 'image_width' appears twice in one mapping: line 3, "
                   "column 1 and line 7, column 1"),
            std::string::npos)
      << m;
}

// Before: a walk of the document expanded the aliases, for minutes, until the
// memory ran out. Now refused at once, at the alias that passes the cap.
TEST_F(YamlTextTest, AliasBombIsRefusedAtOnceInEveryLoader) {
  const auto start = std::chrono::steady_clock::now();
  write("c.yaml", "scene: scene.gltf\nbomb: " + test::aliasBomb() + "\n");
  const std::string file = errorOf([&] { loadRunConfig(dir_ / "c.yaml"); });
  EXPECT_NE(file.find("c.yaml:2:"), std::string::npos) << file;
  EXPECT_NE(file.find("aliases expand this document past 1000000 nodes"), std::string::npos)
      << file;

  write("base.yaml", "scene: scene.gltf\n");
  write("b.yaml", "base: base.yaml\nset:\n  camera.resolution: " + test::aliasBomb() + "\n");
  const std::string batch = errorOf([&] { loadBatchConfig(dir_ / "b.yaml", {}); });
  EXPECT_NE(batch.find("b.yaml:3:"), std::string::npos) << batch;
  EXPECT_NE(batch.find("past 1000000 nodes"), std::string::npos) << batch;

  const std::string set = errorOf([&] {
    loadRunConfig(dir_ / "base.yaml", {{"camera.resolution", test::aliasBomb()}});
  });
  EXPECT_NE(set.find("--set camera.resolution="), std::string::npos) << set;
  EXPECT_NE(set.find("past 1000000 nodes"), std::string::npos) << set;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

TEST_F(YamlTextTest, AliasInsideItsOwnAnchorIsACycle) {
  write("c.yaml", "scene: scene.gltf\ncamera: &c {resolution: [8, 8], again: *c}\n");
  const std::string m = errorOf([&] { loadRunConfig(dir_ / "c.yaml"); });
  EXPECT_NE(m.find("c.yaml:2:40: an alias inside the node its anchor names (a cycle)"),
            std::string::npos)
      << m;
}

TEST_F(YamlTextTest, AliasesUnderTheCapLoad) {
  write("c.yaml", "scene: scene.gltf\nlight: {}\ntime: {}\ncamera: {resolution: [&w 8, *w]}\n");
  EXPECT_EQ(loadRunConfig(dir_ / "c.yaml").camera.camera.height, 8);
  // Exactly at the cap: 1000 aliases of a list of 999 scalars (1000 nodes).
  std::string list = "[&a [";
  for (int i = 0; i < 999; ++i) list += (i ? ", 0" : "0");
  list += "]";
  for (int i = 0; i < 1000; ++i) list += ", *a";
  EXPECT_NO_THROW(parseYaml(list + "]"));
  EXPECT_THROW(parseYaml(list + ", *a]"), YAML::ParserException);
}

}  // namespace
}  // namespace tofsim::config
