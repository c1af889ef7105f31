// `tofsim render` of an nlos config through the pipeline: the files it writes
// (H.npy, H.json, the grids, capture.hdf5 in y-tal's layout) agree with each
// other and with the render, and bad input stops the run before anything is
// written.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/io/Npy.h"
#include "tofsim/io/TalCapture.h"
#include "tofsim/pipeline/RenderRun.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {
namespace {

const std::filesystem::path kConfigs = std::filesystem::path(TOFSIM_SOURCE_DIR) / "configs";

// The example scene (a letter T and a patch behind a 1 m wall), a small scan.
std::string smallScan(const std::string& scan, const std::string& extra = "") {
  return "scene: scenes/nlos_letter.gltf\n"
         "nlos:\n"
         "  relay_wall: wall\n"
         "  scan: " +
         scan +
         "\n"
         "  sensor_grid: [6, 5]\n"
         "  sensor_origin: [-0.5, 0, 0.25]\n"
         "  laser_origin: [-0.4, 0.1, 0.25]\n" +
         extra +
         "time: {start: 0.5 m, bin_width: 2 cm, bins: 128}\n"
         "render: {indirect: {rsm_resolution: 32, visibility: exact}}\n";
}

class NlosRunTest : public test::TempDirTest {
 protected:
  RunSummary run(const std::string& yaml) {
    const config::RunConfig c = config::loadRunConfigText(yaml, kConfigs / "test_nlos.yaml");
    RunOptions options;
    options.outputDirectory = dir_ / "out";
    options.quiet = true;
    return runRender(c, options);
  }
};

TEST_F(NlosRunTest, TheHdf5HoldsWhatTheNpyFilesAndTheJsonSay) {
  const RunSummary s = run(smallScan("exhaustive", "  laser_grid: [2, 3]\n"));
  const std::filesystem::path out = dir_ / "out";
  for (const char* f :
       {"H.npy", "H.json", "sensor_grid_xyz.npy", "laser_grid_xyz.npy", "capture.hdf5",
        "config.effective.yaml", "H_steady.png", "H_xt.png", "H_yt.png"}) {
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  }
  const io::NpyArray h = io::readNpy(out / "H.npy");
  EXPECT_EQ(h.shape, (std::vector<std::size_t>{128, 2, 3, 6, 5}));
  const io::TalCapture tal = io::readTalCapture(out / "capture.hdf5");
  EXPECT_EQ(tal.H_shape, h.shape);
  EXPECT_EQ(tal.H, h.data);
  EXPECT_EQ(tal.H_format, io::TalHFormat::T_Lx_Ly_Sx_Sy);
  double energy = 0.0;
  for (float v : h.data) energy += v;
  EXPECT_GT(energy, 0.0);
  EXPECT_NEAR(tal.delta_t_m, 0.02, 1e-12);
  EXPECT_NEAR(tal.t_start_m, 0.5, 1e-12);
  EXPECT_FALSE(tal.t_accounts_first_and_last_bounces);
  EXPECT_EQ(tal.sensor_grid.shape, (std::vector<std::size_t>{6, 5, 3}));
  EXPECT_EQ(tal.laser_grid.shape, (std::vector<std::size_t>{2, 3, 3}));
  EXPECT_EQ(tal.sensor_grid.xyz, io::readNpy(out / "sensor_grid_xyz.npy").data);
  EXPECT_EQ(tal.laser_grid.xyz, io::readNpy(out / "laser_grid_xyz.npy").data);
  // tal's grid: a 1 m wall at z = 0 sampled at cell centres, x index major.
  EXPECT_FLOAT_EQ(tal.sensor_grid.xyz[0], -0.5f + 0.5f / 6.0f);
  EXPECT_FLOAT_EQ(tal.sensor_grid.xyz[1], -0.5f + 0.5f / 5.0f);
  EXPECT_FLOAT_EQ(tal.sensor_grid.xyz[3 * 1 + 1], -0.5f + 1.5f / 5.0f);  // (0, 1): y steps first
  EXPECT_EQ(tal.sensor_grid.normals[2], 1.0f);
  EXPECT_EQ(tal.sensor_xyz, (std::array<float, 3>{-0.5f, 0.0f, 0.25f}));
  EXPECT_EQ(tal.laser_xyz, (std::array<float, 3>{-0.4f, 0.1f, 0.25f}));
  EXPECT_NE(tal.scene_info_yaml.find("tofsim_version"), std::string::npos);
  EXPECT_NE(tal.scene_info_yaml.find("relay_wall: wall"), std::string::npos);
  nlohmann::json j;
  std::ifstream(out / "H.json") >> j;
  EXPECT_EQ(j["axes"], (nlohmann::json{"t", "lx", "ly", "sx", "sy"}));
  EXPECT_EQ(j["scan"], "exhaustive");
  EXPECT_EQ(j["stats"]["captures"], 6);
  EXPECT_NEAR(j["delta_t_m"].get<double>(), 0.02, 1e-12);
  EXPECT_EQ(s.files.size(), 10u);  // with the three pictures
}

TEST_F(NlosRunTest, ConfocalFileIsConfocalAndHdf5CanBeLeftOut) {
  run(smallScan("confocal", "  hdf5: false\n"));
  const std::filesystem::path out = dir_ / "out";
  EXPECT_FALSE(std::filesystem::exists(out / "capture.hdf5"));
  EXPECT_EQ(io::readNpy(out / "H.npy").shape, (std::vector<std::size_t>{128, 6, 5}));
  EXPECT_EQ(io::readNpy(out / "laser_grid_xyz.npy").data,
            io::readNpy(out / "sensor_grid_xyz.npy").data);
}

// A SPAD per sensor point sees H plus the laser spot's first bounce (at path
// 0 in a confocal scan); gated after it, it counts nothing there and the
// hidden light instead; its counts come back as a y-tal file on its TDC axis.
TEST_F(NlosRunTest, AGatedSpadKeepsTheFirstBounceOutAndWritesItsNoisyH) {
  const std::string spad =
      "sensors:\n"
      "  - {type: spad, name: open, cycles: 20000, pde: 0.5, source_scale: 1}\n"
      "  - {type: spad, name: gated, cycles: 20000, pde: 0.5, source_scale: 1,\n"
      "     gate_start: 0.9 m, gate_width: 2 m}\n";
  std::string yaml = smallScan("confocal") + spad;
  yaml.replace(yaml.find("start: 0.5 m"), 12, "start: 0 m");  // the spot's return at path 0
  run(yaml);
  const std::filesystem::path out = dir_ / "out";
  const io::NpyArray first = io::readNpy(out / "first_bounce.npy");
  const io::NpyArray h = io::readNpy(out / "H.npy");
  ASSERT_EQ(first.shape, h.shape);
  // The first bounce: bin 0 of every point holds the spot's return, nothing after it.
  const std::size_t points = 30;
  for (std::size_t p = 0; p < points; ++p) {
    EXPECT_GT(first.data[0 * points + p], 1.0f) << p;
    for (std::size_t t = 1; t < 128; ++t) ASSERT_EQ(first.data[t * points + p], 0.0f);
  }
  const io::NpyArray open = io::readNpy(out / "sensors/open/spad_counts.npy");
  const io::NpyArray gated = io::readNpy(out / "sensors/gated/spad_counts.npy");
  ASSERT_EQ(open.shape, (std::vector<std::size_t>{6, 5, 128}));
  double openFirst = 0.0, gatedBefore = 0.0, openHidden = 0.0, gatedHidden = 0.0;
  for (std::size_t p = 0; p < points; ++p) {
    openFirst += open.data[p * 128];
    for (std::size_t t = 0; t < 128; ++t) {
      const bool beforeGate = 0.02 * (t + 1) <= 0.9;
      if (beforeGate) gatedBefore += gated.data[p * 128 + t];
      if (t >= 50) {  // the letter, 0.5 m behind the wall, from 1 m of path
        openHidden += open.data[p * 128 + t];
        gatedHidden += gated.data[p * 128 + t];
      }
    }
  }
  EXPECT_GT(openFirst, 0.9 * 20000 * points);  // the first bounce takes almost every cycle
  EXPECT_EQ(gatedBefore, 0.0);
  EXPECT_GT(gatedHidden, 10.0 * openHidden + 100.0);  // the hidden light, no longer blinded
  const io::TalCapture noisy = io::readTalCapture(out / "sensors/gated/capture.hdf5");
  EXPECT_EQ(noisy.H_shape, (std::vector<std::size_t>{128, 6, 5}));
  EXPECT_NEAR(noisy.delta_t_m, 0.02, 1e-9);
  EXPECT_NEAR(noisy.t_start_m, 0.0, 1e-9);
  EXPECT_EQ(noisy.H[60 * points + 7], gated.data[7 * 128 + 60]);  // (t, point) <- (point, t)
}

// Each bad input fails with the config's file, line and key, and leaves no
// output folder behind.
TEST_F(NlosRunTest, BadInputIsALocatedErrorAndWritesNothing) {
  const struct {
    std::string yaml;
    std::string expected;
  } cases[] = {
      {smallScan("confocal", "  relay_wall: ghost\n"), "nlos.relay_wall"},
      {smallScan("confocal", "  laser_origin: [0, 0, -1]\n"), "nlos.laser_origin"},
      {smallScan("confocal", "  sensor_grid: [0, 4]\n"), "nlos.sensor_grid"},
      {smallScan("confocal", "  laser_grid: [2, 2]\n"), "nlos.laser_grid"},
      {smallScan("single", "  laser_point: [1.5, 0.5]\n"), "nlos.laser_point"},
      {smallScan("sideways"), "nlos.scan"},
      {smallScan("confocal") + "camera: {}\n", "camera"},
      {smallScan("confocal") + "output: {video: true}\n", "output.video"},
      {smallScan("confocal") + "sensors: [{type: spad, gate_start: 50 ns, gate_width: 1 ns}]\n",
       "sensors[0].gate_start"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.expected);
    try {
      // Duplicate keys are YAML errors; the later key must replace the earlier
      // one, so drop the default line the case overrides.
      std::string yaml = c.yaml;
      for (const char* key : {"relay_wall", "laser_origin", "sensor_grid"}) {
        const std::string line = std::string("  ") + key + ":";
        const std::size_t first = yaml.find(line), last = yaml.rfind(line);
        if (first != last) yaml.erase(first, yaml.find('\n', first) - first + 1);
      }
      run(yaml);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(c.expected), std::string::npos) << what;
      EXPECT_NE(what.find("test_nlos.yaml:"), std::string::npos) << what;  // file:line
    }
    EXPECT_FALSE(std::filesystem::exists(dir_ / "out" / "H.npy"));
  }
}

