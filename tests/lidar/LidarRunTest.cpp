// A `lidar:` config through the pipeline and the CLI: the files a run
// writes agree with each other, a SPAD sensor runs on the waveforms (pixels
// = beams), the effective config loads again to the same run; bad input
// (no channels, a zero step, a divergence <= 0, an unknown preset, a raster
// scan with channels, `lidar` beside `camera` or `nlos`, a sequence of a
// still scene or with a camera's video) ends in a located error, exit 1 and
// no output folder; a rolling scan of a moving plate through the config.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "RollingPlate.h"
#include "pipeline/CliRun.h"
#include "support/TempDir.h"
#include "tofsim/config/LidarConfig.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/RenderRun.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;

const std::string kStreet = std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/lidar_street.gltf";

// 4 channels x 36 azimuths over the street, 400 bins of 300 ps (0 .. 18 m).
std::string smallLidar(const std::string& extra = "") {
  return "scene: " + kStreet +
         "\n"
         "lidar:\n"
         "  position: [0, 1.8, 0]\n"
         "  orientation: {look_at: [1, 1.8, 0], up: [0, 1, 0]}\n"
         "  channels: {count: 4, min: -15, max: 0}\n"
         "  azimuth: {start: 0, end: 360, step: 10}\n"
         "  beam_divergence: 3 mrad\n"
         "  returns: {mode: dual, max: 2}\n" +
         extra + "time: {bin_width: 300 ps, bins: 400}\n";
}

struct BadLidar {
  const char* name;
  std::string yaml;
  const char* where;  ///< "file:line" and the key the error names
};

class LidarRunTest : public test::TempDirTest {
 protected:
  fs::path writeConfig(const std::string& yaml) {
    const fs::path path = dir_ / "c.yaml";
    std::ofstream(path) << yaml;
    return path;
  }
  /// Each config through the CLI: exit 1, the error at its line, no output.
  void expectLocatedFailures(const std::vector<BadLidar>& cases) {
    for (const BadLidar& bad : cases) {
      const fs::path config = writeConfig(bad.yaml);
      const test::CommandResult r =
          test::runCli("render " + config.string() + " -o " + (dir_ / "out").string());
      EXPECT_EQ(r.exitCode, 1) << bad.name << ": " << r.output;
      EXPECT_NE(r.output.find("c.yaml" + std::string(bad.where)), std::string::npos)
          << bad.name << ": " << r.output;
      EXPECT_FALSE(fs::exists(dir_ / "out")) << bad.name;
    }
  }
};

