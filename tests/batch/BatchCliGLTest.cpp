// `tofsim batch` end to end through the CLI (renders on llvmpipe): resume
// after a simulated crash, shards, a failing run among good ones; and the
// transient video read back with OpenCV.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/videoio.hpp>
#include <set>
#include <sstream>

#include "batch/BatchTestSupport.h"
#include "pipeline/CliRun.h"
#include "support/TempDir.h"
#include "tofsim/imaging/Video.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;
using test::runCli;

const char* const kTiny = test::kTinyRunSet;

// The status column of `name`'s row in the summary table, or "" when absent.
std::string statusOf(const std::string& output, const std::string& name) {
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream row(line);
    std::string first, status;
    if (row >> first >> status && first == name) return status;
  }
  return "";
}

class BatchCliGLTest : public test::TempDirTest {
 protected:
  std::string writeBatch(const std::string& body) {
    const fs::path path = dir_ / "batch.yaml";
    std::ofstream(path) << "base: " << test::kCornellConfig << "\noutput: out\n" << kTiny << body;
    return path.string();
  }
};

TEST_F(BatchCliGLTest, ResumeRedoesOnlyTheRunWithoutManifest) {
  const std::string batch = writeBatch("sweep:\n  zip:\n    render.seed: [1, 2, 3]\n");
  const std::vector<std::string> names = {"run0000_seed-1", "run0001_seed-2", "run0002_seed-3"};
  CommandResult r = runCli("batch " + batch + " --jobs 2 -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const std::string& n : names) {
    EXPECT_EQ(statusOf(r.output, n), "done") << r.output;
    EXPECT_TRUE(fs::exists(dir_ / "out" / n / "manifest.json"));
    EXPECT_TRUE(fs::exists(dir_ / "out" / n / "config.effective.yaml"));
    EXPECT_TRUE(fs::exists(dir_ / "out" / n / "log.txt"));
  }
  // A crash of run 1 after its outputs, before its manifest; and a stray
  // partial file that the redo's manifest must not list.
  fs::remove(dir_ / "out" / names[1] / "manifest.json");
  std::ofstream(dir_ / "out" / names[1] / "stray.tmp") << "partial";
  r = runCli("batch " + batch + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(statusOf(r.output, names[0]), "skipped") << r.output;
  EXPECT_EQ(statusOf(r.output, names[1]), "done") << r.output;
  EXPECT_EQ(statusOf(r.output, names[2]), "skipped") << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "out" / names[1] / "manifest.json"));
  EXPECT_EQ(test::fileBytes((dir_ / "out" / names[1] / "manifest.json").string()).find("stray"),
            std::string::npos);

  // A truncated output (size differs from the manifest) is incomplete too.
  fs::resize_file(dir_ / "out" / names[2] / "transient.npy", 100);
  r = runCli("batch " + batch + " -q");
  EXPECT_EQ(statusOf(r.output, names[0]), "skipped") << r.output;
  EXPECT_EQ(statusOf(r.output, names[2]), "done") << r.output;
}

