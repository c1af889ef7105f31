// Issue 41's materials through the CLI (no GL: nothing renders): bad
// delays in the config or in the glTF's extras, an unknown material and a
// table of too many response classes end `validate` and `render` with a
// located error, exit 1 and nothing written; `validate`'s suggested time
// axis holds a 3.5 ns lifetime's tail that the same axis without the delay
// does not need; configs/flim_spad.yaml validates.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "pipeline/CliRefusal.h"
#include "pipeline/CliRun.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;

const std::string kSlide = std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/flim_slide.gltf";

class MaterialsCliTest : public test::TempDirTest {
 protected:
  // The slide seen from 0.2 m, 250 bins of 50 ps (12.5 ns), direct light
  // only, then `extra` (materials:, render:).
  std::string writeConfig(const std::string& extra, const std::string& scene = kSlide) {
    const fs::path path = dir_ / "c.yaml";
    std::ofstream(path) << "scene: " << scene
                        << "\ncamera: {gltf_camera: flim_camera, resolution: [8, 8]}\n"
                           "light: {type: point, position: [0, 0, 0.2]}\n"
                           "time: {bin_width: 50 ps, bins: 250}\n"
                        << extra;
    return path.string();
  }
  test::CommandResult validate(const std::string& extra) {
    return test::runCli("validate " + writeConfig(extra));
  }
};

const char* kNoIndirect = "render: {backend: cpu, indirect: {enabled: false}}\n";
const char* kDyeLong =
    "materials:\n  dye_long:\n    scattering_delay: {model: exponential, "
    "lifetime: 3.5 ns}\n";

// The bins of "time.bins: N would hold it all", 0 when there is no such advice.
int suggestedBins(const std::string& output) {
  std::smatch m;
  if (!std::regex_search(output, m, std::regex("time\\.bins: ([0-9]+) would hold it all")))
    return 0;
  return std::stoi(m[1]);
}

TEST_F(MaterialsCliTest, ValidatesSuggestedAxisHoldsTheLifetimesTail) {
  // The slide's extras give dye_long its 3.5 ns; `none` drops it: the axis
  // holds every path (no advice).
  const test::CommandResult plain =
      validate(std::string(kNoIndirect) + "materials:\n  dye_long: {scattering_delay: none}\n");
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_EQ(suggestedBins(plain.output), 0) << plain.output;
  // With it, one delayed vertex: the tail to 0.1 % is 3.5 ns ln(1000) =
  // 24.2 ns past the longest path (which the plain axis held).
  const test::CommandResult delayed = validate(std::string(kNoIndirect) + kDyeLong);
  ASSERT_EQ(delayed.exitCode, 0) << delayed.output;
  const int bins = suggestedBins(delayed.output);
  EXPECT_GE(bins * 50e-12, 3.5e-9 * std::log(1000.0)) << delayed.output;
  EXPECT_LT(bins * 50e-12, 3.5e-9 * std::log(1000.0) + 3e-9) << delayed.output;
  EXPECT_NE(delayed.output.find("its materials' delays"), std::string::npos) << delayed.output;
  // Two delayed vertices per path (one bounce): each at 0.05 %, twice.
  const test::CommandResult bounce =
      validate("render: {backend: cpu, indirect: {bounces: 1}}\n" + std::string(kDyeLong));
  ASSERT_EQ(bounce.exitCode, 0) << bounce.output;
  EXPECT_GE(suggestedBins(bounce.output) * 50e-12, 2 * 3.5e-9 * std::log(2000.0)) << bounce.output;
}

TEST_F(MaterialsCliTest, BadDelaysExitOneAndWriteNothing) {
  struct Case {
    std::string extra;
    std::string message;
  };
  for (const Case& c : {
           Case{"materials:\n  dye_long:\n    scattering_delay: {model: exponential, "
                "lifetime: -1 ns}\n",
                "c.yaml:7:"},
           Case{"materials:\n  dye_lng:\n    scattering_delay: {model: exponential, "
                "lifetime: 1 ns}\n",
                "its materials: background, dye_short, dye_long"},
           // 3 distinct kernels on paths of 7 delayed vertices: 120 classes.
           Case{"render: {backend: cpu, indirect: {bounces: 6}}\nmaterials:\n"
                "  dye_short: {scattering_delay: {model: exponential, lifetime: 1 ns}}\n"
                "  background: {scattering_delay: {model: gaussian, mean: 0 s, sigma: 20 ps}}\n",
                "render.indirect.bounces"},
       }) {
    SCOPED_TRACE(c.extra);
    test::expectValidateAndRenderRefuse(writeConfig(c.extra), dir_ / "out", c.message);
  }
}

TEST_F(MaterialsCliTest, BadExtrasNameTheGltfAndTheMaterial) {
  std::ifstream in(kSlide);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = text.find("\"3.5 ns\"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 8, "\"-3.5 ns\"");
  std::ofstream(dir_ / "slide.gltf") << text;
  const test::CommandResult v =
      test::runCli("validate " + writeConfig(kNoIndirect, (dir_ / "slide.gltf").string()));
  EXPECT_EQ(v.exitCode, 1) << v.output;
  EXPECT_NE(v.output.find("slide.gltf: materials[2] 'dye_long'.extras.scattering_delay.lifetime: "
                          "must be > 0"),
            std::string::npos)
      << v.output;
}

TEST_F(MaterialsCliTest, TheFlimExampleValidates) {
  const test::CommandResult v =
      test::runCli("validate " + std::string(TOFSIM_SOURCE_DIR) + "/configs/flim_spad.yaml");
  EXPECT_EQ(v.exitCode, 0) << v.output;
}

}  // namespace
}  // namespace tofsim
