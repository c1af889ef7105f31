// End-to-end: a render's sensors are fed the volume segment by segment as it
// streams out of the renderer (a memory budget small enough for several
// segments), and write byte for byte what `tofsim sense` writes from the
// saved volume, read back run by run within the same budget (several runs);
// without the volume written (sensors only)
// the sensors' files are the same again. The streamed spad_counts.npy still
// has its metadata, and output.plot_ranges reaches the sensors' pictures.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "pipeline/CliRun.h"
#include "pipeline/StatsJson.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

using test::CommandResult;
using test::runCli;

// The demo at 24x24 pixels and 200 bins (rendered on the CPU backend), 1 MiB of budget
// (a 24x24x200x3 segment of both components would take 2.6 MiB), the
// direct component saved so that the CW-ToF writes both multipath errors,
// 3 CW-ToF frequencies, and fixed colour ranges for two sensor pictures.
const std::string kSegmented =
    " --set render.memory_budget=1MiB"
    " --set camera.resolution=[24,24] --set time.bins=200 --set render.shadow_map_resolution=256"
    " --set render.indirect.rsm_resolution=4 --set render.indirect.points_per_vpl=200"
    " --set output.video=false --set output.components=[direct]"
    " --set sensors.0.bins=200 --set sensors.0.plot_pixels=[[12,12],[4,12]]"
    " --set sensors.1.bins=200 --set sensors.1.rows=[6,18,7]"
    " --set sensors.2.frequencies=[20MHz,50MHz,100MHz]"
    " --set 'output.plot_ranges={sensors/spad/spad_intensity: [0, 50],"
    " sensors/cwtof/cwtof_mpi_error: [-0.05, 0.05]}' -q";

std::set<std::string> filesUnder(const std::filesystem::path& dir) {
  std::set<std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) files.insert(std::filesystem::relative(e.path(), dir).string());
  }
  return files;
}

void expectSameFiles(const std::filesystem::path& a, const std::filesystem::path& b) {
  const std::set<std::string> files = filesUnder(a);
  EXPECT_EQ(filesUnder(b), files);
  EXPECT_GT(files.size(), 40u);
  for (const std::string& f : files) {
    EXPECT_TRUE(test::fileBytes((a / f).string()) == test::fileBytes((b / f).string())) << f;
  }
}

class StreamingSensorsGLTest : public test::TempDirTest {};

TEST_F(StreamingSensorsGLTest, SegmentedSensorsWriteTheBytesOfTheWholeVolume) {
  const auto out = dir_ / "render";
  const CommandResult r =
      runCli("render --backend cpu " + test::kCornellConfig + " -o " + out.string() + kSegmented);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_GE(test::jsonNumber(out / "transient.json", "segments"), 3.0);
  EXPECT_TRUE(std::filesystem::exists(out / "sensors" / "cwtof" / "cwtof_mpi_error_direct.exr"));
  EXPECT_TRUE(std::filesystem::exists(out / "sensors" / "cwtof" / "cwtof_depth_50MHz.exr"));
  // Both ranges were taken by a picture of the streamed sensors.
  EXPECT_EQ(r.output.find("names no picture"), std::string::npos) << r.output;
  // spad_counts went to its .npy segment by segment; its metadata is whole.
  const nlohmann::json counts = nlohmann::json::parse(
      test::fileBytes((out / "sensors" / "spad" / "spad_counts.json").string()));
  EXPECT_EQ(counts["shape"], (nlohmann::json{24, 24, 200}));
  EXPECT_EQ(counts["axes"], (nlohmann::json{"y", "x", "t"}));
  EXPECT_EQ(counts["time"]["bins"], 200);
  EXPECT_EQ(counts["files"]["data"], "spad_counts.npy");
  // A picture's JSON says the colour range it was drawn with: the fixed one,
  // or the automatic one with its percentiles.
  const nlohmann::json intensity = nlohmann::json::parse(
      test::fileBytes((out / "sensors" / "spad" / "spad_intensity.json").string()));
  EXPECT_EQ(intensity["picture"]["range"]["lo"], 0.0);
  EXPECT_EQ(intensity["picture"]["range"]["hi"], 50.0);
  EXPECT_EQ(intensity["picture"]["range"]["source"], "output.plot_ranges");
  EXPECT_EQ(intensity["picture"]["range"]["unit"], "counts");
  const nlohmann::json peak = nlohmann::json::parse(
      test::fileBytes((out / "sensors" / "spad" / "spad_depth_peak.json").string()));
  const nlohmann::json& range = peak["picture"]["range"];
  EXPECT_EQ(range["source"], "automatic");
  EXPECT_LT(range["lo"].get<double>(), range["hi"].get<double>());
  EXPECT_GT(range["lo"].get<double>(), 0.5);  // metres: the box is 0.8 .. 1.4 m away
  EXPECT_LT(range["hi_percentile"].get<double>(), 100.0 + 1e-9);

  // The saved volume read back in runs of pixels within the 1 MiB budget.
  const auto sensed = dir_ / "sense";
  const CommandResult s = runCli("sense " + test::kCornellConfig + " --volume " + out.string() +
                                 " -o " + sensed.string() + kSegmented);
  ASSERT_EQ(s.exitCode, 0) << s.output;
  expectSameFiles(out / "sensors", sensed / "sensors");

  // Sensors only: nothing of the volume written, the same sensor files. A
  // range for a picture no sensor draws is warned about, and changes nothing.
  const auto only = dir_ / "only";
  const CommandResult o = runCli(
      "render --backend cpu " + test::kCornellConfig + " -o " + only.string() + kSegmented +
      " --set output.transient=false --set 'output.plot_ranges.sensors/spad/spad_nope=[0, 1]'");
  ASSERT_EQ(o.exitCode, 0) << o.output;
  EXPECT_NE(o.output.find("output.plot_ranges.sensors/spad/spad_nope names no picture"),
            std::string::npos)
      << o.output;
  EXPECT_FALSE(std::filesystem::exists(only / "transient.npy"));
  expectSameFiles(out / "sensors", only / "sensors");
}

}  // namespace
}  // namespace tofsim
