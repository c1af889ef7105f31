// Lidar presets and grid scans through the config and the CLI: a preset's
// values reach the spec (and the multizone's bins the time axis), explicit
// keys win, the effective config of a raster, a zone scan and a preset loads
// to the same run, `tofsim presets` lists each value with its source; bad
// input (an unknown preset, a zone grid of no rows, a key of another scan, a
// grid scan without its grid, a field of view of 180 deg) is a located
// error, exit 1, nothing written.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "pipeline/CliRun.h"
#include "support/TempDir.h"
#include "tofsim/config/LidarConfig.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;

const std::string kStreet = std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/lidar_street.gltf";

class LidarPresetTest : public test::TempDirTest {
 protected:
  fs::path write(const std::string& lidarKeys, const std::string& time = "time: {start: 0}\n") {
    const fs::path path = dir_ / "c.yaml";
    std::ofstream(path) << "scene: " << kStreet
                        << "\nlidar:\n  position: [0, 1.8, 0]\n  orientation: {look_at: [1, 1.8, "
                           "0], up: [0, 1, 0]}\n"
                        << lidarKeys << time;
    return path;
  }
  config::RunConfig load(const std::string& lidarKeys,
                         const std::string& time = "time: {start: 0}\n") {
    return config::loadRunConfig(write(lidarKeys, time));
  }
};

TEST_F(LidarPresetTest, PresetValuesReachTheSpec) {
  {
    const config::RunConfig c = load("  preset: spinning-16\n");
    const lidar::LidarSpec& s = c.lidar->spec;
    ASSERT_EQ(s.channels(), 16);
    EXPECT_DOUBLE_EQ(s.elevations_deg.front(), -15.0);
    EXPECT_DOUBLE_EQ(s.elevations_deg[1], -13.0);
    EXPECT_DOUBLE_EQ(s.elevations_deg.back(), 15.0);
    EXPECT_EQ(s.azimuths(), 1800);
    EXPECT_DOUBLE_EQ(s.divergence_rad, 3e-3);
    EXPECT_EQ(s.returns.mode, lidar::ReturnMode::Dual);
    EXPECT_EQ(s.returns.max, 2);
    EXPECT_DOUBLE_EQ(c.lidar->rotation_rate_Hz, 10.0);
    EXPECT_EQ(c.lidar->preset, "spinning-16");
  }
  {
    const config::RunConfig c = load("  preset: spinning-64\n");
    const lidar::LidarSpec& s = c.lidar->spec;
    EXPECT_EQ(s.channels(), 64);
    EXPECT_NEAR(s.elevations_deg.back() - s.elevations_deg.front(), 33.2, 1e-12);
    EXPECT_EQ(s.azimuths(), 1024);
    // 0.13 deg FWHM as a Gaussian's 1/e^2 full width: 3.854 mrad.
    EXPECT_NEAR(s.divergence_rad, 3.854e-3, 1e-6);
    EXPECT_EQ(s.returns.mode, lidar::ReturnMode::Strongest);
    EXPECT_EQ(s.returns.max, 1);
  }
  {
    const config::RunConfig c = load("  preset: multizone-8x8\n");
    const lidar::LidarSpec& s = c.lidar->spec;
    EXPECT_EQ(s.scan, lidar::ScanPattern::Zones);
    EXPECT_EQ(s.channels(), 8);
    EXPECT_EQ(s.azimuths(), 8);
    EXPECT_DOUBLE_EQ(s.grid.fov_horizontal_deg, 45.0);
    EXPECT_DOUBLE_EQ(s.grid.fov_vertical_deg, 45.0);
    EXPECT_EQ(c.render.time.bins, 128);
    EXPECT_NEAR(c.render.time.bin_width_s, 250.4e-12, 1e-18);
    EXPECT_EQ(s.returns.mode, lidar::ReturnMode::All);
    EXPECT_EQ(s.returns.max, 4);
    // The device looks at look_at; the sensors' image is the zones.
    EXPECT_EQ(c.camera.camera.width, 8);
    EXPECT_EQ(c.camera.camera.height, 8);
  }
}

TEST_F(LidarPresetTest, ExplicitKeysWin) {
  const config::RunConfig a = load(
      "  preset: spinning-16\n  channels: {count: 4, min: -2, max: 2}\n"
      "  beam_divergence: 1 mrad\n  returns: {mode: last}\n");
  EXPECT_EQ(a.lidar->spec.channels(), 4);
  EXPECT_DOUBLE_EQ(a.lidar->spec.divergence_rad, 1e-3);
  EXPECT_EQ(a.lidar->spec.returns.mode, lidar::ReturnMode::Last);
  EXPECT_EQ(a.lidar->spec.returns.max, 2);    // the preset's
  EXPECT_EQ(a.lidar->spec.azimuths(), 1800);  // the preset's
  const config::RunConfig b =
      load("  preset: multizone-8x8\n  grid: {rows: 4, columns: 4}\n  zone_rays: 2\n",
           "time: {bins: 64}\n");
  EXPECT_EQ(b.lidar->spec.channels(), 4);
  EXPECT_EQ(b.lidar->spec.grid.zone_rays, 2);
  EXPECT_DOUBLE_EQ(b.lidar->spec.grid.fov_vertical_deg, 45.0);  // the preset's
  EXPECT_EQ(b.render.time.bins, 64);
  EXPECT_NEAR(b.render.time.bin_width_s, 250.4e-12, 1e-18);  // the preset's
}