TEST_F(BatchCliGLTest, ShardsPartitionTheRunsExactly) {
  const std::string batch =
      writeBatch("sweep:\n  product:\n    render.seed: [1, 2, 3, 4]\n    time.bins: [30, 40]\n");
  std::multiset<std::string> seen;
  for (int k = 1; k <= 3; ++k) {
    const CommandResult r =
        runCli("batch " + batch + " --dry-run --shard " + std::to_string(k) + "/3");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (int i = 0; i < 8; ++i) {
      char prefix[16];
      std::snprintf(prefix, sizeof prefix, "run%04d_", i);
      const std::size_t at = r.output.find(prefix);
      if (at == std::string::npos) continue;
      EXPECT_EQ(i % 3, k - 1) << r.output;
      seen.insert(prefix);
    }
  }
  EXPECT_EQ(seen.size(), 8u);  // every run in exactly one shard
  EXPECT_EQ(std::set<std::string>(seen.begin(), seen.end()).size(), 8u);
  EXPECT_FALSE(fs::exists(dir_ / "out"));  // a dry run renders nothing

  // One real shard renders only its runs.
  const CommandResult r = runCli("batch " + batch + " --shard 3/3 -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::size_t runDirs = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "out")) runDirs += e.is_directory() ? 1 : 0;
  EXPECT_EQ(runDirs, 2u);  // runs 2 and 5
  EXPECT_TRUE(fs::exists(dir_ / "out" / "run0002_seed-2_bins-30" / "manifest.json"));
}

TEST_F(BatchCliGLTest, FailingRunIsReportedAndTheOthersComplete) {
  // A valid config whose memory budget cannot hold the GL backend's 1024^2
  // cube shadow map: found only when the render plans its GPU memory.
  const std::string batch = writeBatch(
      "runs:\n"
      "  - name: good1\n"
      "  - name: broken\n"
      "    set: {render.memory_budget: 1 MiB, render.shadow_map_resolution: 1024, "
      "render.backend: gl}\n"
      "  - name: good2\n"
      "    set: {render.seed: 5}\n");
  const CommandResult r = runCli("batch " + batch + " --jobs 2 -q");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(statusOf(r.output, "good1"), "done") << r.output;
  EXPECT_EQ(statusOf(r.output, "broken"), "failed") << r.output;
  EXPECT_EQ(statusOf(r.output, "good2"), "done") << r.output;
  EXPECT_NE(r.output.find("memory_budget"), std::string::npos)
      << r.output;  // the reason, from log.txt
  EXPECT_FALSE(fs::exists(dir_ / "out" / "broken" / "manifest.json"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "good2" / "manifest.json"));
}

TEST_F(BatchCliGLTest, InvalidRunConfigStopsTheBatchBeforeRendering) {
  const std::string batch =
      writeBatch("runs:\n  - name: a\n  - name: b\n    set: {time.bins: 0}\n");
  const CommandResult r = runCli("batch " + batch + " -q");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("run b:"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(BatchCliGLTest, VideoHasOneFramePerStrideAndDocumentedSize) {
  const fs::path out = dir_ / "render";
  const CommandResult r = runCli(
      "render " + test::kCornellConfig + " -o " + out.string() +
      " --set camera.resolution=[24,16] --set time.bins=40 --set render.shadow_map_resolution=64"
      " --set render.indirect.rsm_resolution=4 --set sensors=[] --set output.video=true"
      " --set output.video_stride=2 --set output.frame_pngs=true --set output.video_tone_map=log"
      " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const fs::path mp4 = out / "transient.mp4";
  ASSERT_TRUE(fs::exists(mp4)) << r.output;
  cv::VideoCapture video(mp4.string());
  ASSERT_TRUE(video.isOpened());
  const imaging::FrameSize size = imaging::videoFrameSize(24, 16);
  EXPECT_EQ(size.width, 24 * 16);  // k = ceil(256 / 16)
  EXPECT_EQ(size.height, 16 * 16 + 24);
  int frames = 0;
  cv::Mat frame;
  while (video.read(frame)) {
    EXPECT_EQ(frame.cols, size.width);
    EXPECT_EQ(frame.rows, size.height);
    ++frames;
  }
  EXPECT_EQ(frames, 20);
  EXPECT_TRUE(fs::exists(out / "frames" / "frame_00000.png"));
  EXPECT_TRUE(fs::exists(out / "frames" / "frame_00038.png"));
  EXPECT_FALSE(fs::exists(out / "frames" / "frame_00001.png"));
  for (const auto& e : fs::directory_iterator(out)) {
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
  }
}

TEST_F(BatchCliGLTest, InfoDescribesTheCornellBox) {
  const CommandResult r =
      runCli("info " + std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/cornell_box.gltf");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("triangles: 34"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("cornell_camera"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("albedo [0.630, 0.065, 0.050]"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bounds (m)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("lambertian: albedo / pi"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("gltf:       dielectric"), std::string::npos) << r.output;
  const CommandResult glossy =
      runCli("info " + std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/cornell_box_glossy.gltf");
  ASSERT_EQ(glossy.exitCode, 0) << glossy.output;
  EXPECT_NE(glossy.output.find("gltf:       metal: F(albedo) GGX; metallic 1, roughness 0.35"),
            std::string::npos)
      << glossy.output;
  EXPECT_NE(glossy.output.find("albedo / pi (metallic, roughness ignored)"), std::string::npos)
      << glossy.output;
}

}  // namespace
}  // namespace tofsim
