// `tofsim batch` resume keyed on content (issue 11): a run is redone exactly
// when its effective config, its scene's bytes or the tofsim version differ
// from what its manifest records; `--dry-run` says which and why. Two
// batches over one output tree share it without harm.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include "batch/BatchTestSupport.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;
using test::runCli;
using test::stateOf;

class BatchResumeGLTest : public test::TempDirTest {
 protected:
  fs::path manifest(const std::string& run) const { return dir_ / "out" / run / "manifest.json"; }
  std::string manifestText(const std::string& run) const {
    return test::fileBytes(manifest(run).string());
  }
};

TEST_F(BatchResumeGLTest, SetChangeRedoesExactlyThatRun) {
  const std::string runs =
      "runs:\n  - name: a\n    set: {render.seed: 1}\n  - name: b\n    set: {time.bins: 40}\n";
  std::string batch = test::writeBatchFile(dir_, test::kCornellConfig, test::kTinyRunSet + runs);
  CommandResult r = runCli("batch " + batch + " --jobs 2 -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(manifestText("a").find("\"inputs\""), std::string::npos) << manifestText("a");
  const auto aTime = fs::last_write_time(manifest("a"));
  const auto bTime = fs::last_write_time(manifest("b"));

  r = runCli("batch " + batch + " --dry-run");
  EXPECT_EQ(stateOf(r.output, "a"), "done") << r.output;
  EXPECT_EQ(stateOf(r.output, "b"), "done") << r.output;

  // b's own `set:` changes; a's effective config does not.
  batch = test::writeBatchFile(dir_, test::kCornellConfig,
                               test::kTinyRunSet + std::string("runs:\n  - name: a\n    set: "
                                                               "{render.seed: 1}\n  - name: b\n "
                                                               "   set: {time.bins: 30}\n"));
  r = runCli("batch " + batch + " --dry-run");
  EXPECT_EQ(stateOf(r.output, "a"), "done") << r.output;
  EXPECT_EQ(stateOf(r.output, "b"), "stale (config changed)") << r.output;
  r = runCli("batch " + batch + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(stateOf(r.output, "a"), "skipped") << r.output;
  EXPECT_EQ(stateOf(r.output, "b"), "done") << r.output;
  EXPECT_EQ(fs::last_write_time(manifest("a")), aTime);
  EXPECT_NE(fs::last_write_time(manifest("b")), bTime);
  EXPECT_NE(test::fileBytes((dir_ / "out/b/config.effective.yaml").string()).find("bins: 30"),
            std::string::npos);

  // Unchanged: nothing is recomputed.
  r = runCli("batch " + batch + " -q");
  EXPECT_EQ(stateOf(r.output, "a"), "skipped") << r.output;
  EXPECT_EQ(stateOf(r.output, "b"), "skipped") << r.output;

  // The CLI's --set is part of every run's config.
  // Keyed on content, not on the text of the overrides: the seed is already 1.
  r = runCli("batch " + batch + " --dry-run --set render.seed=1");
  EXPECT_EQ(stateOf(r.output, "a"), "done") << r.output;
  EXPECT_EQ(stateOf(r.output, "b"), "done") << r.output;
  r = runCli("batch " + batch + " --dry-run --set render.indirect.points_per_vpl=90");
  EXPECT_EQ(stateOf(r.output, "a"), "stale (config changed)") << r.output;
  EXPECT_EQ(stateOf(r.output, "b"), "stale (config changed)") << r.output;

  // A manifest of an older tofsim (no inputs), another version, a lost file.
  std::ofstream(manifest("a")) << R"({"run": "a", "hash": "fnv1a64", "files": []})";
  const std::string bText = manifestText("b");
  std::ofstream(manifest("b")) << std::regex_replace(bText, std::regex("\"version\": \"[^\"]*\""),
                                                     "\"version\": \"0.0.0-old\"");
  r = runCli("batch " + batch + " --dry-run");
  EXPECT_EQ(stateOf(r.output, "a"), "stale (no inputs recorded)") << r.output;
  EXPECT_EQ(stateOf(r.output, "b"), "stale (version changed)") << r.output;
  std::ofstream(manifest("b")) << bText;
  fs::remove(dir_ / "out/b/transient.npy");
  r = runCli("batch " + batch + " --dry-run");
  EXPECT_EQ(stateOf(r.output, "b"), "incomplete (missing transient.npy)") << r.output;
  EXPECT_NE(r.output.find("0 done, 2 to run"), std::string::npos) << r.output;
}

TEST_F(BatchResumeGLTest, SceneChangeRedoesEveryRun) {
  // A private copy of the demo, so the test may change the scene's bytes.
  fs::create_directories(dir_ / "scenes");
  fs::copy_file(fs::path(TOFSIM_SOURCE_DIR) / "configs/cornell_box.yaml", dir_ / "cornell.yaml");
  fs::copy_file(fs::path(TOFSIM_SOURCE_DIR) / "configs/scenes/cornell_box.gltf",
                dir_ / "scenes/cornell_box.gltf");
  const std::string batch = test::writeBatchFile(
      dir_, "cornell.yaml",
      test::kTinyRunSet + std::string("sweep:\n  zip:\n    render.seed: [1, 2]\n"));
  CommandResult r = runCli("batch " + batch + " --jobs 2 -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string names[] = {"run0000_seed-1", "run0001_seed-2"};

  std::ofstream(dir_ / "scenes/cornell_box.gltf", std::ios::app) << "\n";  // same scene, new bytes
  r = runCli("batch " + batch + " --dry-run");
  for (const std::string& n : names)
    EXPECT_EQ(stateOf(r.output, n), "stale (scene changed)") << r.output;
  r = runCli("batch " + batch + " --jobs 2 -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const std::string& n : names) EXPECT_EQ(stateOf(r.output, n), "done") << r.output;
  r = runCli("batch " + batch + " --dry-run");
  for (const std::string& n : names) EXPECT_EQ(stateOf(r.output, n), "done") << r.output;
}

TEST_F(BatchResumeGLTest, TwoBatchesShareOneOutputTree) {
  const std::string batch = test::writeBatchFile(
      dir_, test::kCornellConfig,
      test::kTinyRunSet + std::string("sweep:\n  zip:\n    render.seed: [1, 2, 3, 4]\n"));
  CommandResult first, second;
  std::thread other([&] { second = runCli("batch " + batch + " --jobs 2 -q"); });
  first = runCli("batch " + batch + " --jobs 2 -q");
  other.join();
  for (const CommandResult* r : {&first, &second}) {
    // Each renders some runs and waits for the other's: both end with all done.
    EXPECT_EQ(r->exitCode, 0) << r->output;
    for (int i = 1; i <= 4; ++i) {
      const std::string status =
          stateOf(r->output, "run000" + std::to_string(i - 1) + "_seed-" + std::to_string(i));
      EXPECT_TRUE(status == "done" || status == "skipped") << r->output;
    }
    EXPECT_EQ(r->output.find("filesystem error"), std::string::npos) << r->output;
    EXPECT_NE(r->output.find(" 0 failed,"), std::string::npos) << r->output;
  }
  const CommandResult verify = runCli("batch " + batch + " --verify -q");
  EXPECT_EQ(verify.exitCode, 0) << verify.output;
  for (const auto& e : fs::directory_iterator(dir_ / "out")) {
    if (!e.is_directory()) continue;
    const std::string name = e.path().filename().string();
    EXPECT_EQ(stateOf(verify.output, name), "skipped") << verify.output;
    EXPECT_NE(manifestText(name).find("\"transient.npy\""), std::string::npos) << name;
  }
}

}  // namespace
}  // namespace tofsim
