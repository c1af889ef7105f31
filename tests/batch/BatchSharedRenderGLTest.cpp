// Issue 44 item 7: a batch whose runs differ only in their sensors renders
// once (the content key split into render and sense): the other runs copy
// the render's files and sense their own sensors from its volume, with the
// bytes of separate renders; each manifest names the render it used; a
// resumed batch keeps each run's state; and every batch writes its results
// table (results.csv / results.json), one row per run with its swept value
// and its sensors' numbers.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "batch/BatchTestSupport.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::CommandResult;
using test::runCli;
using test::stateOf;

// The demo at 8 x 8 with one CW-ToF sensor, its read noise swept: three runs
// of one render key.
const char* kSet =
    "set:\n"
    "  camera.resolution: [8, 8]\n"
    "  time.bins: 40\n"
    "  render.shadow_map_resolution: 64\n"
    "  render.indirect.rsm_resolution: 4\n"
    "  render.indirect.points_per_vpl: 100\n"
    "  sensors: [{type: cwtof, name: tof, frequencies: [20 MHz]}]\n";
const char* kRunSet =
    "--set camera.resolution=[8,8] --set time.bins=40 --set render.shadow_map_resolution=64 "
    "--set render.indirect.rsm_resolution=4 --set render.indirect.points_per_vpl=100 "
    "--set 'sensors=[{type: cwtof, name: tof, frequencies: [20 MHz]}]' ";

class BatchSharedRenderGLTest : public test::TempDirTest {
 protected:
  std::string writeBatch(const std::string& noises) {
    return test::writeBatchFile(dir_, test::kCornellConfig,
                                std::string(kSet) + "sweep:\n  product:\n    sensors.0.read_noise: " +
                                    noises + "\n");
  }
  json read(const fs::path& file) const {
    std::ifstream in(file);
    return json::parse(in);
  }
  std::string renderFrom(const std::string& run) const {
    return read(dir_ / "out" / run / "manifest.json")["render"]["from"].get<std::string>();
  }
};

