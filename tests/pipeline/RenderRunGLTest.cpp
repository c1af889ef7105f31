// End-to-end: `tofsim render` on the shipped Cornell box at a small size
// writes files that load back and agree with each other; bad configs fail
// with a located one-line error and leave no output directory.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "pipeline/CliRun.h"
#include "support/TempDir.h"
#include "tofsim/capture/Vignetting.h"
#include "tofsim/io/DepthExr.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/Capture.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim {
namespace {

using test::CommandResult;

CommandResult run(const std::string& args) { return test::runCli(args); }

const std::string kConfig = test::kCornellConfig;
const std::string kSmall =
    " --set camera.resolution=[24,24] --set time.bins=200 --set render.shadow_map_resolution=256"
    " --set render.indirect.rsm_resolution=8 --set render.indirect.points_per_vpl=200 -q"
    " --set sensors=[]";  // the sensors have their own tests (SenseGLTest.cpp)

class RenderRunGLTest : public test::TempDirTest {};

TEST_F(RenderRunGLTest, TransientSumsToSteadyAndFilesLoad) {
  const CommandResult r = run("render " + kConfig + " -o " + (dir_ / "out").string() + kSmall);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const io::NpyArray transient = io::readNpy(dir_ / "out" / "transient.npy");
  ASSERT_EQ(transient.shape, (io::NpyShape{24, 24, 200, 3}));
  std::vector<std::string> channels;
  const Image steady = io::readExr(dir_ / "out" / "steady.exr", &channels);
  EXPECT_EQ(channels, (std::vector<std::string>{"R", "G", "B"}));
  double total = 0.0;
  for (std::size_t p = 0; p < 24 * 24; ++p) {
    for (int c = 0; c < 3; ++c) {
      double sum = 0.0;
      for (int t = 0; t < 200; ++t) sum += transient.data[(p * 200 + t) * 3 + c];
      EXPECT_NEAR(sum, steady.data[p * 3 + c], 1e-6 * std::abs(sum) + 1e-12);
      total += sum;
    }
  }
  EXPECT_GT(total, 0.0);
  // depth.exr: the metres twice, as Y (OpenCV and image readers) and Z (depth tools).
  const Image depthYZ = io::readExr(dir_ / "out" / "depth.exr", &channels);
  EXPECT_EQ(channels, (std::vector<std::string>{"Y", "Z"}));
  const Image depth = io::readDepthExr(dir_ / "out" / "depth.exr");
  ASSERT_EQ(depth.channels, 1);
  for (std::size_t i = 0; i < depth.data.size(); ++i) {
    ASSERT_EQ(depthYZ.data[2 * i], depth.data[i]);
    ASSERT_EQ(depthYZ.data[2 * i + 1], depth.data[i]);
  }
  // Surfaces lie between the box's open front (0.8 m) and its back corners;
  // only the outermost pixels look past the walls' front edges (depth 0).
  std::size_t seen = 0;
  for (float d : depth.data) {
    if (d == 0.0f) continue;
    ++seen;
    EXPECT_GT(d, 0.79f);
    EXPECT_LT(d, 1.6f);
  }
  EXPECT_GT(seen, depth.data.size() * 8 / 10);
  // depth.npy: the same metres as depth.exr, shape (H, W), for numpy.load.
  const io::NpyArray depthNpy = io::readNpy(dir_ / "out" / "depth.npy");
  EXPECT_EQ(depthNpy.shape, (io::NpyShape{24, 24}));
  EXPECT_EQ(depthNpy.data, depth.data);
  for (const char* f : {"transient.json", "config.effective.yaml", "steady.png", "depth.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir_ / "out" / f)) << f;
  }
  std::ifstream json(dir_ / "out" / "transient.json");
  std::stringstream text;
  text << json.rdbuf();
  EXPECT_NE(text.str().find("\"bin_width_s\""), std::string::npos);
  EXPECT_NE(text.str().find("\"bin_width_m\""), std::string::npos);
}

TEST_F(RenderRunGLTest, EffectiveConfigRecordsTheGltfCameraThatWasUsed) {
  const auto out = dir_ / "out";
  const CommandResult r = run("render " + kConfig + " -o " + out.string() + kSmall);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const config::RunConfig original = config::loadRunConfig(kConfig, {});
  ASSERT_FALSE(original.camera.gltf_camera.empty()) << "the demo uses its glTF camera";
  const scene::Scene scene = scene::loadGltf(original.scene_file);
  const capture::Camera used = pipeline::makeRenderJob(original, scene).camera();
  const capture::Camera recorded =
      config::loadRunConfig(out / "config.effective.yaml", {}).camera.camera;
  EXPECT_NE(original.camera.camera.position_world, used.position_world) << "not the defaults";
  EXPECT_EQ(recorded.position_world, used.position_world);
  EXPECT_EQ(recorded.look_at_world, used.look_at_world);
  EXPECT_EQ(recorded.up_world, used.up_world);
  EXPECT_EQ(recorded.fov_y_deg, used.fov_y_deg);
}

TEST_F(RenderRunGLTest, SameConfigAndSeedGiveTheSameBytes) {
  ASSERT_EQ(run("render " + kConfig + " -o " + (dir_ / "a").string() + kSmall).exitCode, 0);
  ASSERT_EQ(run("render " + kConfig + " -o " + (dir_ / "b").string() + kSmall).exitCode, 0);
  for (const char* f : {"transient.npy", "direct.npy", "indirect.npy"}) {
    std::ifstream a(dir_ / "a" / f, std::ios::binary), b(dir_ / "b" / f, std::ios::binary);
    std::stringstream sa, sb;
    sa << a.rdbuf();
    sb << b.rdbuf();
    EXPECT_TRUE(sa.str() == sb.str()) << f;
    EXPECT_GT(sa.str().size(), 1000u) << f;
  }
}

// A calibrated lens through the CLI (both backends: the GL one gathers the
// traced samples), and cos4 vignetting on top: every volume value is the
// lens render's times its pixel's gain, bit for bit (the bounce files still
// add up), and transient.json records the lens.
TEST_F(RenderRunGLTest, LensAndVignettingReachEveryVolume) {
  const std::string lens =
      " --set camera.lens.camera_matrix=[22,0,11.5,0,22,11.5,0,0,1]"
      " --set camera.lens.distortion=[-0.2,0.03,0,0]";
  for (const char* backend : {"gl", "cpu"}) {
    SCOPED_TRACE(backend);
    const std::string common = kSmall + lens + " --set render.backend=" + backend +
                               " --set render.indirect.bounces=2"
                               " --set output.components=[direct,indirect,bounce1,bounce2]";
    const auto plain = dir_ / (std::string("lens_") + backend);
    const auto vign = dir_ / (std::string("vign_") + backend);
    CommandResult r = run("render " + kConfig + " -o " + plain.string() + common);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = run("render " + kConfig + " -o " + vign.string() + common +
            " --set camera.vignetting=cos4");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const config::RunConfig c = config::loadRunConfig(vign / "config.effective.yaml", {});
    ASSERT_TRUE(c.camera.camera.lens.has_value());
    const scene::Scene scene = scene::loadGltf(c.scene_file);
    const std::vector<float> gains =
        capture::vignettingGains(pipeline::makeRenderJob(c, scene).camera(), c.camera.vignetting);
    ASSERT_EQ(gains.size(), 24u * 24u);
    EXPECT_LT(*std::min_element(gains.begin(), gains.end()), 0.8f);
    for (const char* f : {"direct.npy", "bounce1.npy", "bounce2.npy"}) {
      const io::NpyArray a = io::readNpy(plain / f), b = io::readNpy(vign / f);
      ASSERT_EQ(a.data.size(), b.data.size()) << f;
      const std::size_t perPixel = a.data.size() / gains.size();
      double lit = 0.0;
      for (std::size_t i = 0; i < a.data.size(); ++i) {
        ASSERT_EQ(b.data[i], a.data[i] * gains[i / perPixel]) << f << " value " << i;
        lit += a.data[i];
      }
      EXPECT_GT(lit, 0.0) << f;
    }
    const io::NpyArray indirect = io::readNpy(vign / "indirect.npy");
    const io::NpyArray b1 = io::readNpy(vign / "bounce1.npy"),
                       b2 = io::readNpy(vign / "bounce2.npy");
    for (std::size_t i = 0; i < indirect.data.size(); ++i) {
      ASSERT_EQ(indirect.data[i], b1.data[i] + b2.data[i]) << i;
    }
    std::ifstream json(vign / "transient.json");
    std::stringstream text;
    text << json.rdbuf();
    EXPECT_NE(text.str().find("calibrated lens"), std::string::npos);
    EXPECT_NE(text.str().find("cos^4"), std::string::npos);
  }
}

TEST_F(RenderRunGLTest, BadConfigFailsWithLocatedErrorAndNoOutput) {
  const CommandResult r =
      run("render " + kConfig + " -o " + (dir_ / "bad").string() + " --set time.bin_width=-1ps");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.output.find("time.bin_width"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "bad"));
}

TEST_F(RenderRunGLTest, ValidateChecksWithoutRendering) {
  const CommandResult ok = run("validate " + kConfig);
  EXPECT_EQ(ok.exitCode, 0) << ok.output;
  std::ofstream(dir_ / "typo.yaml") << "scene: " << TOFSIM_SOURCE_DIR
                                    << "/configs/scenes/cornell_box.gltf\ncamera: {}\nlight: {}\n"
                                       "time: {bins: 10}\nrendr: {}\n";
  const CommandResult bad = run("validate " + (dir_ / "typo.yaml").string());
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.output.find("typo.yaml:5:1: rendr: unknown key"), std::string::npos) << bad.output;
}

TEST_F(RenderRunGLTest, VersionAndHelp) {
  EXPECT_EQ(run("--version").exitCode, 0);
  const CommandResult help = run("--help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.output.find("render"), std::string::npos);
  EXPECT_NE(run("render").exitCode, 0);
}

}  // namespace
}  // namespace tofsim