TEST_F(LidarPresetTest, GridScansAndPresetsRoundTrip) {
  for (const std::string& keys :
       {std::string("  scan: raster\n  grid: {rows: 3, columns: 5}\n  field_of_view: "
                    "{horizontal: 30, vertical: 10}\n  beam_rays: 4\n  plot_beams: [[1, 4]]\n"
                    "  frame_rate: 25 Hz\n"),
        std::string("  scan: zones\n  grid: {rows: 2, columns: 6}\n  field_of_view: "
                    "{horizontal: 60, vertical: 20}\n  zone_rays: 5\n"),
        std::string("  preset: multizone-8x8\n"), std::string("  preset: spinning-64\n")}) {
    const config::RunConfig c = load(keys);
    const std::string written = config::effectiveConfigYaml(c);
    const fs::path again = dir_ / "again.yaml";
    std::ofstream(again) << written;
    const config::RunConfig d = config::loadRunConfig(again);
    EXPECT_EQ(config::effectiveConfigYaml(d), written) << keys;
    EXPECT_EQ(d.lidar->spec.grid.zone_rays, c.lidar->spec.grid.zone_rays);
    EXPECT_EQ(d.lidar->spec.forward_world, c.lidar->spec.forward_world);
    EXPECT_EQ(d.lidar->scanRate_Hz(), c.lidar->scanRate_Hz());
  }
  EXPECT_EQ(load("  scan: raster\n  grid: {rows: 3, columns: 5}\n  field_of_view: {horizontal: 30, "
                 "vertical: 10}\n  frame_rate: 25 Hz\n")
                .lidar->scanRate_Hz(),
            25.0);
}

TEST_F(LidarPresetTest, PresetsCommandListsEachValueAndItsSource) {
  const test::CommandResult all = test::runCli("presets");
  ASSERT_EQ(all.exitCode, 0) << all.output;
  for (const char* name :
       {"spinning-16 (lidar)", "spinning-64 (lidar)", "multizone-8x8 (lidar)", "spad512s"}) {
    EXPECT_NE(all.output.find(name), std::string::npos) << name;
  }
  const test::CommandResult one = test::runCli("presets multizone-8x8");
  ASSERT_EQ(one.exitCode, 0) << one.output;
  for (const char* line : {"time.bin_width = 250.4 ps  source: [CNH]", "time.bins = 128  source:",
                           "grid = {rows: 8, columns: 8}  source: [DS13754]",
                           "zone_rays = 4  assumed:", "[DS13754] ST VL53L5CX datasheet"}) {
    EXPECT_NE(one.output.find(line), std::string::npos) << line << "\n" << one.output;
  }
  EXPECT_EQ(one.output.find("spinning-16"), std::string::npos);
}

TEST_F(LidarPresetTest, BadInputIsALocatedErrorAndWritesNothing) {
  struct Bad {
    const char* name;
    std::string keys;
    const char* where;  ///< "c.yaml:line:" and a word of the message
    const char* says;
  };
  const std::string zones =
      "  scan: zones\n  grid: {rows: 8, columns: 8}\n  field_of_view: {horizontal: 45, "
      "vertical: 45}\n";
  const auto replace = [](std::string s, const std::string& from, const std::string& to) {
    return s.replace(s.find(from), from.size(), to);
  };
  const std::vector<Bad> cases = {
      {"an unknown preset", "  preset: vlp-17\n",
       "c.yaml:5:", "spinning-16, spinning-64, multizone-8x8"},
      {"zones of no rows", replace(zones, "rows: 8", "rows: 0"), "c.yaml:6:", "rows"},
      {"zones of 2000 columns", replace(zones, "columns: 8", "columns: 2000"),
       "c.yaml:6:", "columns"},
      {"zones without a grid", "  scan: zones\n", "c.yaml:5:", "grid"},
      {"a field of view of 180 deg", replace(zones, "horizontal: 45", "horizontal: 180"),
       "c.yaml:7:", "horizontal"},
      {"zones with channels", zones + "  channels: {count: 4}\n", "c.yaml:8:", "channels"},
      {"zones with a divergence", zones + "  beam_divergence: 3 mrad\n",
       "c.yaml:8:", "beam_divergence"},
      {"a spinning lidar with a grid", "  channels: {count: 4}\n  grid: {rows: 8, columns: 8}\n",
       "c.yaml:6:", "grid"},
      {"an unknown scan", "  scan: flash\n", "c.yaml:5:", "spinning, raster or zones"},
      {"zones with multipath", zones + "  multipath: {bounces: 1}\n", "c.yaml:8:",
       "flood emitter has no spot"},
      {"a zone scan's sequence", zones + "sequence: {times: [0 s]}\n", "c.yaml:8:",
       "no firing order"},
      {"zones with a frame rate", zones + "  frame_rate: 10 Hz\n", "c.yaml:8:",
       "lights every zone at once"},
  };
  for (const Bad& bad : cases) {
    const fs::path config = write(bad.keys, "time: {bins: 64}\n");
    const test::CommandResult r =
        test::runCli("render " + config.string() + " -o " + (dir_ / "out").string());
    EXPECT_EQ(r.exitCode, 1) << bad.name << ": " << r.output;
    EXPECT_NE(r.output.find(bad.where), std::string::npos) << bad.name << ": " << r.output;
    EXPECT_NE(r.output.find(bad.says), std::string::npos) << bad.name << ": " << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << bad.name;
  }
}

}  // namespace
}  // namespace tofsim
