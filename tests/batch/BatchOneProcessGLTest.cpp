// `tofsim batch` renders its runs on worker processes that keep the scene and
// the renderer loaded (issue 45 item 4): each run's folder holds the bytes a
// standalone `tofsim render` of that run writes, on both IR backends; the
// scene is loaded once per worker (its log.txt says so); and a run that fails
// does not stop the ones after it on the same worker.

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "batch/BatchTestSupport.h"
#include "pipeline/CliRun.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;
using test::runCli;

// kTinyRunSet's keys as --set arguments of a standalone render.
const char* const kTinySets =
    " --set camera.resolution=[16,16] --set time.bins=40 --set render.shadow_map_resolution=64"
    " --set render.indirect.rsm_resolution=4 --set render.indirect.points_per_vpl=100"
    " --set sensors=[]";

// transient.json with the render's timings taken out: the only bytes that
// differ between two renders of one config.
std::string withoutTimings(std::string json) {
  json = std::regex_replace(json, std::regex(R"("pass_seconds": \{[^}]*\})"), "");
  return std::regex_replace(json, std::regex(R"("seconds": [-+0-9.eE]+)"), "");
}

// Every file of the standalone render `reference` is in `run` with the same
// bytes; the run has its log.txt and manifest.json besides.
void expectSameOutputs(const fs::path& run, const fs::path& reference) {
  const std::vector<std::string> want = test::visibleFiles(reference);
  std::vector<std::string> got = test::visibleFiles(run);
  std::erase_if(got, [](const std::string& f) { return f == "log.txt" || f == "manifest.json"; });
  ASSERT_EQ(got, want) << run;
  ASSERT_GT(want.size(), 8u);
  for (const std::string& f : want) {
    std::string a = test::fileBytes((run / f).string());
    std::string b = test::fileBytes((reference / f).string());
    if (f == "transient.json") {
      a = withoutTimings(a);
      b = withoutTimings(b);
    }
    EXPECT_TRUE(a == b) << run / f << " differs from the standalone render's";
  }
}

class BatchOneProcessGLTest : public test::TempDirTest {};

TEST_F(BatchOneProcessGLTest, RunsEqualStandaloneRendersAndTheSceneLoadsOnce) {
  const std::string batch = test::writeBatchFile(
      dir_, test::kCornellConfig,
      std::string(test::kTinyRunSet) +
          "sweep:\n  product:\n    render.backend: [cpu, gl]\n    render.seed: [1, 2]\n");
  const CommandResult r = runCli("batch " + batch + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"run0000_backend-cpu_seed-1", "--set render.backend=cpu --set render.seed=1"},
      {"run0001_backend-cpu_seed-2", "--set render.backend=cpu --set render.seed=2"},
      {"run0002_backend-gl_seed-1", "--set render.backend=gl --set render.seed=1"},
      {"run0003_backend-gl_seed-2", "--set render.backend=gl --set render.seed=2"}};
  for (const auto& [name, sets] : runs) {
    const fs::path reference = dir_ / ("standalone_" + name);
    const CommandResult s = runCli("render " + test::kCornellConfig + " -o " +
                                   reference.string() + kTinySets + " " + sets + " -q");
    ASSERT_EQ(s.exitCode, 0) << s.output;
    expectSameOutputs(dir_ / "out" / name, reference);
  }
  // One worker: the scene loaded by the first run and kept; the renderer made
  // again (and the scene prepared again) only where the backend changed.
  const auto log = [&](const std::string& name) {
    return test::fileBytes((dir_ / "out" / name / "log.txt").string());
  };
  EXPECT_NE(log(runs[1].first).find("scene loaded 1 time(s), renderer made 1 time(s), scene "
                                    "prepared 1 time(s)"),
            std::string::npos)
      << log(runs[1].first);
  EXPECT_NE(log(runs[3].first).find("scene loaded 1 time(s), renderer made 2 time(s), scene "
                                    "prepared 2 time(s)"),
            std::string::npos)
      << log(runs[3].first);
  // The log is a render's: its device and its closing line.
  EXPECT_NE(log(runs[3].first).find("render: device: "), std::string::npos) << log(runs[3].first);
  EXPECT_NE(log(runs[3].first).find("wrote "), std::string::npos) << log(runs[3].first);
}

TEST_F(BatchOneProcessGLTest, AFailedRunDoesNotStopTheRunsAfterItOnItsWorker) {
  // A valid config whose memory budget cannot hold the GL backend's 1024^2
  // cube shadow map: found only when the render plans its GPU memory.
  const std::string batch = test::writeBatchFile(
      dir_, test::kCornellConfig,
      std::string(test::kTinyRunSet) +
          "runs:\n"
          "  - name: good1\n"
          "  - name: broken\n"
          "    set: {render.memory_budget: 1 MiB, render.shadow_map_resolution: 1024, "
          "render.backend: gl}\n"
          "  - name: good2\n"
          "    set: {render.seed: 5}\n");
  const CommandResult r = runCli("batch " + batch + " --jobs 1 -q");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(test::stateOf(r.output, "good1"), "done") << r.output;
  EXPECT_EQ(test::stateOf(r.output, "broken"), "failed") << r.output;
  EXPECT_EQ(test::stateOf(r.output, "good2"), "done") << r.output;
  EXPECT_NE(r.output.find("exit code 1: tofsim: error:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("memory_budget"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "broken" / "manifest.json"));
  const fs::path reference = dir_ / "standalone_good2";
  const CommandResult s = runCli("render " + test::kCornellConfig + " -o " + reference.string() +
                                 kTinySets + " --set render.seed=5 -q");
  ASSERT_EQ(s.exitCode, 0) << s.output;
  expectSameOutputs(dir_ / "out" / "good2", reference);
}

}  // namespace
}  // namespace tofsim
