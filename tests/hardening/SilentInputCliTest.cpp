// Bad input that tofsim once took without a word (issue 39), end to end
// through the CLI (CPU backend, no GL): a key given twice in a config or a
// --set value, a YAML alias bomb in a batch `set`, a saved volume with NaN,
// infinite or negative values read by `sense` and `compare` (.npy and
// capture.h5), and a vignetting map of zeros or of gains that overflow; and
// the light off the time axis counted against the light on it before the
// vignetting's gains, as the renderer counts it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "pipeline/CliRun.h"
#include "pipeline/StatsJson.h"
#include "support/AliasBomb.h"
#include "support/TempDir.h"
#include "tofsim/io/Hdf5Capture.h"
#include "tofsim/io/Npy.h"

namespace tofsim::test {
namespace {

namespace fs = std::filesystem;

// The Cornell box at 16 x 16 pixels and 256 bins (some light arrives after
// the last bin), its three sensors.
std::string small(const std::string& extra = "") {
  return " --set camera.resolution=[16,16] --set time.bins=256 --set render.backend=cpu"
         " --set output.video=false --set sensors.0.plot_pixels=[[4,4]]"
         " --set sensors.1.rows=[8] -q " +
         extra;
}

// A config file: the demo's text with its scene's path made absolute, then `more`.
fs::path writeConfig(const fs::path& file, const std::string& more) {
  std::string text = fileBytes(kCornellConfig);
  const std::string scene = "scene: scenes/";
  text.replace(text.find(scene), scene.size(),
               "scene: " + std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/");
  std::ofstream(file) << text << more;
  return file;
}

using SilentInputCliTest = TempDirTest;

TEST_F(SilentInputCliTest, AKeyGivenTwiceIsAnErrorNamingBothLines) {
  // Before: `validate` said ok and the first camera won.
  const fs::path config = writeConfig(dir_ / "c.yaml", "camera: {resolution: [16, 16]}\n");
  const std::string text = fileBytes(config.string());
  const auto lines = std::count(text.begin(), text.end(), '\n');
  const CommandResult r = runCli("validate " + config.string());
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("c.yaml:" + std::to_string(lines) +
                          ":1: key 'camera' appears twice in one mapping: line 7, column 1 and "
                          "line " +
                          std::to_string(lines) + ", column 1"),
            std::string::npos)
      << r.output;
  const CommandResult set = runCli("validate " + kCornellConfig +
                                   " --set 'camera={resolution: [8, 8], resolution: [16, 16]}'");
  EXPECT_EQ(set.exitCode, 1) << set.output;
  EXPECT_NE(set.output.find("'resolution' appears twice in one mapping: line 1, column 2 and "
                            "line 1, column 22"),
            std::string::npos)
      << set.output;
}

TEST_F(SilentInputCliTest, AnAliasBombInABatchSetIsRefusedAtOnce) {
  // Before: minutes of expansion, then the video's out-of-memory message.
  // The limits keep a build without the check from taking the machine.
  std::ofstream(dir_ / "b.yaml") << "base: " << kCornellConfig
                                 << "\noutput: out\nset:\n  camera.resolution: " << aliasBomb()
                                 << "\n";
  // (Not the address-space limit under AddressSanitizer, whose shadow memory
  // is a reservation of terabytes.)
#ifdef __SANITIZE_ADDRESS__
  const char* limits = "timeout -s KILL 10";
#else
  const char* limits = "ulimit -v 4000000; timeout -s KILL 10";
#endif
  const CommandResult r =
      runCli("batch " + (dir_ / "b.yaml").string() + " --dry-run", limits);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("b.yaml:4:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("aliases expand this document past 1000000 nodes"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(SilentInputCliTest, AVignettingMapOfZerosOrOverflowingGainsIsRefused) {
  const std::vector<float> zeros(16 * 16, 0.0f);
  io::writeNpy(dir_ / "zeros.npy", {16, 16}, zeros.data());
  std::vector<float> huge(16 * 16, 1.0f);
  huge[3 * 16 + 5] = 3e38f;
  io::writeNpy(dir_ / "huge.npy", {16, 16}, huge.data());
  const std::string validate = "validate " + kCornellConfig + " --set camera.resolution=[16,16]";
  const CommandResult z =
      runCli(validate + " --set camera.vignetting=" + (dir_ / "zeros.npy").string());
  EXPECT_EQ(z.exitCode, 1) << z.output;
  EXPECT_NE(z.output.find("camera.vignetting: " + (dir_ / "zeros.npy").string() +
                          ": every gain is 0, which makes every pixel black"),
            std::string::npos)
      << z.output;
  const CommandResult h =
      runCli(validate + " --set camera.vignetting=" + (dir_ / "huge.npy").string());
  EXPECT_EQ(h.exitCode, 1) << h.output;
  EXPECT_NE(h.output.find("camera.vignetting: " + (dir_ / "huge.npy").string() +
                          ": gain 3e+38 at (y, x) = (3, 5) is over 1000"),
            std::string::npos)
      << h.output;
}

// Before: the light on the axis was summed after the gains and the light
// off it before them, so a map of 0.25 made the late light's share 4 times
// larger (an all-zero map: 100 %), a map of 3e38 hid it.
TEST_F(SilentInputCliTest, LightOffTheTimeAxisIsTheSameShareWithVignetting) {
  const std::vector<float> quarter(16 * 16, 0.25f);
  io::writeNpy(dir_ / "quarter.npy", {16, 16}, quarter.data());
  const CommandResult plain = runCli("render " + kCornellConfig + " -o " +
                                     (dir_ / "plain").string() + small("--set sensors=[]"));
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  const CommandResult dim =
      runCli("render " + kCornellConfig + " -o " + (dir_ / "dim").string() +
             small("--set sensors=[] --set camera.vignetting=" + (dir_ / "quarter.npy").string()));
  ASSERT_EQ(dim.exitCode, 0) << dim.output;
  const double share = jsonNumber(dir_ / "plain" / "transient.json", "fraction_after_axis");
  ASSERT_GT(share, 0.01);  // the axis cuts light off: what is under test
  EXPECT_NEAR(jsonNumber(dir_ / "dim" / "transient.json", "fraction_after_axis"), share,
              1e-4 * share);
  // The warning says the same share in both.
  const std::size_t at = plain.output.find("of the light arrives after the last bin");
  ASSERT_NE(at, std::string::npos) << plain.output;
  const std::size_t from = plain.output.rfind(' ', at - 2) + 1;
  EXPECT_NE(dim.output.find(plain.output.substr(from, at - from)), std::string::npos)
      << plain.output << dim.output;
}

// A render to damage, made once for the suite; each test gets its own copy.
class SavedVolumeCliTest : public TempDirTest {
 protected:
  static void SetUpTestSuite() {
    rendered_ = fs::temp_directory_path() / ("tofsim_SavedVolumeCli_" + std::to_string(::getpid()));
    fs::remove_all(rendered_);
    const CommandResult r =
        runCli("render " + kCornellConfig + " -o " + (rendered_ / "r").string() + small());
    failure_ = r.exitCode != 0 ? r.output : "";
  }
  static void TearDownTestSuite() { fs::remove_all(rendered_); }
  void SetUp() override {
    TempDirTest::SetUp();
    ASSERT_EQ(failure_, "");
    fs::copy(rendered_, dir_, fs::copy_options::recursive);
    volume_ = io::readNpy(dir_ / "r" / "transient.npy");
  }
  // value at (y, x, bin, channel) of the saved transient.
  float& at(std::size_t y, std::size_t x, std::size_t bin, std::size_t channel) {
    const io::NpyShape& s = volume_.shape;
    return volume_.data[((y * s[1] + x) * s[2] + bin) * s[3] + channel];
  }
  void save() { io::writeNpy(dir_ / "r" / "transient.npy", volume_.shape, volume_.data.data()); }
  CommandResult sense() {
    return runCli("sense " + kCornellConfig + " --volume " + (dir_ / "r").string() + " -o " +
                  (dir_ / "s").string() + small());
  }

  io::NpyArray volume_;
  static inline fs::path rendered_;
  static inline std::string failure_;
};

TEST_F(SavedVolumeCliTest, AnAllNanVolumeIsALocatedErrorOfSenseAndCompare) {
  // Before: sense exit 0 with zero counts, compare exit 0 printing nan.
  for (float& v : volume_.data) v = std::numeric_limits<float>::quiet_NaN();
  save();
  const std::string file = (dir_ / "r" / "transient.npy").string();
  const CommandResult s = sense();
  EXPECT_EQ(s.exitCode, 1) << s.output;
  EXPECT_NE(
      s.output.find(file + ": value nan at (y, x, bin, channel) = (0, 0, 0, 0) is not finite"),
      std::string::npos)
      << s.output;
  EXPECT_TRUE(visibleFiles(dir_ / "s").empty());
  const CommandResult c = runCli("compare " + (dir_ / "r").string() + " " +
                                 (rendered_ / "r").string() + " -o " + (dir_ / "c").string());
  EXPECT_EQ(c.exitCode, 1) << c.output;
  EXPECT_NE(c.output.find(file + ": value nan at"), std::string::npos) << c.output;
  EXPECT_FALSE(fs::exists(dir_ / "c"));
}

TEST_F(SavedVolumeCliTest, OneInfiniteOrNegativeValueIsNamedWhereItIs) {
  at(9, 4, 100, 2) = std::numeric_limits<float>::infinity();
  save();
  CommandResult r = sense();
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("transient.npy: value inf at (y, x, bin, channel) = (9, 4, 100, 2) is "
                          "not finite: a saved volume holds radiance, finite and >= 0"),
            std::string::npos)
      << r.output;
  at(9, 4, 100, 2) = 0.0f;
  at(15, 15, 255, 0) = -0.5f;
  save();
  r = runCli("compare " + (rendered_ / "r").string() + " " + (dir_ / "r").string() + " -o " +
             (dir_ / "c").string());
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("transient.npy: value -0.5 at (y, x, bin, channel) = (15, 15, 255, 0) "
                          "is negative"),
            std::string::npos)
      << r.output;
}

TEST_F(SavedVolumeCliTest, ANanInACaptureH5IsNamedWithItsDataset) {
  at(2, 3, 40, 1) = std::numeric_limits<float>::quiet_NaN();
  {
    io::H5CaptureWriter h5(dir_ / "r" / "capture.h5");
    h5.write("transient", volume_.shape, volume_.data.data());
    for (const char* name : {"direct", "indirect"}) {
      const fs::path npy = dir_ / "r" / (std::string(name) + ".npy");
      if (!fs::exists(npy)) continue;
      const io::NpyArray component = io::readNpy(npy);
      h5.write(name, component.shape, component.data.data());
      fs::remove(npy);
    }
    h5.commit();
  }
  fs::remove(dir_ / "r" / "transient.npy");
  const CommandResult r = sense();
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("capture.h5:/transient: value nan at (y, x, bin, channel) = (2, 3, 40, "
                          "1) is not finite"),
            std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace tofsim::test
