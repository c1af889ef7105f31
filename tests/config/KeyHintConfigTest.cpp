// Typos get hints: an unknown key names the closest key its level knows when
// one is a likely typo of it, a key of another sensor type says whose it is,
// and a misspelt required key is reported as the typo, not as missing. The
// location (file:line:col, key path) stays the one of the key as written.

#include <gtest/gtest.h>

#include <fstream>

#include "KeyHint.h"
#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

namespace tofsim::config {
namespace {

class KeyHintConfigTest : public test::TempDirTest {
 protected:
  std::string errorOf(const std::string& yaml) {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    const auto path = dir_ / "test.yaml";
    std::ofstream(path) << yaml;
    try {
      loadRunConfig(path);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no error for:\n" << yaml;
    return "";
  }
};

const char* kCamera = R"(camera:
  position: [0, 0, 2]
  look_at: [0, 0, 0]
  resolution: [8, 6]
)";
const char* kRest = R"(light:
  type: point
  position: [0, 1, 2]
  intensity: [1, 1, 1]
time:
  start: 1 ns
  bin_width: 10 ps
  bins: 100
)";

std::string withCamera(const std::string& cameraKey) {
  std::string camera = kCamera;
  camera.replace(0, 6, cameraKey);
  return "scene: scene.gltf\n" + camera + kRest;
}

TEST(KeyHint, DistanceCountsSwapsAsOneEdit) {
  EXPECT_EQ(keyEditDistance("widht", "width"), 1u);
  EXPECT_EQ(keyEditDistance("camra", "camera"), 1u);
  EXPECT_EQ(keyEditDistance("", "abc"), 3u);
  EXPECT_EQ(closestKey("bin_widht", {"bins", "bin_width", "start"}), "bin_width");
  // Far from every key: no guess rather than a wrong one.
  EXPECT_EQ(closestKey("colour", {"bins", "bin_width", "start"}), "");
  EXPECT_EQ(closestKey("ab", {"bc"}), "");
}

TEST_F(KeyHintConfigTest, MisspeltRequiredKeyIsTheTypoNotAMissingKey) {
  const std::string e = errorOf(withCamera("camra"));
  EXPECT_NE(e.find("test.yaml:2:1: camra: unknown key (did you mean 'camera'?)"), std::string::npos)
      << e;
}

TEST_F(KeyHintConfigTest, NestedTypoNamesTheKeyOfItsLevel) {
  std::string yaml = "scene: scene.gltf\n" + std::string(kCamera) + kRest;
  yaml.replace(yaml.find("bins: 100"), 9, "bins: 100\n  bin_widht: 5 ps");
  const std::string e = errorOf(yaml);
  EXPECT_NE(e.find("test.yaml:14:3: time.bin_widht: unknown key (did you mean 'bin_width'?)"),
            std::string::npos)
      << e;
}

TEST_F(KeyHintConfigTest, FarFromEveryKeyGetsNoGuess) {
  const std::string e =
      errorOf("scene: scene.gltf\n" + std::string(kCamera) + kRest + "wavelength: 850 nm\n");
  EXPECT_NE(e.find("wavelength: unknown key"), std::string::npos) << e;
  EXPECT_EQ(e.find("did you mean"), std::string::npos) << e;
}

TEST_F(KeyHintConfigTest, KeyOfAnotherSensorTypeSaysWhose) {
  const std::string base = "scene: scene.gltf\n" + std::string(kCamera) + kRest;
  const std::string e = errorOf(base + "sensors:\n  - type: spad\n    frequencies: [20 MHz]\n");
  EXPECT_NE(e.find("test.yaml:16:5: sensors[0].frequencies: unknown key: 'frequencies' is a "
                   "cwtof key; this sensor is a spad"),
            std::string::npos)
      << e;
  // A typo inside a sensor still gets its guess from the sensor's own keys.
  const std::string typo = errorOf(base + "sensors:\n  - type: spad\n    cylces: 10\n");
  EXPECT_NE(typo.find("sensors[0].cylces: unknown key (did you mean 'cycles'?)"), std::string::npos)
      << typo;
}

}  // namespace
}  // namespace tofsim::config