TEST_F(LidarRunTest, ARunWritesItsFilesAndASpadCountsItsBeams) {
  const config::RunConfig c = config::loadRunConfig(writeConfig(
      smallLidar() + "sensors:\n  - {type: spad, cycles: 1000, source_scale: 1e5}\n"));
  pipeline::RunOptions options;
  options.outputDirectory = dir_ / "out";
  options.quiet = true;
  pipeline::runRender(c, options);
  const fs::path out = dir_ / "out";
  EXPECT_EQ(io::readNpy(out / "waveforms.npy").shape, (std::vector<std::size_t>{4, 36, 400}));
  const io::NpyArray range = io::readNpy(out / "range.npy");
  EXPECT_EQ(range.shape, (std::vector<std::size_t>{4, 36}));
  for (const char* f : {"range.exr", "range.png", "intensity.npy", "intensity.exr",
                        "intensity.png", "points.pcd", "points.ply", "beam_directions.npy"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  // The lowest ring (-15 deg from 1.8 m) sees the ground at 1.8 / sin 15 deg
  // where nothing stands nearer.
  int ground = 0;
  for (std::size_t a = 0; a < 36; ++a) ground += std::fabs(range.data[a] - 6.955) < 0.05;
  EXPECT_GT(ground, 18);
  const nlohmann::json meta = nlohmann::json::parse(std::ifstream(out / "lidar.json"));
  EXPECT_EQ(meta["stats"]["beams"].get<double>(), 144.0);
  // Dual returns: one or two points per beam that has a return.
  int withReturns = 0;
  for (float r : range.data) withReturns += r > 0.0f;
  EXPECT_EQ(meta["stats"]["beams_with_returns"].get<int>(), withReturns);
  EXPECT_GE(meta["stats"]["points"].get<int>(), withReturns);
  EXPECT_LE(meta["stats"]["points"].get<int>(), 2 * withReturns);
  EXPECT_GT(withReturns, 100);
  const io::NpyArray counts = io::readNpy(out / "sensors/spad/spad_counts.npy");
  ASSERT_EQ(counts.shape.size(), 3u);
  EXPECT_EQ(counts.shape[0], 4u);
  EXPECT_EQ(counts.shape[1], 36u);
  double total = 0.0;
  for (float v : counts.data) total += v;
  EXPECT_GT(total, 0.0);
  // The effective config is the same run again.
  const config::RunConfig again = config::loadRunConfig(out / "config.effective.yaml");
  ASSERT_TRUE(again.lidar);
  EXPECT_EQ(config::effectiveConfigYaml(again), config::effectiveConfigYaml(c));
  EXPECT_EQ(again.lidar->spec.elevations_deg, c.lidar->spec.elevations_deg);
}

// A rolling scan through the pipeline: a plate 5 m + 30 m/s t ahead of the
// lidar (along +z), two frames, each the turn from its own time; every
// column's range is the plate's at its firing time (the closed form of
// LidarRollingScanTest, here through the config, the scene's animation and
// the files).
TEST_F(LidarRunTest, ARollingSequenceSeesEachColumnAtItsOwnTime) {
  const fs::path scene = test::writeMovingPlate(dir_);
  const config::RunConfig c = config::loadRunConfig(writeConfig(
      "scene: " + scene.string() +
      "\n"
      "lidar:\n"
      "  position: [0, 0, 0]\n"
      "  orientation: {look_at: [0, 0, 1], up: [0, 1, 0]}\n"
      "  channels: [0]\n"
      "  azimuth: {start: -20, end: 20, step: 4}\n"
      "  rotation_rate: 10 Hz\n"
      "  returns: {mode: first, max: 1}\n"
      "time: {bin_width: 10 ps, bins: 10000}\n"
      "sequence: {times: [0.2 s, 0.3 s]}\n"));
  pipeline::RunOptions options;
  options.outputDirectory = dir_ / "out";
  options.quiet = true;
  pipeline::runRender(c, options);
  const fs::path out = dir_ / "out";
  const nlohmann::json seq = nlohmann::json::parse(std::ifstream(out / "sequence.json"));
  ASSERT_EQ(seq["frames"].size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const double start = seq["frames"][k]["time_s"].get<double>();
    const fs::path frame = out / seq["frames"][k]["folder"].get<std::string>();
    const io::NpyArray range = io::readNpy(frame / "range.npy");
    ASSERT_EQ(range.shape, (std::vector<std::size_t>{1, 10}));
    EXPECT_EQ(io::readNpy(frame / "waveforms.npy").shape,
              (std::vector<std::size_t>{1, 10, 10000}));
    for (std::size_t a = 0; a < 10; ++a) {
      const double azimuth = -20.0 + 4.0 * a;
      const double t = start + (azimuth + 20.0) / 360.0 / 10.0;
      const double want = (5.0 + 30.0 * t) / std::cos(azimuth * M_PI / 180.0);
      EXPECT_NEAR(range.data[a], want, 0.01) << "frame " << k << ", azimuth " << azimuth;
    }
    // Every file the frame's lidar.json lists is in the frame's folder.
    const nlohmann::json meta = nlohmann::json::parse(std::ifstream(frame / "lidar.json"));
    for (const auto& f : meta["files"]) {
      EXPECT_TRUE(fs::exists(frame / f.get<std::string>())) << f;
    }
  }
  // The effective config is the same run again.
  const config::RunConfig again = config::loadRunConfig(out / "config.effective.yaml");
  ASSERT_TRUE(again.lidar && again.sequence);
  EXPECT_EQ(config::effectiveConfigYaml(again), config::effectiveConfigYaml(c));
  EXPECT_EQ(again.sequence->times_s, c.sequence->times_s);
}

// Rolling scans with the rest of a lidar (RollingScan.h's addRollingLight)
// through the pipeline: the same plate in fog (50 m visibility) with
// one-bounce multipath, two frames; every column's last return is the
// plate's at its firing time, the fog is in the waveforms before it and its
// false returns are written apart. And a raster (rows x columns cells at
// frame_rate, line by line from the top): every cell's range the plate's at
// its own firing time.
TEST_F(LidarRunTest, ARollingSequenceInFogWithMultipathAndARollingRaster) {
  const fs::path scene = test::writeMovingPlate(dir_);
  const std::string head = "scene: " + scene.string() +
                           "\n"
                           "lidar:\n"
                           "  position: [0, 0, 0]\n"
                           "  orientation: {look_at: [0, 0, 1], up: [0, 1, 0]}\n";
  const std::string tail =
      "  returns: {mode: last, max: 1, threshold: 1.0e-5}\n"
      "time: {bin_width: 10 ps, bins: 10000}\n"
      "sequence: {times: [0.1 s, 0.2 s]}\n";
  const auto render = [&](const std::string& yaml, const std::string& name) {
    pipeline::RunOptions options;
    options.outputDirectory = dir_ / name;
    options.quiet = true;
    pipeline::runRender(config::loadRunConfig(writeConfig(yaml)), options);
    return nlohmann::json::parse(std::ifstream(dir_ / name / "sequence.json"));
  };
  // The plate's range along beam direction d at time t (|d| = 1).
  const auto plateRange = [](double t, const std::vector<float>& d) { return (5.0 + 30.0 * t) / d[2]; };

  const nlohmann::json fog = render(head +
                                        "  channels: [0]\n"
                                        "  azimuth: {start: -20, end: 20, step: 4}\n"
                                        "  rotation_rate: 10 Hz\n"
                                        "  multipath: {bounces: 1, receiver_fov: 30 mrad}\n"
                                        "  backscatter: {phase_at_pi: 0.052}\n" +
                                        tail + "medium: {visibility: 50 m}\n",
                                    "fog");
  for (std::size_t k = 0; k < 2; ++k) {
    const double start = fog["frames"][k]["time_s"].get<double>();
    const fs::path frame = dir_ / "fog" / fog["frames"][k]["folder"].get<std::string>();
    const io::NpyArray range = io::readNpy(frame / "range.npy");
    const io::NpyArray directions = io::readNpy(frame / "beam_directions.npy");
    const io::NpyArray waveforms = io::readNpy(frame / "waveforms.npy");
    ASSERT_EQ(range.shape, (std::vector<std::size_t>{1, 10}));
    for (std::size_t a = 0; a < 10; ++a) {
      const double t = start + 4.0 * a / 360.0 / 10.0;
      const std::vector<float> d(directions.data.begin() + 3 * a, directions.data.begin() + 3 * a + 3);
      EXPECT_NEAR(range.data[a], plateRange(t, d), 0.01) << "frame " << k << ", azimuth " << a;
      EXPECT_GT(waveforms.data[a * 10000 + 1000], 0.0f) << "the fog at 1.5 m";
    }
    EXPECT_TRUE(fs::exists(frame / "fog_points.ply"));
    const nlohmann::json meta = nlohmann::json::parse(std::ifstream(frame / "lidar.json"));
    EXPECT_TRUE(meta["stats"].contains("fog_returns"));
  }

  const nlohmann::json raster = render(head +
                                           "  scan: raster\n"
                                           "  grid: {rows: 2, columns: 3}\n"
                                           "  field_of_view: {horizontal: 20, vertical: 10}\n"
                                           "  frame_rate: 10 Hz\n" +
                                           tail,
                                       "raster");
  EXPECT_EQ(raster["frame_rate_Hz"].get<double>(), 10.0);
  for (std::size_t k = 0; k < 2; ++k) {
    const double start = raster["frames"][k]["time_s"].get<double>();
    const fs::path frame = dir_ / "raster" / raster["frames"][k]["folder"].get<std::string>();
    const io::NpyArray range = io::readNpy(frame / "range.npy");
    const io::NpyArray directions = io::readNpy(frame / "beam_directions.npy");
    ASSERT_EQ(range.shape, (std::vector<std::size_t>{2, 3}));
    for (std::size_t cell = 0; cell < 6; ++cell) {  // row-major, row 0 the lowest: fired last
      const std::size_t row = cell / 3, column = cell % 3;
      const double t = start + ((1 - row) * 3.0 + column) / (6.0 * 10.0);
      const std::vector<float> d(directions.data.begin() + 3 * cell,
                                 directions.data.begin() + 3 * cell + 3);
      EXPECT_NEAR(range.data[cell], plateRange(t, d), 0.01) << "frame " << k << ", cell " << cell;
    }
  }
}

TEST_F(LidarRunTest, BadInputIsALocatedErrorAndWritesNothing) {
  const std::string base = smallLidar();
  const auto replace = [&](const std::string& from, const std::string& to) {
    std::string s = base;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  const std::vector<BadLidar> cases = {
      {"no channels", replace("{count: 4, min: -15, max: 0}", "{count: 0}"), ":5:"},
      {"an empty list", replace("{count: 4, min: -15, max: 0}", "[]"), ":5:"},
      {"a zero step", replace("step: 10", "step: 0"), ":6:"},
      {"no divergence", replace("3 mrad", "0 mrad"), ":7:"},
      {"a negative divergence", replace("3 mrad", "-1 mrad"), ":7:"},
      {"a preset", replace("  beam_divergence", "  preset: vlp16\n  beam_divergence"), ":7:"},
      {"a raster scan with channels",
       replace("  beam_divergence", "  scan: raster\n  beam_divergence"), ":5:"},
      {"a camera too", base + "camera: {resolution: [4, 4]}\n", ":10:"},
      {"an nlos scan too", base + "nlos: {relay_wall: wall}\n", ":10:"},
      {"a sequence of a still scene", base + "sequence: {times: [0 s]}\n", ":10:"},
      {"a sequence's video", base + "sequence: {times: [0 s], video: false}\n", ":10:"},
      {"a sequence's exposure samples", base + "sequence: {times: [0 s], exposure_samples: 2}\n",
       ":10:"},
      {"a spinning lidar's frame rate", replace("  beam_divergence", "  frame_rate: 10 Hz\n  beam_divergence"),
       ":7:"},
  };
  expectLocatedFailures(cases);
}

// lidar.multipath through the config: the waveforms gain the multipath
// (and only light: every bin at least the direct run's), the effective
// config runs it again, and bad multipath keys are located errors.
TEST_F(LidarRunTest, MultipathAddsToTheWaveformsAndBadKeysAreLocated) {
  const auto waveforms = [&](const std::string& extra, const char* name) {
    const config::RunConfig c = config::loadRunConfig(writeConfig(smallLidar(extra)));
    pipeline::RunOptions options;
    options.outputDirectory = dir_ / name;
    options.quiet = true;
    pipeline::runRender(c, options);
    return io::readNpy(dir_ / name / "waveforms.npy").data;
  };
  const std::string multipath = "  multipath: {bounces: 1, receiver_fov: 30 mrad}\n";
  const std::vector<float> direct = waveforms("", "direct");
  const std::vector<float> both = waveforms(multipath, "multipath");
  ASSERT_EQ(direct.size(), both.size());
  double d = 0.0, b = 0.0;
  int lower = 0;
  for (std::size_t i = 0; i < direct.size(); ++i) {
    d += direct[i], b += both[i];
    lower += both[i] < direct[i];
  }
  EXPECT_EQ(lower, 0);
  EXPECT_GT(b, d * 1.0001);
  const config::RunConfig again =
      config::loadRunConfig(dir_ / "multipath" / "config.effective.yaml");
  ASSERT_TRUE(again.lidar);
  EXPECT_EQ(again.lidar->multipath.bounces, 1);
  EXPECT_EQ(again.lidar->multipath.receiver_fov_rad, 0.03);

  const std::vector<BadLidar> cases = {
      {"a receiver narrower than the beam",
       smallLidar("  multipath: {bounces: 1, receiver_fov: 1 mrad}\n"), ":9:"},
      {"a receiver fov without a unit", smallLidar("  multipath: {bounces: 1, receiver_fov: 30}\n"),
       ":9:"},
      {"too many bounces", smallLidar("  multipath: {bounces: 9}\n"), ":9:"},
      {"no spot rays", smallLidar("  multipath: {bounces: 1, spot_rays: 0}\n"), ":9:"},
      {"a typo", smallLidar("  multipath: {bounce: 1}\n"), ":9:"},
  };
  expectLocatedFailures(cases);
}

}  // namespace
}  // namespace tofsim
