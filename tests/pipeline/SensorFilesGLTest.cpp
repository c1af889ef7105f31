// End-to-end through the CLI: the files a researcher reads. depth.npy beside
// depth.exr; every sensor output with a metadata JSON whose shape, axes and
// time axis match the array actually written; the CW-ToF ambiguity warning
// for one frequency on a scene deeper than its range (and none when the
// frequencies unwrap far enough); per-frequency files for several frequencies.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "pipeline/CliRun.h"
#include "support/TempDir.h"
#include "tofsim/io/DepthExr.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"

namespace tofsim {
namespace {

using nlohmann::json;
using test::CommandResult;
using test::runCli;

// The demo (sensors 0: spad, 1: streak, 2: cwtof at 20 and 100 MHz) at 24x24
// pixels and 200 bins of 10 ps from 5 ns.
const std::string kSmall =
    " --set camera.resolution=[24,24] --set time.bins=200 --set render.shadow_map_resolution=256"
    " --set render.indirect.rsm_resolution=8 --set render.indirect.points_per_vpl=200"
    " --set sensors.0.plot_pixels=[[12,12]] --set sensors.1.rows=[6] -q";

json readJson(const std::filesystem::path& file) {
  return json::parse(test::fileBytes(file.string()));
}

class SensorFilesGLTest : public test::TempDirTest {
 protected:
  std::filesystem::path render(const std::string& extra, CommandResult* result = nullptr) {
    const auto out = dir_ / "out";
    const CommandResult r =
        runCli("render " + test::kCornellConfig + " -o " + out.string() + kSmall + extra);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    if (result) *result = r;
    return out;
  }
};

TEST_F(SensorFilesGLTest, DepthNpyHoldsTheDepthOfDepthExr) {
  const auto out = render(" --set sensors=[]");
  const io::NpyArray npy = io::readNpy(out / "depth.npy");
  EXPECT_EQ(npy.shape, (io::NpyShape{24, 24}));
  const Image exr = io::readDepthExr(out / "depth.exr");
  EXPECT_EQ(npy.data, exr.data);
  // The box spans 0.8 m (open front) to its back corners; a few edge pixels see nothing (0).
  std::size_t surfaces = 0;
  for (float d : npy.data) {
    if (d == 0.0f) continue;
    ++surfaces;
    EXPECT_GT(d, 0.79f);
    EXPECT_LT(d, 1.6f);
  }
  EXPECT_GT(surfaces, npy.data.size() * 8 / 10);
}

TEST_F(SensorFilesGLTest, EverySensorFileHasMetadataMatchingItsArray) {
  const auto out = render("");
  std::size_t described = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(out / "sensors")) {
    const std::filesystem::path file = e.path();
    if (file.extension() != ".npy" && file.extension() != ".exr") continue;
    const auto metaFile = std::filesystem::path(file).replace_extension(".json");
    ASSERT_TRUE(std::filesystem::exists(metaFile)) << metaFile;
    const json meta = readJson(metaFile);
    std::vector<int64_t> shape;
    if (file.extension() == ".npy") {
      const io::NpyShape s = io::readNpy(file).shape;
      shape.assign(s.begin(), s.end());
      // An Array's data, or an Image's numbers beside its .exr (files.npy).
      const bool imageTwin = meta["kind"] == "image";
      EXPECT_EQ(meta["files"][imageTwin ? "npy" : "data"], file.filename().string());
    } else {
      const Image image = io::readExr(file);
      shape = {image.height, image.width};
      EXPECT_EQ(meta["exr_channels"], json{"Y"});
    }
    EXPECT_EQ(meta["shape"].get<std::vector<int64_t>>(), shape) << file;
    EXPECT_EQ(meta["axes"].size(), shape.size()) << file;
    EXPECT_EQ(meta["name"], file.stem().string());
    EXPECT_EQ(meta["dtype"], "float32");
    EXPECT_EQ(meta["sensor"]["seed"], 1);  // the demo's render.seed
    EXPECT_EQ(meta["sensor"]["name"], file.parent_path().filename().string());
    EXPECT_FALSE(meta["unit"].get<std::string>().empty()) << file;
    ++described;
  }
  EXPECT_GE(described, 15u);

