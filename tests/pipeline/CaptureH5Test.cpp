// output.format: hdf5 end to end through the CLI (CPU backend, no GL): the
// datasets of capture.h5 equal the .npy files of the same render, whatever
// the thread count and memory budget; a pixel's histogram and a time slice
// read through hyperslabs; attributes = the JSON files; an earlier file
// survives a failed run; `tofsim sense` and `tofsim compare` read it, and a
// damaged one is a located error.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "pipeline/CliRun.h"
#include "support/TempDir.h"
#include "tofsim/io/Hdf5Capture.h"
#include "tofsim/io/Npy.h"
#include "tofsim/util/Error.h"

namespace tofsim::test {
namespace {

namespace fs = std::filesystem;
using CaptureH5Test = TempDirTest;

// The Cornell box, small: 32 x 32 pixels, 256 bins (3 MiB a volume, so a
// 1 MiB memory budget cuts it into segments), its three sensors.
std::string small(const std::string& extra = "") {
  return " --set camera.resolution=[32,32] --set time.bins=256 --set render.backend=cpu"
         " --set output.video=false --set sensors.0.plot_pixels=[[4,4]]"
         " --set sensors.1.rows=[8] -q " +
         extra;
}

CommandResult render(const fs::path& out, const std::string& extra) {
  return runCli("render " + kCornellConfig + " -o " + out.string() + small(extra));
}

std::vector<float> npy(const fs::path& file) { return io::readNpy(file).data; }

// The two renders, made once for the suite; each test gets its own copy.
class RenderedPair : public CaptureH5Test {
 protected:
  static void SetUpTestSuite() {
    rendered_ = fs::temp_directory_path() / ("tofsim_RenderedPair_" + std::to_string(::getpid()));
    fs::remove_all(rendered_);
    const CommandResult a = render(rendered_ / "npy", "");
    const CommandResult b =
        render(rendered_ / "h5",
               "--set output.format=hdf5 --set render.threads=1 --set render.memory_budget=1MiB");
    failure_ = a.exitCode != 0 ? a.output : b.exitCode != 0 ? b.output : "";
  }
  static void TearDownTestSuite() { fs::remove_all(rendered_); }
  void SetUp() override {
    CaptureH5Test::SetUp();
    ASSERT_EQ(failure_, "");
    fs::copy(rendered_, dir_, fs::copy_options::recursive);
  }

  static inline fs::path rendered_;
  static inline std::string failure_;
};

TEST_F(RenderedPair, DatasetsEqualTheNpyFilesAcrossThreadsAndBudgets) {
  EXPECT_FALSE(fs::exists(dir_ / "h5" / "transient.npy"));
  EXPECT_FALSE(fs::exists(dir_ / "h5" / "direct.npy"));
  const io::H5CaptureReader h5(dir_ / "h5" / "capture.h5");
  for (const char* name : {"transient", "direct", "indirect", "depth"}) {
    SCOPED_TRACE(name);
    const io::NpyArray want = io::readNpy(dir_ / "npy" / (std::string(name) + ".npy"));
    const io::NpyArray got = h5.read(name);
    EXPECT_EQ(got.shape, want.shape);
    EXPECT_EQ(got.data, want.data);
  }
  int sensorArrays = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir_ / "npy" / "sensors")) {
    if (entry.path().extension() != ".npy") continue;
    const std::string dataset =
        fs::relative(entry.path(), dir_ / "npy").replace_extension().generic_string();
    SCOPED_TRACE(dataset);
    const io::NpyArray want = io::readNpy(entry.path());
    const io::NpyArray got = h5.read(dataset);
    EXPECT_EQ(got.shape, want.shape);
    ASSERT_EQ(got.data.size(), want.data.size());
    // Bitwise (NaN where undefined in both).
    EXPECT_EQ(0, std::memcmp(got.data.data(), want.data.data(), got.data.size() * sizeof(float)));
    ++sensorArrays;
  }
  EXPECT_GE(sensorArrays, 3);
  EXPECT_TRUE(h5.has("steady"));
  EXPECT_TRUE(h5.has("sensors/cwtof/cwtof_depth"));  // an EXR output
}

TEST_F(RenderedPair, PixelHistogramAndTimeSliceThroughHyperslabs) {
  const io::H5CaptureReader h5(dir_ / "h5" / "capture.h5");
  const std::vector<float> full = npy(dir_ / "npy" / "transient.npy");
  const std::size_t T = 256, C = 3, W = 32;
  const std::vector<float> pixel = h5.readSlab("transient", {20, 11, 0, 0}, {1, 1, T, C});
  const std::size_t first = (20 * W + 11) * T * C;
  EXPECT_EQ(pixel, std::vector<float>(full.begin() + first, full.begin() + first + T * C));
  const std::vector<float> slice = h5.readSlab("transient", {0, 0, 100, 0}, {32, 32, 1, C});
  ASSERT_EQ(slice.size(), 32 * W * C);
  for (std::size_t p = 0; p < 32 * W; ++p) {
    for (std::size_t c = 0; c < C; ++c) {
      ASSERT_EQ(slice[p * C + c], full[(p * T + 100) * C + c]) << p;
    }
  }
}

