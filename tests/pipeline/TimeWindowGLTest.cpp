// Light cut off by a time window is reported: after the render with the
// measured fraction (the same as transient.json's energies and an uncut
// render's total), before it by `validate` from the scene's bounds, as an
// error that writes nothing under --strict, and for a sensor's own window,
// which by default is the render's axis.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "pipeline/CliRun.h"
#include "pipeline/StatsJson.h"
#include "support/TempDir.h"
#include "tofsim/io/Npy.h"

namespace tofsim {
namespace {

using test::CommandResult;
using test::jsonNumber;

const std::string kSpad = std::string(TOFSIM_SOURCE_DIR) + "/configs/spad_lidar.yaml";
const std::string kSmall =
    " --set camera.resolution=[16,16] --set render.shadow_map_resolution=256"
    " --set render.indirect.rsm_resolution=8 --set render.indirect.points_per_vpl=100"
    " --set render.indirect.ism_resolution=16 --set sensors.0.plot_pixels=[[8,8]] -q";
// spad_lidar's axis starts at 1.5 m; 200 bins of 3 mm end at 2.1 m, before the back wall.
const std::string kCut = " --set time.bins=200";
const std::string kNoLight = " --set time.start=-1ns --set time.bins=50";

class TimeWindowGLTest : public test::TempDirTest {};

// The percentage after "tofsim: warning: ", or NaN.
double warnedPercent(const std::string& output) {
  const std::size_t at = output.find("tofsim: warning: ");
  if (at == std::string::npos) return std::nan("");
  return std::strtod(output.c_str() + at + 17, nullptr);
}

TEST_F(TimeWindowGLTest, CutOffAxisWarnsWithTheMeasuredFraction) {
  const CommandResult cut =
      test::runCli("render " + kSpad + " -o " + (dir_ / "cut").string() + kSmall + kCut);
  ASSERT_EQ(cut.exitCode, 0) << cut.output;
  EXPECT_NE(cut.output.find("of the light arrives after the last bin (7.003 ns); time.bins: "),
            std::string::npos)
      << cut.output;
  const std::filesystem::path json = dir_ / "cut" / "transient.json";
  const double on = jsonNumber(json, "energy_on_axis");
  const double after = jsonNumber(json, "energy_after_axis");
  EXPECT_EQ(jsonNumber(json, "energy_before_axis"), 0.0);
  EXPECT_NEAR(jsonNumber(json, "fraction_after_axis"), after / (on + after), 1e-12);
  EXPECT_GT(after / (on + after), 0.2);  // the back wall and the indirect light
  EXPECT_NEAR(warnedPercent(cut.output), 100.0 * after / (on + after), 0.05);

  // The light a longer axis bins is the light the short one binned plus what it lost.
  const CommandResult whole =
      test::runCli("render " + kSpad + " -o " + (dir_ / "whole").string() + kSmall);
  ASSERT_EQ(whole.exitCode, 0) << whole.output;
  EXPECT_EQ(whole.output.find("warning"), std::string::npos) << whole.output;
  const std::filesystem::path wholeJson = dir_ / "whole" / "transient.json";
  // The pixel footprint spreads a grazing pixel's light a little past any
  // axis that ends close behind it (16 x 16 pixels are wide): a trace, not a cut.
  EXPECT_LT(test::offAxisFraction(wholeJson), 1e-4);
  EXPECT_NEAR(jsonNumber(wholeJson, "energy_on_axis"), on + after, 1e-4 * (on + after));
}

TEST_F(TimeWindowGLTest, ValidatePredictsTheCutAndStrictFailsOnAProvenOne) {
  CommandResult r = test::runCli("validate " + kSpad + kNoLight);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("tofsim: warning: the time axis ends at -0.5 ns"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("all of it arrives after the last bin; time.start: "), std::string::npos)
      << r.output;
  r = test::runCli("validate " + kSpad + kNoLight + " --strict");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("tofsim: error: "), std::string::npos) << r.output;
  // 200 bins may cut (the bound says so); only rendering can tell how much.
  r = test::runCli("validate " + kSpad + kCut + " --strict");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("tofsim: note: the time axis 5.003 ns .. 7.003 ns may cut light off"),
            std::string::npos)
      << r.output;
  // A note (a loose bound), which names the warning render gives a measured cut.
  EXPECT_NE(r.output.find("(render measures the cut and warns above 0.1 %)"), std::string::npos)
      << r.output;
  // The shipped axis ends a little before the (loose) bound: a note at most.
  r = test::runCli("validate " + kSpad);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
  // An axis over the whole bound: no word.
  r = test::runCli("validate " + kSpad + " --set time.bins=800");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("tofsim:"), std::string::npos) << r.output;
}