  // SPAD counts: (y, x, t) over the instrument's axis, which the config sets
  // to follow the render's (start 5 ns... , 10 ps bins, as many as cover it).
  const json counts = readJson(out / "sensors/spad/spad_counts.json");
  EXPECT_EQ(counts["axes"], (json{"y", "x", "t"}));
  EXPECT_EQ(counts["time"]["bins"], counts["shape"][2]);
  EXPECT_DOUBLE_EQ(counts["time"]["bin_width_s"].get<double>(),
                   counts["sensor"]["parameters"]["bin_width_s"].get<double>());
  EXPECT_DOUBLE_EQ(counts["time"]["start_s"].get<double>(),
                   counts["sensor"]["render_time"]["start_s"].get<double>());
  EXPECT_NEAR(counts["time"]["bin_width_m"].get<double>(),
              299792458.0 * counts["time"]["bin_width_s"].get<double>(), 1e-12);
  EXPECT_EQ(counts["sensor"]["parameters"]["cycles"], 20000);
  const json streak = readJson(out / "sensors/streak/streak_row006.json");
  EXPECT_EQ(streak["axes"], (json{"t", "x"}));
  EXPECT_EQ(streak["time"]["bins"], streak["shape"][0]);
  EXPECT_EQ(streak["attributes"]["row"], 6);
  EXPECT_EQ(streak["picture"]["colormap"], "inferno");
  EXPECT_EQ(readJson(out / "sensors/cwtof/cwtof_raw.json")["axes"],
            (json{"frequency", "phase_step", "y", "x"}));
}

TEST_F(SensorFilesGLTest, OneFrequencyOnADeeperSceneWarnsOfAmbiguity) {
  // 150 MHz: 1.0 m unambiguous range; the box reaches ~1.5 m.
  CommandResult r;
  const auto out = render(" --set 'sensors.2.frequencies=[\"150 MHz\"]'", &r);
  EXPECT_NE(r.output.find("tofsim: warning: sensor 'cwtof' (cwtof): the scene's ground-truth "
                          "depth reaches"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("unambiguous range of 150MHz"), std::string::npos) << r.output;
  const json depth = readJson(out / "sensors/cwtof/cwtof_depth.json");
  ASSERT_EQ(depth["sensor"]["warnings"].size(), 1u);
  EXPECT_NE(depth["sensor"]["warnings"][0].get<std::string>().find("unambiguous range"),
            std::string::npos);
  EXPECT_NEAR(depth["attributes"]["range_m"].get<double>(), 299792458.0 / 2 / 150e6, 1e-9);
  EXPECT_NE(depth["description"].get<std::string>().find("wrapped"), std::string::npos);
  EXPECT_EQ(depth["description"].get<std::string>().find("unwrapped"), std::string::npos);
}

TEST_F(SensorFilesGLTest, SeveralFrequenciesWritePerFrequencyFilesAndUnwrapWithoutWarning) {
  CommandResult r;
  const auto out = render("", &r);  // the demo's 20 and 100 MHz: 7.5 m unwrapped range
  EXPECT_EQ(r.output.find("unambiguous"), std::string::npos) << r.output;
  const auto cwtof = out / "sensors" / "cwtof";
  for (const auto& [label, hz] : {std::pair{"20MHz", 20e6}, std::pair{"100MHz", 100e6}}) {
    for (const char* stem :
         {"cwtof_phase_", "cwtof_amplitude_", "cwtof_depth_", "cwtof_multipath_error_"}) {
      const std::string name = std::string(stem) + label;
      for (const char* ext : {".exr", ".png", ".json"}) {
        EXPECT_TRUE(std::filesystem::exists(cwtof / (name + ext))) << name << ext;
      }
      const json meta = readJson(cwtof / (name + ".json"));
      EXPECT_EQ(meta["attributes"]["frequency_Hz"].get<double>(), hz) << name;
      EXPECT_EQ(meta["signed"].get<bool>(), std::string(stem) == "cwtof_multipath_error_");
    }
  }
  EXPECT_EQ(io::readNpy(cwtof / "cwtof_phase.npy").shape, (io::NpyShape{2, 24, 24}));
  const json depth = readJson(cwtof / "cwtof_depth.json");
  EXPECT_NE(depth["description"].get<std::string>().find("unwrapped"), std::string::npos);
  EXPECT_EQ(depth["sensor"]["parameters"]["frequencies_Hz"], (json{20e6, 100e6}));
}

}  // namespace
}  // namespace tofsim