TEST_F(RenderedPair, AttributesAreTheJsonFiles) {
  const io::H5CaptureReader h5(dir_ / "h5" / "capture.h5");
  EXPECT_EQ(h5.stringAttribute("transient", "json"),
            fileBytes((dir_ / "h5" / "transient.json").string()));
  EXPECT_EQ(h5.stringAttribute("transient", "units"), "W m^-2 sr^-1");
  EXPECT_EQ(h5.stringAttribute("depth", "units"), "m");
  EXPECT_EQ(h5.stringAttribute("sensors/spad/spad_counts", "json"),
            fileBytes((dir_ / "h5" / "sensors" / "spad" / "spad_counts.json").string()));
}

TEST_F(RenderedPair, SenseAndCompareReadTheCapture) {
  const std::string sensorsNpy = "sense " + kCornellConfig + " --volume " +
                                 (dir_ / "npy").string() + " -o " + (dir_ / "sa").string();
  const std::string sensorsH5 = "sense " + kCornellConfig + " --volume " + (dir_ / "h5").string() +
                                " -o " + (dir_ / "sb").string();
  const CommandResult a = runCli(sensorsNpy + small());
  ASSERT_EQ(a.exitCode, 0) << a.output;
  const CommandResult b = runCli(sensorsH5 + small());
  ASSERT_EQ(b.exitCode, 0) << b.output;
  for (const std::string& f : visibleFiles(dir_ / "sa" / "sensors")) {
    if (fs::path(f).extension() != ".npy") continue;
    EXPECT_EQ(fileBytes((dir_ / "sa" / "sensors" / f).string()),
              fileBytes((dir_ / "sb" / "sensors" / f).string()))
        << f;
  }
  const CommandResult c = runCli("compare " + (dir_ / "npy").string() + " " +
                                 (dir_ / "h5").string() + " -o " + (dir_ / "cmp").string());
  ASSERT_EQ(c.exitCode, 0) << c.output;
  EXPECT_NE(c.output.find("transient relative L1       0"), std::string::npos) << c.output;
}

TEST_F(RenderedPair, AFailedRunLeavesTheEarlierFile) {
  const fs::path file = dir_ / "h5" / "capture.h5";
  const std::string before = fileBytes(file.string());
  const std::vector<std::string> listing = visibleFiles(dir_ / "h5");
  // --strict: the light past the last bin fails the run (after rendering).
  const CommandResult r = render(dir_ / "h5", "--set output.format=hdf5 --strict");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(fileBytes(file.string()), before);
  EXPECT_EQ(visibleFiles(dir_ / "h5"), listing);
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().filename().string().find("staging"), std::string::npos) << entry.path();
  }
}

TEST_F(RenderedPair, ADamagedCaptureIsALocatedErrorOfSense) {
  const fs::path file = dir_ / "h5" / "capture.h5";
  const std::string bytes = fileBytes(file.string());
  for (const std::size_t keep : {bytes.size() / 2, std::size_t{4000}, std::size_t{10}}) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes.substr(0, keep);
    const CommandResult r =
        runCli("sense " + kCornellConfig + " --volume " + (dir_ / "h5").string() + " -o " +
               (dir_ / "s").string() + small());
    EXPECT_EQ(r.exitCode, 1) << keep << ": " << r.output;
    EXPECT_NE(r.output.find(file.string()), std::string::npos) << r.output;
  }
}

TEST_F(CaptureH5Test, BatchManifestListsTheCaptureAndVerifyChecksIt) {
  std::ofstream(dir_ / "batch.yaml")
      << "base: " << kCornellConfig << "\noutput: " << (dir_ / "out").string()
      << "\nset:\n  camera.resolution: [8, 8]\n  time.bins: 32\n  render.backend: cpu\n"
         "  output.video: false\n  output.format: hdf5\n  sensors: []\nruns:\n  - name: one\n";
  const CommandResult r = runCli("batch " + (dir_ / "batch.yaml").string() + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const fs::path run = dir_ / "out" / "one";
  EXPECT_NE(fileBytes((run / "manifest.json").string()).find("\"capture.h5\""), std::string::npos);
  // One byte changed in the middle of the file: --verify finds it.
  std::string bytes = fileBytes((run / "capture.h5").string());
  bytes[bytes.size() / 2] ^= 0x5a;
  std::ofstream(run / "capture.h5", std::ios::binary | std::ios::trunc) << bytes;
  const CommandResult dry =
      runCli("batch " + (dir_ / "batch.yaml").string() + " --dry-run --verify");
  EXPECT_NE(dry.output.find("incomplete"), std::string::npos) << dry.output;
  EXPECT_NE(dry.output.find("capture.h5"), std::string::npos) << dry.output;
}

}  // namespace
}  // namespace tofsim::test
