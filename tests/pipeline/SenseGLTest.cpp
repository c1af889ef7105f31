// End-to-end: the demo config's sensors run after `tofsim render`, write
// their files by kind, and `tofsim sense` on the saved render reproduces them
// byte for byte; bad sensor settings fail with a located error.

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "pipeline/CliRun.h"
#include "support/TempDir.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"

namespace tofsim {
namespace {

using test::CommandResult;
using test::runCli;

// The demo at 24x24 pixels and 200 bins; the sensors (0: spad, 1: streak,
// 2: cwtof) shrunk to fit.
const std::string kSmall =
    " --set camera.resolution=[24,24] --set time.bins=200 --set render.shadow_map_resolution=256"
    " --set render.indirect.rsm_resolution=8 --set render.indirect.points_per_vpl=200"
    " --set sensors.0.bins=200 --set sensors.0.plot_pixels=[[12,12],[4,12]]"
    " --set sensors.1.bins=200 --set sensors.1.rows=[6,18] -q";

std::set<std::string> filesUnder(const std::filesystem::path& dir) {
  std::set<std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) files.insert(std::filesystem::relative(e.path(), dir).string());
  }
  return files;
}

class SenseGLTest : public test::TempDirTest {};

TEST_F(SenseGLTest, RenderWritesSensorOutputsAndSenseReproducesThem) {
  const auto out = dir_ / "render";
  const CommandResult r = runCli("render " + test::kCornellConfig + " -o " + out.string() + kSmall);
  ASSERT_EQ(r.exitCode, 0) << r.output;

  const auto spad = out / "sensors" / "spad";
  EXPECT_EQ(io::readNpy(spad / "spad_counts.npy").shape, (io::NpyShape{24, 24, 200}));
  const Image depth = io::readExr(spad / "spad_depth_peak.exr");
  EXPECT_EQ(depth.width, 24);
  EXPECT_EQ(depth.channels, 1);
  for (const char* f : {"spad_histograms.png", "spad_depth_peak.png", "spad_depth_coates.exr",
                        "spad_intensity.png"}) {
    EXPECT_TRUE(std::filesystem::exists(spad / f)) << f;
  }
  const auto streak = out / "sensors" / "streak";
  const Image row = io::readExr(streak / "streak_row006.exr");
  EXPECT_EQ(row.width, 24);
  EXPECT_EQ(row.height, 200);  // rows are time bins
  EXPECT_TRUE(std::filesystem::exists(streak / "streak_row018.png"));
  const auto cwtof = out / "sensors" / "cwtof";
  EXPECT_EQ(io::readNpy(cwtof / "cwtof_raw.npy").shape, (io::NpyShape{2, 4, 24, 24}));
  // The demo saves depth.exr and direct.npy, so both multipath errors exist.
  for (const char* f : {"cwtof_depth.exr", "cwtof_depth.png", "cwtof_mpi_error.exr",
                        "cwtof_mpi_error_direct.exr"}) {
    EXPECT_TRUE(std::filesystem::exists(cwtof / f)) << f;
  }

  const auto again = dir_ / "sense";
  const CommandResult s = runCli("sense " + test::kCornellConfig + " --volume " + out.string() +
                                 " -o " + again.string() + kSmall);
  ASSERT_EQ(s.exitCode, 0) << s.output;
  const std::set<std::string> rendered = filesUnder(out / "sensors");
  EXPECT_EQ(filesUnder(again / "sensors"), rendered);
  EXPECT_GT(rendered.size(), 15u);
  for (const std::string& f : rendered) {
    EXPECT_TRUE(test::fileBytes((out / "sensors" / f).string()) ==
                test::fileBytes((again / "sensors" / f).string()))
        << f;
  }
  // Only the sensors' files: sense does not rewrite the render's outputs.
  EXPECT_EQ(test::visibleFiles(again).size(), rendered.size());
}

// transient.json carries the medium: `sense` without the --set turns time
// into depth as the render did (c / 1.33), so the depths come out the same.
TEST_F(SenseGLTest, SenseTakesTheMediumFromTheSavedVolume) {
  const auto out = dir_ / "render";
  const std::string water = " --set time.index_of_refraction=1.33 --set time.bins=300";
  const CommandResult r =
      runCli("render " + test::kCornellConfig + " -o " + out.string() + kSmall + water);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto again = dir_ / "sense";
  const CommandResult s = runCli("sense " + test::kCornellConfig + " --volume " + out.string() +
                                 " -o " + again.string() + kSmall + " --set time.bins=300");
  ASSERT_EQ(s.exitCode, 0) << s.output;
  for (const char* f : {"cwtof/cwtof_depth.exr", "spad/spad_depth_peak.exr"}) {
    EXPECT_TRUE(test::fileBytes((out / "sensors" / f).string()) ==
                test::fileBytes((again / "sensors" / f).string()))
        << f;
  }
}

TEST_F(SenseGLTest, BadSensorValueFailsWithLocatedError) {
  const CommandResult r = runCli("render " + test::kCornellConfig + " -o " +
                                 (dir_ / "bad").string() + " --set sensors.0.pulse_fwhm=-1ps");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.output.find("--set sensors.0.pulse_fwhm=-1ps: sensors[0].pulse_fwhm: must be >= 0"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "bad"));
}

TEST_F(SenseGLTest, SenseNamesTheMissingVolumeFile) {
  const CommandResult r = runCli("sense " + test::kCornellConfig + " --volume " + dir_.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.output.find((dir_ / "transient.json").string()), std::string::npos) << r.output;
  EXPECT_NE(runCli("sense " + test::kCornellConfig).exitCode, 0);  // --volume is required
}

}  // namespace
}  // namespace tofsim
