// `tofsim view` through the CLI (CPU backend, no GL, no browser): the page's
// data equal the render's files (the transient of transient.npy and of
// capture.h5, the steady image, every sensor map), an NLOS capture's page
// holds H, and a folder that is not a tofsim output is a located error that
// writes nothing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/TempDir.h"
#include "tofsim/io/Npy.h"
#include "viewer/ViewerPage.h"

namespace tofsim::test {
namespace {

namespace fs = std::filesystem;

// A render of each format, made when a test first asks for it (ctest runs
// each test in its own process) and read, never written, by the tests.
class ViewerPageTest : public TempDirTest {
 protected:
  static void TearDownTestSuite() { fs::remove_all(root()); }
  static fs::path root() {
    return fs::temp_directory_path() / ("tofsim_ViewerPageTest_" + std::to_string(::getpid()));
  }
  // "npy": with the config's sensors; "volume-npy", "volume-h5": without
  // them (0.6 s instead of 3 s: no sensor files to write and sync).
  static fs::path rendered(const std::string& name) {
    const fs::path out = root() / name;
    if (!fs::exists(out)) {
      std::string extra = name.rfind("volume-", 0) == 0 ? "--set sensors=[] " : "";
      if (name == "volume-h5") extra += "--set output.format=hdf5";
      const CommandResult r = renderSmallCornell(out, extra);
      EXPECT_EQ(r.exitCode, 0) << r.output;
    }
    return out;
  }
  nlohmann::json view(const std::string& format) {
    const fs::path page = dir_ / (format + ".html");
    const CommandResult r = runCli("view " + rendered(format).string() + " -o " + page.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return pageData(fileBytes(page.string()));
  }
};

TEST_F(ViewerPageTest, TheVolumeAndSteadyImageAreTheRendersOfEitherFormat) {
  const io::NpyArray transient = io::readNpy(rendered("volume-npy") / "transient.npy");
  ASSERT_EQ(transient.shape, (io::NpyShape{10, 12, 96, 3}));
  for (const std::string format : {"volume-npy", "volume-h5"}) {
    const nlohmann::json page = view(format);
    ASSERT_FALSE(page.is_null()) << format;
    const nlohmann::json& v = page["volume"];
    EXPECT_EQ(page["kind"], "camera");
    EXPECT_EQ(v["full"], nlohmann::json({10, 12, 96})) << format;
    EXPECT_EQ(v["pixel_block"], 1);  // small: nothing downsampled
    EXPECT_EQ(v["bin_run"], 1);
    const std::vector<double> values = decoded(v);
    ASSERT_EQ(values.size(), transient.data.size());
    const double scale = v["scale"];
    std::vector<double> steady(10 * 12 * 3, 0.0);
    for (std::size_t i = 0; i < values.size(); ++i) {
      const double expected = transient.data[i];
      ASSERT_NEAR(values[i], expected, halfTolerance(expected, scale)) << format << " value " << i;
      steady[(i / (96 * 3)) * 3 + i % 3] += expected;
    }
    const std::vector<double> image = decoded(page["image"]);
    ASSERT_EQ(image.size(), steady.size());
    for (std::size_t i = 0; i < image.size(); ++i) {
      EXPECT_NEAR(image[i], steady[i],
                  halfTolerance(steady[i], page["image"]["scale"]) +
                      1e-6 * steady[i]);  // float sums in another order
    }
  }
}

TEST_F(ViewerPageTest, EverySensorMapAndHistogramIsInThePage) {
  const nlohmann::json page = view("npy");
  std::vector<std::string> names;
  for (const auto& m : page["maps"])
    names.push_back(m["group"].get<std::string>() + "/" + m["name"].get<std::string>());
  for (const std::string want :
       {"render/depth", "spad/spad_depth_peak", "spad/spad_confidence", "cwtof/cwtof_depth",
        "cwtof/cwtof_phase[1]", "streak/streak_row004"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  }
  for (const auto& m : page["maps"]) {
    if (m["name"] != "spad_depth_peak") continue;
    EXPECT_EQ(m["unit"], "m");
    const io::NpyArray depth = io::readNpy(rendered("npy") / "sensors/spad/spad_depth_peak.npy");
    const std::vector<double> values = decoded(m);
    ASSERT_EQ(values.size(), depth.data.size());
    const double step = (m["hi"].get<double>() - m["lo"].get<double>()) / 65534.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
      EXPECT_NEAR(values[i], depth.data[i], step / 2 + 1e-6 * std::fabs(depth.data[i])) << i;
    }
  }
  // A SPAD's counts (y, x, t): every pixel's histogram.
  ASSERT_EQ(page["histograms"].size(), 1u);
  const nlohmann::json& h = page["histograms"][0];
  EXPECT_EQ(h["label"], "spad/spad_counts");
  EXPECT_EQ(h["unit"], "counts");
  EXPECT_EQ(h["full"], nlohmann::json({10, 12, 96}));
  const io::NpyArray counts = io::readNpy(rendered("npy") / "sensors/spad/spad_counts.npy");
  const std::vector<double> values = decoded(h);
  ASSERT_EQ(values.size(), counts.data.size());
  const double scale = h["scale"];
  for (std::size_t i = 0; i < values.size(); ++i) {
    ASSERT_NEAR(values[i], counts.data[i], halfTolerance(counts.data[i], scale)) << i;
  }
}

TEST_F(ViewerPageTest, AnNlosCapturesPageHoldsH) {
  const fs::path out = dir_ / "nlos";
  const CommandResult r =
      runCli("render " + std::string(TOFSIM_SOURCE_DIR) + "/configs/nlos_single.yaml -o " +
             out.string() + " --set nlos.sensor_grid=[4,3] --set time.bins=128 -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ASSERT_EQ(runCli("view " + out.string()).exitCode, 0);
  const nlohmann::json page = pageData(fileBytes((out / "view.html").string()));
  EXPECT_EQ(page["kind"], "nlos");
  EXPECT_EQ(page["volume"]["full"], nlohmann::json({4, 3, 128}));
  const io::NpyArray h = io::readNpy(out / "H.npy");  // (t, sx, sy)
  const std::vector<double> values = decoded(page["volume"]);
  const double scale = page["volume"]["scale"];
  for (std::size_t sx = 0; sx < 4; ++sx) {
    for (std::size_t sy = 0; sy < 3; ++sy) {
      for (std::size_t t = 0; t < 128; ++t) {
        const double expected = h.data[(t * 4 + sx) * 3 + sy];
        ASSERT_NEAR(values[(sx * 3 + sy) * 128 + t], expected, halfTolerance(expected, scale));
      }
    }
  }
}

TEST_F(ViewerPageTest, ALidarsPageHoldsItsWaveformsAndRangeImage) {
  const fs::path out = dir_ / "lidar";
  const CommandResult r = runCli(
      "render " + std::string(TOFSIM_SOURCE_DIR) + "/configs/lidar_street.yaml -o " +
      out.string() + " --set lidar.channels.count=4 --set lidar.azimuth.step=10 -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ASSERT_EQ(runCli("view " + out.string()).exitCode, 0);
  const nlohmann::json page = pageData(fileBytes((out / "view.html").string()));
  EXPECT_EQ(page["kind"], "lidar");
  const io::NpyArray w = io::readNpy(out / "waveforms.npy");  // (rings, azimuths, t)
  ASSERT_EQ(w.shape.size(), 3u);
  EXPECT_EQ(page["volume"]["full"], nlohmann::json({w.shape[0], w.shape[1], w.shape[2]}));
  const std::vector<double> values = decoded(page["volume"]);
  const double scale = page["volume"]["scale"];
  ASSERT_EQ(values.size(), w.data.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    ASSERT_NEAR(values[i], w.data[i], halfTolerance(w.data[i], scale)) << i;
  }
  const io::NpyArray range = io::readNpy(out / "range.npy");
  bool found = false;
  for (const auto& m : page["lidars"]) {
    if (m["name"] != "range") continue;
    found = true;
    const std::vector<double> v = decoded(m);
    ASSERT_EQ(v.size(), w.shape[0] * w.shape[1]);
    const std::size_t perBeam = range.data.size() / v.size();  // returns per beam
    const double step = (m["hi"].get<double>() - m["lo"].get<double>()) / 65534.0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const double expected = range.data[i * perBeam];
      EXPECT_NEAR(v[i], expected, step / 2 + 1e-6 * std::fabs(expected)) << i;
    }
  }
  EXPECT_TRUE(found);
}

// A multizone sensor's folder: its own per-zone distance is a lidar map.
TEST_F(ViewerPageTest, AMultizonePageHoldsItsZoneDistances) {
  const fs::path out = dir_ / "zones";
  const CommandResult r = runCli("render " + std::string(TOFSIM_SOURCE_DIR) +
                                 "/configs/multizone_8x8.yaml -o " + out.string() + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ASSERT_EQ(runCli("view " + out.string()).exitCode, 0);
  const nlohmann::json page = pageData(fileBytes((out / "view.html").string()));
  const io::NpyArray d = io::readNpy(out / "zone_distance.npy");
  bool found = false;
  for (const auto& m : page["lidars"]) {
    if (m["name"] != "zone_distance") continue;
    found = true;
    const std::vector<double> v = decoded(m);
    ASSERT_EQ(v.size(), d.data.size());
    const double step = (m["hi"].get<double>() - m["lo"].get<double>()) / 65534.0;
    for (std::size_t i = 0; i < v.size(); ++i) EXPECT_NEAR(v[i], d.data[i], step / 2 + 1e-6) << i;
  }
  EXPECT_TRUE(found);
}

TEST_F(ViewerPageTest, AFolderThatIsNotAnOutputIsALocatedErrorAndWritesNothing) {
  const CommandResult empty = runCli("view " + dir_.string());
  EXPECT_EQ(empty.exitCode, 1);
  EXPECT_NE(empty.output.find(dir_.string() + ": not a tofsim output folder"), std::string::npos)
      << empty.output;
  // A folder of outputs (a batch's): the error names one to view.
  fs::create_directories(dir_ / "batch" / "run_a");
  std::ofstream(dir_ / "batch" / "run_a" / "transient.json") << "{}";
  const CommandResult batch = runCli("view " + (dir_ / "batch").string());
  EXPECT_EQ(batch.exitCode, 1);
  EXPECT_NE(batch.output.find("view one, e.g. tofsim view " + (dir_ / "batch" / "run_a").string()),
            std::string::npos)
      << batch.output;
  const CommandResult missing = runCli("view " + (dir_ / "nothing").string());
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.output.find("no such folder"), std::string::npos) << missing.output;
  // Metadata that is not JSON, an NLOS capture without its H.npy: each error
  // names the file, and no page appears.
  fs::create_directories(dir_ / "damaged");
  std::ofstream(dir_ / "damaged" / "transient.json") << "{\"time\": ";
  const CommandResult damaged = runCli("view " + (dir_ / "damaged").string());
  EXPECT_EQ(damaged.exitCode, 1);
  EXPECT_NE(damaged.output.find("damaged/transient.json: not a tofsim transient.json"),
            std::string::npos)
      << damaged.output;
  fs::create_directories(dir_ / "nlos");
  std::ofstream(dir_ / "nlos" / "H.json")
      << R"({"time": {"start_s": 0, "bin_width_s": 1e-11, "start_m": 0, "bin_width_m": 0.003}})";
  const CommandResult noH = runCli("view " + (dir_ / "nlos").string());
  EXPECT_EQ(noH.exitCode, 1);
  EXPECT_NE(noH.output.find("nlos/H.npy"), std::string::npos) << noH.output;
  for (const std::string& file : visibleFiles(dir_)) {
    EXPECT_EQ(file.find("view.html"), std::string::npos) << file;  // nor a temporary
  }
}

}  // namespace
}  // namespace tofsim::test
