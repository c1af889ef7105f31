// A lidar in fog through the pipeline (apd43): the fog's backscatter makes
// false returns, counted in lidar.json (`stats.fog_returns`) and written
// alone to fog_points.ply, one per beam that sees no surface near it; an APD
// sensor runs on the waveforms. In clear air neither file nor count exists.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/RenderRun.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;

const std::string kStreet = std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/lidar_street.gltf";

// 2 channels x 36 azimuths over the street (the lowest sees the ground at
// 7 m), 400 bins of 300 ps (0 .. 18 m).
std::string fogLidar(const std::string& medium, const std::string& apd = "") {
  return "scene: " + kStreet +
         "\n"
         "lidar:\n"
         "  position: [0, 1.8, 0]\n"
         "  orientation: {look_at: [1, 1.8, 0], up: [0, 1, 0]}\n"
         "  channels: {count: 2, min: -15, max: 0}\n"
         "  azimuth: {start: 0, end: 360, step: 10}\n"
         "  returns: {mode: all, max: 3, threshold: 2.0e-5}\n"
         "  backscatter: {phase_at_pi: 0.052}\n" +
         medium +
         "time: {bin_width: 300 ps, bins: 400}\n"
         "sensors:\n  - {type: apd, source_scale: 3.0e-7, etendue: 4.9e-4" + apd + "}\n";
}

class LidarFogRunTest : public test::TempDirTest {
 protected:
  nlohmann::json run(const std::string& yaml, const fs::path& out) {
    const fs::path path = dir_ / "c.yaml";
    std::ofstream(path) << yaml;
    pipeline::RunOptions options;
    options.outputDirectory = out;
    options.quiet = true;
    pipeline::runRender(config::loadRunConfig(path), options);
    return nlohmann::json::parse(std::ifstream(out / "lidar.json"));
  }
};

TEST_F(LidarFogRunTest, FogsFalseReturnsAreCountedAndWrittenApart) {
  const nlohmann::json fog = run(fogLidar("medium: {visibility: 50 m}\n"), dir_ / "fog");
  // Every beam's fog echo from 1 m (the overlap) on: the nearest surface is
  // farther than ~2.5 m in every direction from the lidar's mast.
  EXPECT_EQ(fog["stats"]["fog_returns"].get<int>(), 72);
  EXPECT_GT(fog["stats"]["points"].get<int>(), 72);  // and the surfaces within reach
  EXPECT_TRUE(fs::exists(dir_ / "fog" / "fog_points.ply"));
  EXPECT_EQ(io::readNpy(dir_ / "fog" / "sensors/apd/apd_range.npy").shape,
            (std::vector<std::size_t>{2, 36, 3}));
  const nlohmann::json clear = run(fogLidar(""), dir_ / "clear");
  EXPECT_FALSE(clear["stats"].contains("fog_returns"));
  EXPECT_FALSE(fs::exists(dir_ / "clear" / "fog_points.ply"));
}

// The APD in fog (sensors/README.md, "CA-CFAR"): its noise-level CFAR sees
// the fog's return above it far past the surfaces, one echo swallowing
// them; the cell-averaging CFAR's threshold follows the fog, so each
// surface the clear run sees is an echo of its own (within 0.3 m of the
// clear run's range) in nearly every beam. The fog's rise at the overlap
// stays the first echo (an edge: no window's mean follows it).
TEST_F(LidarFogRunTest, ACellAveragingCfarFindsTheSurfacesInTheFog) {
  run(fogLidar(""), dir_ / "clear");
  const std::string fog = "medium: {visibility: 50 m}\n";
  run(fogLidar(fog), dir_ / "noise");
  run(fogLidar(fog, ", threshold_mode: ca_cfar"), dir_ / "ca");
  const io::NpyArray surface = io::readNpy(dir_ / "clear" / "range.npy");
  const auto onSurface = [&](const fs::path& out, int& firstPastFog) {
    const io::NpyArray r = io::readNpy(out / "sensors/apd/apd_range.npy");
    int found = 0;
    firstPastFog = 0;
    for (std::size_t b = 0; b < surface.data.size(); ++b) {
      firstPastFog += r.data[3 * b] > 3.0f;  // NaN compares false
      if (!(surface.data[b] > 0.0f)) continue;
      bool hit = false;
      for (std::size_t k = 0; k < 3; ++k) hit |= std::fabs(r.data[3 * b + k] - surface.data[b]) < 0.3f;
      found += hit;
    }
    return found;
  };
  int surfaces = 0;
  for (float v : surface.data) surfaces += v > 0.0f;
  int noiseFirst = 0, caFirst = 0;
  const int noise = onSurface(dir_ / "noise", noiseFirst);
  const int ca = onSurface(dir_ / "ca", caFirst);
  EXPECT_GT(surfaces, 40);
  EXPECT_GE(ca, 0.9 * surfaces) << ca << " of " << surfaces;
  EXPECT_LE(noise, 0.2 * surfaces) << noise << " of " << surfaces;
  EXPECT_EQ(caFirst, 0);  // the fog's rise first in every beam
}

}  // namespace
}  // namespace tofsim