TEST_F(BatchSharedRenderGLTest, SensorOnlyRunsRenderOnceWithTheBytesOfSeparateRenders) {
  const std::string batch = writeBatch("[1, 5, 9]");
  const CommandResult r = runCli("batch " + batch + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string runs[] = {"run0000_read_noise-1", "run0001_read_noise-5",
                              "run0002_read_noise-9"};
  // One render: the first run's; the others took it.
  for (const std::string& run : runs) EXPECT_EQ(renderFrom(run), runs[0]) << run;
  const std::string log1 = test::fileBytes((dir_ / "out" / runs[1] / "log.txt").string());
  EXPECT_NE(log1.find("took the render of run 'run0000_read_noise-1'"), std::string::npos) << log1;
  EXPECT_EQ(log1.find("renderer made"), std::string::npos) << log1;
  EXPECT_NE(read(dir_ / "out" / runs[1] / "manifest.json")["inputs"]["sense"],
            read(dir_ / "out" / runs[2] / "manifest.json")["inputs"]["sense"]);

  // The same files and bytes as `tofsim render` of the run's config (but
  // transient.json's timings and the batch's own files).
  const CommandResult alone =
      runCli("render " + test::kCornellConfig + " " + kRunSet +
             "--set sensors.0.read_noise=9 -q -o " + (dir_ / "alone").string());
  ASSERT_EQ(alone.exitCode, 0) << alone.output;
  const fs::path shared = dir_ / "out" / runs[2];
  std::vector<std::string> files = test::visibleFiles(shared);
  std::erase_if(files, [](const std::string& f) { return f == "manifest.json" || f == "log.txt"; });
  EXPECT_EQ(files, test::visibleFiles(dir_ / "alone"));
  EXPECT_GT(files.size(), 20u);
  for (const std::string& f : files) {
    if (f == "transient.json") {
      json a = read(shared / f), b = read(dir_ / "alone" / f);
      a.erase("stats");
      b.erase("stats");
      EXPECT_EQ(a, b);
      continue;
    }
    EXPECT_TRUE(test::fileBytes((shared / f).string()) ==
                test::fileBytes((dir_ / "alone" / f).string()))
        << f;
  }

  // The results table: a row per run with its swept value and numbers.
  const json results = read(dir_ / "out" / "results.json");
  ASSERT_EQ(results["runs"].size(), 3u);
  const json& row = results["runs"][2];
  EXPECT_EQ(row["run"], runs[2]);
  EXPECT_EQ(row["status"], "done");
  EXPECT_EQ(row["swept"]["sensors.0.read_noise"], "9");
  EXPECT_EQ(row["render_from"], runs[0]);
  const double valid = row["sensors"]["tof"]["cwtof_depth"]["valid_fraction"].get<double>();
  EXPECT_GT(valid, 0.5);
  EXPECT_LE(valid, 1.0);
  EXPECT_TRUE(row["sensors"]["tof"]["cwtof_mpi_error"].contains("mean_abs"));
  std::ifstream csv(dir_ / "out" / "results.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("run,status,seconds,directory,render_from,sensors.0.read_noise,", 0), 0u)
      << header;
  EXPECT_NE(header.find("tof/cwtof_depth:valid_fraction"), std::string::npos) << header;
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 3);
}

TEST_F(BatchSharedRenderGLTest, AResumedBatchKeepsEachRunsStateAndItsTable) {
  ASSERT_EQ(runCli("batch " + writeBatch("[1, 5]") + " -q").exitCode, 0);
  // The render's run is gone and a sensor value is added: the second is done
  // (its own copies), and the first and the new one take its render: no
  // render at all.
  fs::remove_all(dir_ / "out" / "run0000_read_noise-1");
  const CommandResult r = runCli("batch " + writeBatch("[1, 5, 9]") + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(stateOf(r.output, "run0000_read_noise-1"), "done") << r.output;
  EXPECT_EQ(stateOf(r.output, "run0001_read_noise-5"), "skipped") << r.output;
  EXPECT_EQ(stateOf(r.output, "run0002_read_noise-9"), "done") << r.output;
  EXPECT_EQ(renderFrom("run0000_read_noise-1"), "run0001_read_noise-5");
  EXPECT_EQ(renderFrom("run0002_read_noise-9"), "run0001_read_noise-5");
  const std::string log0 = test::fileBytes((dir_ / "out/run0000_read_noise-1/log.txt").string());
  EXPECT_EQ(log0.find("renderer made"), std::string::npos) << log0;
  const json results = read(dir_ / "out" / "results.json");
  ASSERT_EQ(results["runs"].size(), 3u);
  EXPECT_EQ(results["runs"][1]["status"], "skipped");
  EXPECT_TRUE(results["runs"][1]["sensors"]["tof"].contains("cwtof_depth"));
  // Unchanged: every run skipped, none rendered.
  const CommandResult again = runCli("batch " + writeBatch("[1, 5, 9]") + " --dry-run");
  EXPECT_EQ(stateOf(again.output, "run0002_read_noise-9"), "done") << again.output;
}

// Issue 44 item 7's own sweep: the kinect-v2 preset's frequencies swept
// over a render that saves no volume (output.transient: false) and has a
// lens PSF, which the CW-ToF sensor applies to its raws (PsfPath::Raws).
// The batch saves the light before the PSF for the other run (a hidden
// folder, gone at the end); that run's sensors apply the PSF to their raws
// as a render does: one render, and the bytes of a separate render.
TEST_F(BatchSharedRenderGLTest, AKinectV2FrequencySweepWithALensPsfAndNoSavedVolumeRendersOnce) {
  const std::string set =
      "set:\n"
      "  camera.resolution: [8, 8]\n"
      "  camera.psf: {core_sigma: 0.6, halo_weight: 0.04, halo_profile: exponential, "
      "halo_radius: 3}\n"
      "  time.bins: 40\n"
      "  time.bin_width: 50 ps\n"
      "  render.shadow_map_resolution: 64\n"
      "  render.indirect.rsm_resolution: 4\n"
      "  render.indirect.points_per_vpl: 100\n"
      "  output: {transient: false, components: [], video: false}\n"
      "  sensors: [{type: cwtof, name: kinect, preset: kinect-v2, channel: 0}]\n";
  const std::string batch = test::writeBatchFile(
      dir_, test::kCornellConfig,
      set + "sweep:\n  product:\n    sensors.0.frequencies: [40 MHz, [20 MHz, 100 MHz]]\n");
  const CommandResult r = runCli("batch " + batch + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string runs[] = {"run0000_frequencies-40MHz", "run0001_frequencies-20MHz,100MHz"};
  // One render: only the first run's log says its renderer was made.
  int renders = 0;
  for (const std::string& run : runs) {
    EXPECT_EQ(renderFrom(run), runs[0]) << run;
    const std::string log = test::fileBytes((dir_ / "out" / run / "log.txt").string());
    renders += log.find("renderer made") != std::string::npos ? 1 : 0;
  }
  EXPECT_EQ(renders, 1);
  // The saved volume is the batch's, not a run's: gone with the batch.
  for (const auto& e : fs::directory_iterator(dir_ / "out")) {
    EXPECT_EQ(e.path().filename().string().rfind(".shared-volumes", 0), std::string::npos)
        << e.path();
  }
  EXPECT_FALSE(fs::exists(dir_ / "out" / runs[1] / "transient.npy"));

  const CommandResult alone = runCli(
      "render " + test::kCornellConfig +
      " --set camera.resolution=[8,8] --set 'camera.psf={core_sigma: 0.6, halo_weight: 0.04, "
      "halo_profile: exponential, halo_radius: 3}' --set time.bins=40 --set 'time.bin_width=50 "
      "ps' --set render.shadow_map_resolution=64 --set render.indirect.rsm_resolution=4 --set "
      "render.indirect.points_per_vpl=100 --set 'output={transient: false, components: [], "
      "video: false}' --set 'sensors=[{type: cwtof, name: kinect, preset: kinect-v2, channel: "
      "0, frequencies: [20 MHz, 100 MHz]}]' -q -o " +
      (dir_ / "alone").string());
  ASSERT_EQ(alone.exitCode, 0) << alone.output;
  const fs::path shared = dir_ / "out" / runs[1];
  std::vector<std::string> files = test::visibleFiles(shared);
  std::erase_if(files, [](const std::string& f) { return f == "manifest.json" || f == "log.txt"; });
  EXPECT_EQ(files, test::visibleFiles(dir_ / "alone"));
  EXPECT_GT(files.size(), 40u);  // the raws, the maps with cwtof_psf_error, their pictures
  for (const std::string& f : files) {
    EXPECT_TRUE(test::fileBytes((shared / f).string()) ==
                test::fileBytes((dir_ / "alone" / f).string()))
        << f;
  }
}

// A lidar's runs save waveforms.npy, not the camera volume a shared render's
// sensors read: a sweep over its sensors renders each run (on 05d73fe the
// second run took the first's render and failed on a missing transient.json).
TEST_F(BatchSharedRenderGLTest, ALidarsSensorSweepRendersEachRun) {
  const std::string batch = test::writeBatchFile(
      dir_, std::string(TOFSIM_SOURCE_DIR) + "/configs/lidar_street.yaml",
      "set:\n"
      "  lidar.azimuth: {start: 0, end: 40, step: 2}\n"
      "  lidar.plot_beams: []\n"
      "  sensors: [{type: spad, name: s}]\n"
      "sweep:\n  product:\n    sensors.0.jitter_fwhm: [30 ps, 60 ps]\n");
  const CommandResult r = runCli("batch " + batch + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(renderFrom("run0001_jitter_fwhm-60ps"), "run0001_jitter_fwhm-60ps");
}

}  // namespace
}  // namespace tofsim