// One bin far wider than all of the scene's arrivals resolves nothing: an
// error from validate and from render (which writes nothing), naming
// time.bin_width and a width that would resolve the light.
TEST_F(TimeWindowGLTest, AnAxisThatCannotResolveTheLightIsAnError) {
  const std::string wide = " --set 'time.bin_width=10 s' --set time.bins=1";
  CommandResult r = test::runCli("validate " + kSpad + wide);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("time.bin_width: one bin of 1e+10 ns cannot resolve the scene's light"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("a bin width near"), std::string::npos) << r.output;
  const std::filesystem::path out = dir_ / "wide";
  r = test::runCli("render " + kSpad + " -o " + out.string() + kSmall + wide);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out / "transient.json"));
  // A wide bin that still resolves the scene (2 ns of 7 ns of arrivals) renders.
  r = test::runCli("validate " + kSpad + " --set 'time.bin_width=2 ns' --set time.bins=10");
  EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST_F(TimeWindowGLTest, StrictFailsAndWritesNothing) {
  // A proven cut fails before rendering; a measured one after it, before the
  // outputs are committed. Neither leaves a folder it made.
  for (const std::string& axis : {kNoLight, kCut}) {
    const std::filesystem::path out = dir_ / "new";
    const CommandResult r =
        test::runCli("render " + kSpad + " -o " + out.string() + kSmall + axis + " --strict");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("--strict"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << axis;
  }
  // An existing folder keeps exactly what it held. render.strict in the
  // config (as batches set it) does the same as the flag.
  const std::filesystem::path kept = dir_ / "kept";
  std::filesystem::create_directories(kept);
  std::ofstream(kept / "earlier.txt") << "earlier run";
  const CommandResult r = test::runCli("render " + kSpad + " -o " + kept.string() + kSmall + kCut +
                                       " --set render.strict=true");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(test::visibleFiles(kept), std::vector<std::string>{"earlier.txt"});
  EXPECT_EQ(test::fileBytes((kept / "earlier.txt").string()), "earlier run");
}

TEST_F(TimeWindowGLTest, SensorWindowFollowsTheRenderAxisAndWarnsWhenSetShort) {
  const auto counts = [&](const std::string& name, const std::string& sets) {
    const CommandResult r =
        test::runCli("render " + kSpad + " -o " + (dir_ / name).string() + kSmall + sets);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return r;
  };
  counts("a", "");
  counts("b", " --set time.bins=500");
  const io::NpyArray a = io::readNpy(dir_ / "a" / "sensors" / "spad" / "spad_counts.npy");
  const io::NpyArray b = io::readNpy(dir_ / "b" / "sensors" / "spad" / "spad_counts.npy");
  // The preset's 17 ps TDC bins up to the render's end: 7 ns / 17 ps -> 412
  // (the render's 700 bins of 10 ps), 5 ns -> 295 (--set time.bins=500).
  EXPECT_EQ(a.shape, (io::NpyShape{16, 16, 412}));
  EXPECT_EQ(b.shape, (io::NpyShape{16, 16, 295}));
  // An explicit window wins and is reported: 100 TDC bins hold only the first returns.
  const CommandResult shortWindow = counts("c", " --set sensors.0.bins=100");
  EXPECT_NE(shortWindow.output.find("sensor 'spad' (spad): its instrument window drops "),
            std::string::npos)
      << shortWindow.output;
  EXPECT_EQ(io::readNpy(dir_ / "c" / "sensors" / "spad" / "spad_counts.npy").shape,
            (io::NpyShape{16, 16, 100}));
  const CommandResult strict = test::runCli("render " + kSpad + " -o " + (dir_ / "d").string() +
                                            kSmall + " --set sensors.0.bins=100 --strict");
  EXPECT_EQ(strict.exitCode, 1) << strict.output;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "d"));
}

}  // namespace
}  // namespace tofsim