// A capture whose files would not fit output.max_bytes fails before
// rendering, naming the key and the files, and the earlier results stay.
TEST_F(NlosRunTest, OutputsOverMaxBytesFailBeforeRenderingAndLeaveEarlierResults) {
  const std::string limit = "output: {max_bytes: 100 KiB}\n";
  run(smallScan("confocal") + limit);  // H: 128 x 6 x 5 x 4 B = 15 KiB, three files fit
  std::string larger = smallScan("confocal") + limit;
  larger.replace(larger.find("[6, 5]"), 6, "[60, 5]");  // ten times that do not
  try {
    run(larger);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("output.max_bytes"), std::string::npos) << what;
    EXPECT_NE(what.find("H.npy"), std::string::npos) << what;
  }
  EXPECT_EQ(io::readNpy(dir_ / "out" / "sensor_grid_xyz.npy").shape,
            (std::vector<std::size_t>{6, 5, 3}));
}

// A scan whose H does not fit render.memory_budget fails before the scene
// loads, naming the budget and the keys that set H's size (not the camera's:
// an NLOS config has no camera.resolution), and writes nothing. (It ran, and
// at 4096 x 4096 points ran out of memory or for an hour.)
TEST_F(NlosRunTest, ScansOverTheMemoryBudgetFailBeforeRendering) {
  // H: 2048 bins x 2 x 1 x 6 x 5 points x 4 B = 480 KiB, twice (with
  // first_bounce), and one laser position's light for all 30 sensor points:
  // 2.3 MiB, over the smallest budget.
  std::string yaml = smallScan("exhaustive", "  laser_grid: [2, 1]\n");
  yaml.replace(yaml.find("bins: 128"), 9, "bins: 2048");
  yaml.replace(yaml.find("render: {"), 9, "render: {memory_budget: 1 MiB, ");
  try {
    run(yaml);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    for (const char* words :
         {"test_nlos.yaml: render.memory_budget: the NLOS scan holds about 2.3 MiB",
          "time.bins x nlos.laser_grid x nlos.sensor_grid", "over render.memory_budget (1.0 MiB)"}) {
      EXPECT_NE(what.find(words), std::string::npos) << words << "\n" << what;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out"));
}

// A wall whose triangles all lost their area (scaled flat along x) is
// dropped when the scene loads; the error says so, at nlos.relay_wall,
// instead of calling the node missing.
TEST_F(NlosRunTest, AWallWithoutAreaIsReportedAsSuch) {
  std::ifstream in(kConfigs / "scenes" / "nlos_letter.gltf");
  nlohmann::json gltf = nlohmann::json::parse(in);
  ASSERT_EQ(gltf["nodes"][0]["name"], "wall");
  gltf["nodes"][0]["scale"] = {0.0, 1.0, 1.0};
  std::ofstream(dir_ / "flat_wall.gltf") << gltf.dump();
  std::string yaml = smallScan("confocal");
  yaml.replace(0, yaml.find('\n'), "scene: " + (dir_ / "flat_wall.gltf").string());
  try {
    run(yaml);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("test_nlos.yaml:3:"), std::string::npos) << what;
    EXPECT_NE(what.find("nlos.relay_wall: relay wall 'wall' has no area"), std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace tofsim::pipeline
