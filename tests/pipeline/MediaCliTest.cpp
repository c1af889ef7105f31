// Issue 42's per-region media (`media:`) through the CLI (no GL): bad
// regions and coefficients end `validate` and `render` with a located error
// (file:line, the key), exit 1 and nothing written (on GL also a scattering
// region, and regions of more triangles than its shaders take); a good entry
// renders on the CPU backend (absorbing and scattering regions; a scattering
// one not with the camera leg untimed), and configs/water_tank.yaml validates.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "pipeline/CliRefusal.h"
#include "pipeline/CliRun.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;

const std::string kTank = std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/water_tank.gltf";

class MediaCliTest : public test::TempDirTest {
 protected:
  // The tank seen by its camera at 8 x 8, direct light only, on the CPU
  // backend; `media` at line 6.
  std::string writeConfig(const std::string& media, const std::string& backend = "cpu",
                          const std::string& timeExtra = "",
                          const std::string& indirect = "{enabled: false}") {
    const fs::path path = dir_ / "c.yaml";
    std::ofstream(path) << "scene: " << kTank
                        << "\ncamera: {gltf_camera: lidar_camera, resolution: [8, 8]}\n"
                           "light: {type: point, position: [0, 0.35, 0.8]}\n"
                           "time: {start: 2 m, bin_width: 5 cm, bins: 100"
                        << timeExtra << "}\nrender: {indirect: " << indirect
                        << ", backend: " << backend << "}\nmedia:\n"
                        << media;
    return path.string();
  }
};

TEST_F(MediaCliTest, BadRegionsAndCoefficientsExitOneAndWriteNothing) {
  struct Case {
    std::string media;
    std::string line;  ///< where: "c.yaml:LINE:"
    std::string message;
  };
  for (const Case& c : {
           Case{"  - {region: no_such_mesh, sigma_a: 0.1}\n", "c.yaml:7:",
                "region: the scene (" + kTank + ") has no mesh or node named 'no_such_mesh'"},
           Case{"  - {region: floor, sigma_a: 0.1}\n", "c.yaml:7:",
                "region: the mesh 'floor' is not closed: an edge has one triangle"},
           Case{"  - {region: water_tank, sigma_a: -0.1}\n", "c.yaml:7:", "must be >= 0"},
           Case{"  - {region: water_tank, sigma_a: 0.1, index_of_refraction: 0.5}\n", "c.yaml:7:",
                "index_of_refraction: must be >= 1"},
           Case{"  - {region: water_tank, sigma_a: 0.1}\n  - {region: water_tank, sigma_a: 1}\n",
                "c.yaml:8:", "region: names 'water_tank' twice"},
           Case{"  - {region: water_tank, sigma_a: 0.1}\n  - {region: target, sigma_a: 1}\n",
                "c.yaml:8:", "region: the mesh 'target' is not closed"},
           Case{"  - {region: water_tank, sigma_a: 0.1, sigma_b: 1}\n", "c.yaml:7:", "sigma_b"},
       }) {
    SCOPED_TRACE(c.media);
    const test::CommandResult v =
        test::expectValidateAndRenderRefuse(writeConfig(c.media), dir_ / "out", c.message);
    EXPECT_NE(v.output.find(c.line), std::string::npos) << v.output;
  }
}

// A scattering region renders in instant radiosity on the CPU backend, with
// its medium VPLs and a later bounce; with the camera leg untimed (its light
// binned by a path that no longer grows along the ray) it is refused at its
// sigma_s.
TEST_F(MediaCliTest, AScatteringRegionRendersOnTheCpuBackendAndNotUnwarped) {
  const std::string media = "  - {region: water_tank, sigma_a: 0.2, sigma_s: 0.5}\n";
  const test::CommandResult r = test::runCli(
      "render -q " + writeConfig(media, "cpu", "", "{bounces: 2, rsm_resolution: 8, medium_vpls: 64}") +
      " -o " + (dir_ / "out").string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  const test::CommandResult v = test::expectValidateAndRenderRefuse(
      writeConfig(media, "cpu", ", camera_unwarp: true"), dir_ / "unwarped",
      "sigma_s: a scattering region (sigma_s > 0) with time.camera_unwarp is not built");
  EXPECT_NE(v.output.find("c.yaml:7:"), std::string::npos) << v.output;
}

TEST_F(MediaCliTest, GlAndAFilledSceneAreRefusedWithWhatToDo) {
  const std::string media = "  - {region: water_tank, sigma_a: 0.1}\n";
  // An absorbing region is built on GL; a scattering one is not.
  const test::CommandResult gl = test::runCli("validate " + writeConfig(media, "gl"));
  EXPECT_EQ(gl.exitCode, 0) << gl.output;
  const test::CommandResult scattering =
      test::runCli("validate " + writeConfig("  - {region: water_tank, sigma_s: 0.1}\n", "gl"));
  EXPECT_EQ(scattering.exitCode, 1) << scattering.output;
  EXPECT_NE(scattering.output.find("c.yaml:7:"), std::string::npos) << scattering.output;
  EXPECT_NE(scattering.output.find("not built on the GL backend"), std::string::npos)
      << scattering.output;
  EXPECT_NE(scattering.output.find("render.backend: cpu"), std::string::npos) << scattering.output;
  // The tank's 12 triangles are more than GL's shaders take at 16 x 16 pixel
  // samples (render/GlRegionLimits.h): located at the region, the limit said.
  const test::CommandResult large =
      test::runCli("validate " + writeConfig(media, "gl, pixel_samples: 16"));
  EXPECT_EQ(large.exitCode, 1) << large.output;
  EXPECT_NE(large.output.find("c.yaml:7:"), std::string::npos) << large.output;
  EXPECT_NE(large.output.find("media[0].region: the media's regions have 12 triangles with the "
                              "mesh 'water_tank': the GL backend takes at most 0 with "
                              "render.pixel_samples 16"),
            std::string::npos)
      << large.output;
  const test::CommandResult both =
      test::runCli("validate " + writeConfig(media + "medium: {sigma_a: 0.1}\n"));
  EXPECT_EQ(both.exitCode, 1) << both.output;
  EXPECT_NE(both.output.find("c.yaml:7:"), std::string::npos) << both.output;  // media: [...]
  EXPECT_NE(both.output.find("a medium filling the scene (`medium`) and per-region media"),
            std::string::npos)
      << both.output;
}

TEST_F(MediaCliTest, ARegionRendersAndItsEffectiveConfigRendersAgain) {
  const fs::path out = dir_ / "out";
  const test::CommandResult r = test::runCli(
      "render -q " + writeConfig("  - {region: water_tank, sigma_a: [0.3, 0.05, 0.02], "
                                 "index_of_refraction: 1.33}\n") +
      " -o " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string effective = test::fileBytes((out / "config.effective.yaml").string());
  EXPECT_NE(effective.find("region: water_tank"), std::string::npos) << effective;
  EXPECT_NE(effective.find("index_of_refraction: 1.33"), std::string::npos) << effective;
  const test::CommandResult again =
      test::runCli("validate " + (out / "config.effective.yaml").string());
  EXPECT_EQ(again.exitCode, 0) << again.output;
}

TEST_F(MediaCliTest, TheWaterTankConfigValidates) {
  const test::CommandResult v =
      test::runCli("validate " + std::string(TOFSIM_SOURCE_DIR) + "/configs/water_tank.yaml");
  EXPECT_EQ(v.exitCode, 0) << v.output;
}

}  // namespace
}  // namespace tofsim
