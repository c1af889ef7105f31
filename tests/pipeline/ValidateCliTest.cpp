// `tofsim validate` runs every check `render` makes before rendering, by the
// same functions on the same scene (issue 44, item 5): a relay wall that is
// not in the scene, a laser behind the wall, a solid as the wall ("not
// planar"), a channel_weights of the wrong length (located at its line, for
// a camera's R, G, B and an NLOS capture's one channel); render refuses each
// with the same message and writes nothing. And validate's advice for a
// camera inside the scene's box starts the axis at 0, not before it (item
// 11). No GL: nothing renders.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "pipeline/CliRun.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;

const std::string kScenes = std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/";

class ValidateCliTest : public test::TempDirTest {
 protected:
  std::string write(const std::string& text) {
    const fs::path path = dir_ / "c.yaml";
    std::ofstream(path) << text;
    return path.string();
  }
  // validate must fail with `words` at `where` (file:line: key); render the
  // same, leaving no output folder.
  void expectRefusedBoth(const std::string& config, const std::string& where,
                         const std::string& words) {
    const std::string path = write(config);
    const test::CommandResult v = test::runCli("validate " + path);
    EXPECT_EQ(v.exitCode, 1) << v.output;
    EXPECT_NE(v.output.find(path + ":" + where), std::string::npos) << where << "\n" << v.output;
    EXPECT_NE(v.output.find(words), std::string::npos) << words << "\n" << v.output;
    const fs::path out = dir_ / "out";
    const test::CommandResult r = test::runCli("render " + path + " -q -o " + out.string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(words), std::string::npos) << words << "\n" << r.output;
    EXPECT_FALSE(fs::exists(out)) << r.output;
  }
};

// configs/nlos_single.yaml, small; `wall` and `laser` replace its lines.
std::string nlos(const std::string& wall = "relay_wall: wall",
                 const std::string& laser = "laser_origin: [-0.5, 0, 0.25]",
                 const std::string& scene = "nlos_letter.gltf", const std::string& extra = "") {
  return "scene: " + kScenes + scene +
         "\n"
         "nlos:\n"
         "  " +
         wall +
         "\n"
         "  scan: single\n"
         "  laser_point: [0.5, 0.5]\n"
         "  sensor_grid: [4, 4]\n"
         "  sensor_origin: [-0.5, 0, 0.25]\n"
         "  " +
         laser +
         "\n"
         "time: {start: 0 m, bin_width: 1 cm, bins: 64}\n"
         "render: {backend: cpu}\n" +
         extra;
}

TEST_F(ValidateCliTest, ARelayWallTheSceneDoesNotHaveIsRefused) {
  expectRefusedBoth(nlos("relay_wall: nowall"), "3:15: nlos.relay_wall",
                    "no node or mesh named 'nowall'");
}

TEST_F(ValidateCliTest, ALaserBehindTheWallIsRefused) {
  expectRefusedBoth(nlos("relay_wall: wall", "laser_origin: [0, 0, -1]"), "8:17: nlos.laser_origin",
                    "lies behind (or on) relay wall 'wall'");
}

TEST_F(ValidateCliTest, ASolidAsTheWallIsNotPlanar) {
  // The Cornell box's short block: a closed box of 12 triangles, whose
  // area-weighted normals cancel (it used to say "has no area").
  expectRefusedBoth(
      nlos("relay_wall: short_block", "laser_origin: [0.3, 0.3, 1]", "cornell_box.gltf"),
      "3:15: nlos.relay_wall", "relay wall 'short_block' is not planar");
}

TEST_F(ValidateCliTest, ChannelWeightsOfTheWrongLengthAreLocated) {
  const std::string camera =
      "scene: " + kScenes +
      "corner.gltf\n"
      "camera: {position: [0, 0, 1], look_at: [0, 0, 0], resolution: [8, 8]}\n"
      "light: {type: point, position: [0, 0, 1]}\n"
      "time: {bin_width: 50 ps, bins: 400}\n"
      "render: {backend: cpu}\n"
      "sensors:\n"
      "  - type: spad\n"
      "    cycles: 100\n"
      "    channel_weights: [1, 1]\n";
  expectRefusedBoth(camera, "9:22: sensors[0].channel_weights",
                    "has 2 weights but the volume has 3 channels");
  // An NLOS capture's sensors see H, one channel.
  expectRefusedBoth(
      nlos("relay_wall: wall", "laser_origin: [-0.5, 0, 0.25]", "nlos_letter.gltf",
           "sensors:\n  - type: spad\n    cycles: 100\n    channel_weights: [1, 1, 1]\n"),
      "14:22: sensors[0].channel_weights", "has 3 weights but the volume has 1 channels");
}

TEST_F(ValidateCliTest, ACameraInsideTheBoxIsAdvisedToStartAtZero) {
  // The camera and light in the Cornell box's middle: light arrives from 0
  // on. A start of 1.01 ns on 0.1 ns bins used to be advised back to
  // -0.09 ns (the bin grid's step below 0).
  const std::string path =
      write("scene: " + kScenes +
            "cornell_box.gltf\n"
            "camera: {position: [0.278, 0.274, 0.28], look_at: [0.278, 0.274, 0], "
            "resolution: [8, 8]}\n"
            "light: {type: point, position: [0.278, 0.274, 0.28]}\n"
            "time: {start: 1.01 ns, bin_width: 100 ps, bins: 100}\n"
            "render: {backend: cpu}\n");
  const test::CommandResult v = test::runCli("validate " + path);
  ASSERT_EQ(v.exitCode, 0) << v.output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(v.output, m, std::regex("time\\.start: (-?[0-9.e+-]+) ns")))
      << v.output;
  EXPECT_EQ(std::stod(m[1]), 0.0) << v.output;
  EXPECT_NE(v.output.find("arrives within 0 ns"), std::string::npos) << v.output;
}

}  // namespace
}  // namespace tofsim
