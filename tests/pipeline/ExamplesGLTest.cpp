// The shipped examples are right: rendered at reduced resolution, none loses
// more than 0.5 % of its light to the render's time axis (transient.json) or
// to a sensor's instrument window (which would print a warning past 0.1 %).

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <string>

#include "pipeline/CliRun.h"
#include "pipeline/StatsJson.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

const std::string kConfigs = std::string(TOFSIM_SOURCE_DIR) + "/configs/";
// Small and fast; the light's arrival times depend on the scene, not on these.
const std::string kSmall =
    " --set render.shadow_map_resolution=256 --set render.indirect.rsm_resolution=8"
    " --set render.indirect.points_per_vpl=100 --set render.indirect.ism_resolution=16"
    " --set output.video=false -q";

class ExamplesGLTest : public test::TempDirTest {
 protected:
  void expectHoldsItsLight(const std::filesystem::path& run, const std::string& output) {
    EXPECT_LE(test::offAxisFraction(run / "transient.json"), 0.005) << run;
    EXPECT_EQ(output.find("instrument window drops"), std::string::npos) << output;
    EXPECT_EQ(output.find("of the light arrives"), std::string::npos) << output;
  }
};

TEST_F(ExamplesGLTest, EveryExampleKeepsItsLightOnTheAxes) {
  // Rows and pixels the sensors name must lie in the 16 x 16 image.
  const std::vector<std::pair<std::string, std::string>> examples = {
      {"cornell_box", " --set sensors.0.plot_pixels=[[8,8]] --set sensors.1.rows=[8]"},
      {"spad_lidar", " --set sensors.0.plot_pixels=[[8,8]]"},
      {"streak_femto", " --set sensors.0.rows=[8]"},
      {"cwtof_corner", ""},
      {"glossy_floor", ""},
      {"fog_lidar", " --set sensors.0.plot_pixels=[[8,8]] --set sensors.1.plot_pixels=[[8,8]]"},
      // The lens's matrix scaled to the small image; the volume written so
      // transient.json counts the light (the PSF then on every bin).
      {"kinect_v2",
       " --set output.transient=true"
       " --set camera.lens.camera_matrix=[11.42,0,7.5,0,11.42,7.5,0,0,1]"},
  };
  for (const auto& [name, sets] : examples) {
    const std::filesystem::path out = dir_ / name;
    const test::CommandResult r =
        test::runCli("render " + kConfigs + name + ".yaml -o " + out.string() +
                     " --set camera.resolution=[16,16]" + kSmall + sets);
    ASSERT_EQ(r.exitCode, 0) << name << "\n" << r.output;
    expectHoldsItsLight(out, r.output);
  }
}

// The glossy-floor example (renderer: ir, render.materials: gltf, two
// bounces, multipath_by_order) validates strictly: no proven cut of its light
// by the time axis. It writes the error of each bounce order (0..2), and
// renders with the reference too once the per-order split, which the
// reference's 3 interactions cannot give, is turned off.
TEST_F(ExamplesGLTest, GlossyFloorValidatesAndRendersItsBounceOrders) {
  const std::string config = kConfigs + "glossy_floor.yaml";
  const test::CommandResult r = test::runCli("validate " + config + " --strict");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  const test::CommandResult typo =
      test::runCli("validate " + config + " --set render.reference.sampling=vndf");
  EXPECT_NE(typo.exitCode, 0) << typo.output;

  const test::CommandResult ir = test::runCli("render " + config + " -o " + (dir_ / "ir").string() +
                                              " --set camera.resolution=[16,16]" + kSmall);
  ASSERT_EQ(ir.exitCode, 0) << ir.output;
  for (int k = 0; k <= 2; ++k) {
    const std::string name = "cwtof_multipath_error_order" + std::to_string(k) + ".png";
    EXPECT_TRUE(std::filesystem::exists(dir_ / "ir/sensors/cwtof" / name)) << name;
  }
  EXPECT_TRUE(
      std::filesystem::exists(dir_ / "ir/sensors/cwtof/cwtof_multipath_error_by_order.npy"));

  const std::string reference =
      "render " + config + " --renderer reference" + " --set camera.resolution=[16,16] -q" +
      " --set render.reference.samples_per_pixel=8 -o " + (dir_ / "reference").string();
  const test::CommandResult refused = test::runCli(reference);
  EXPECT_NE(refused.exitCode, 0) << refused.output;
  EXPECT_NE(refused.output.find("multipath_by_order"), std::string::npos) << refused.output;
  const test::CommandResult ref =
      test::runCli(reference + " --set sensors.0.multipath_by_order=false");
  ASSERT_EQ(ref.exitCode, 0) << ref.output;
  expectHoldsItsLight(dir_ / "reference", ref.output);
}

TEST_F(ExamplesGLTest, EverySweepRunKeepsItsLightOnTheAxes) {
  // sweep.yaml with its paths made absolute and its output in the test's folder.
  std::string batch = test::fileBytes(kConfigs + "sweep.yaml");
  batch = std::regex_replace(batch, std::regex("\nbase: [^\n]*"),
                             "\nbase: " + kConfigs + "cornell_box.yaml");
  batch = std::regex_replace(batch, std::regex("\noutput: [^\n]*"),
                             "\noutput: " + (dir_ / "sweep").string());
  std::ofstream(dir_ / "sweep.yaml") << batch;
  // 32 x 32 keeps the sweep's row 24 and pixel (24, 24) in the image.
  const test::CommandResult r = test::runCli("batch " + (dir_ / "sweep.yaml").string() +
                                             " --jobs 2 --set camera.resolution=[32,32]" + kSmall);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::size_t runs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir_ / "sweep")) {
    if (!std::filesystem::exists(entry.path() / "transient.json")) continue;
    ++runs;
    expectHoldsItsLight(entry.path(), r.output);
  }
  EXPECT_EQ(runs, 8u);
}

}  // namespace
}  // namespace tofsim
