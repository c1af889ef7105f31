// Nothing stale, nothing lost: a render into a folder that holds results
// replaces them only when its own set is complete. SIGINT or SIGKILL at any
// point of a re-render (during the gather, while the volume streams to disk,
// during the video) leaves the earlier files byte-identical; a second writer
// into the same folder fails at once naming the holder; sensors no longer
// configured go only when the new set lands; a dead writer's staging folder
// is cleaned by the next run.

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <thread>

#include "hardening/SpawnCli.h"
#include "pipeline/CliRun.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::string kSmall =
    " --set camera.resolution=[24,24] --set time.bins=200 --set render.shadow_map_resolution=256"
    " --set render.indirect.rsm_resolution=8 --set render.indirect.points_per_vpl=200"
    " --set sensors.0.bins=200 --set sensors.0.plot_pixels=[[12,12],[4,12]]"
    " --set sensors.1.bins=200 --set sensors.1.rows=[6,18] -q";
// Several seconds on llvmpipe, streaming in many segments, then a long video:
// each phase lasts long enough for a signal to land inside it.
const std::string kSlow =
    " --set camera.resolution=[128,128] --set time.bins=700 --set render.memory_budget='64 MiB'"
    " --set output.video_stride=1 --set sensors=[] --set render.seed=99 -q";

using Snapshot = std::map<std::string, std::string>;  // visible file -> bytes

Snapshot snapshot(const fs::path& dir) {
  Snapshot s;
  for (const std::string& f : test::visibleFiles(dir)) s[f] = test::fileBytes((dir / f).string());
  return s;
}

// The staging folder a writer of `out` makes beside it.
std::vector<fs::path> stagingFolders(const fs::path& out) {
  std::vector<fs::path> found;
  const std::string prefix = "." + out.filename().string() + ".tofsim-staging-";
  for (const auto& e : fs::directory_iterator(out.parent_path())) {
    if (e.path().filename().string().rfind(prefix, 0) == 0) found.push_back(e.path());
  }
  return found;
}

// A file in any staging folder of `out` whose name contains `part` and whose
// size is at least `bytes`.
bool stagingHolds(const fs::path& out, const std::string& part, std::uintmax_t bytes) {
  for (const fs::path& staging : stagingFolders(out)) {
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(staging, ec)) {
      if (e.path().filename().string().find(part) == std::string::npos) continue;
      if (e.is_regular_file(ec) && e.file_size(ec) >= bytes) return true;
    }
  }
  return false;
}

bool waitFor(const std::function<bool()>& condition, double seconds) {
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < end) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

class OutputIntegrityGLTest : public test::TempDirTest {
 protected:
  fs::path renderEarlierSet() {
    const fs::path out = dir_ / "out";
    const test::CommandResult r =
        test::runCli("render " + test::kCornellConfig + " -o " + out.string() + kSmall);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return out;
  }

  // Re-renders into `out`, sends `signal` once `phase` holds, and checks that
  // the earlier set is exactly what it was.
  void interruptReRender(const fs::path& out, int signal, const std::string& what,
                         const std::function<bool()>& phase) {
    const Snapshot before = snapshot(out);
    ASSERT_FALSE(before.empty());
    const pid_t pid = test::spawnCli(
        "render " + test::kCornellConfig + " -o " + out.string() + kSlow, (dir_ / "log").string());
    const bool reached = waitFor(phase, 60.0);
    ::kill(pid, signal);
    const int code = test::waitCli(pid);
    ASSERT_TRUE(reached) << what << " never came: " << test::fileBytes((dir_ / "log").string());
    EXPECT_EQ(code, 128 + signal) << what << ": " << test::fileBytes((dir_ / "log").string());
    const Snapshot after = snapshot(out);
    EXPECT_EQ(after.size(), before.size()) << what;
    for (const auto& [name, bytes] : before) {
      EXPECT_TRUE(after.count(name) && after.at(name) == bytes) << what << ": " << name;
    }
  }

  void interruptAtEveryPhase(int signal) {
    const fs::path out = renderEarlierSet();
    interruptReRender(out, signal, "during the gather",
                      [&] { return !stagingFolders(out).empty(); });
    interruptReRender(out, signal, "while the volume is written",
                      [&] { return stagingHolds(out, "transient.npy", 8u << 20); });
    interruptReRender(out, signal, "during the video", [&] { return stagingHolds(out, "mp4", 1); });
  }
};

TEST_F(OutputIntegrityGLTest, SigintDuringAReRenderKeepsTheEarlierFiles) {
  interruptAtEveryPhase(SIGINT);
  EXPECT_TRUE(stagingFolders(dir_ / "out").empty()) << "an interrupted run removes its staging";
}

TEST_F(OutputIntegrityGLTest, SigkillDuringAReRenderKeepsTheEarlierFilesAndTheNextRunCleansUp) {
  interruptAtEveryPhase(SIGKILL);
  const fs::path out = dir_ / "out";
  EXPECT_FALSE(stagingFolders(out).empty()) << "kill -9 cannot clean up";
  const test::CommandResult r = test::runCli("render " + test::kCornellConfig + " -o " +
                                             out.string() + kSmall + " --set render.seed=5");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(stagingFolders(out).empty()) << "the next writer removes dead staging folders";
  EXPECT_NE(test::fileBytes((out / "transient.json").string()).find("\"seed\": 5"),
            std::string::npos);
}

TEST_F(OutputIntegrityGLTest, ASecondWriterFailsAtOnceNamingTheHolder) {
  const fs::path out = dir_ / "out";
  const pid_t first = test::spawnCli("render " + test::kCornellConfig + " -o " + out.string() +
                                         kSlow + " --set output.video=false",
                                     (dir_ / "log").string());
  ASSERT_TRUE(waitFor([&] { return !stagingFolders(out).empty(); }, 60.0));
  const auto started = Clock::now();
  const test::CommandResult second = test::runCli("render " + test::kCornellConfig + " -o " +
                                                  out.string() + kSmall + " --set render.seed=7");
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - started).count(), 10.0);
  EXPECT_EQ(second.exitCode, 1) << second.output;
  EXPECT_NE(second.output.find("pid " + std::to_string(first)), std::string::npos) << second.output;
  EXPECT_NE(second.output.find(out.string()), std::string::npos) << second.output;
  ASSERT_EQ(test::waitCli(first), 0) << test::fileBytes((dir_ / "log").string());
  // Everything in the folder is the first run's.
  EXPECT_NE(test::fileBytes((out / "transient.json").string()).find("\"seed\": 99"),
            std::string::npos);
  EXPECT_NE(test::fileBytes((out / "config.effective.yaml").string()).find("seed: 99"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(out / "transient.mp4"));
}

TEST_F(OutputIntegrityGLTest, SensorsNoLongerConfiguredGoOnlyWhenTheNewSetLands) {
  const fs::path out = renderEarlierSet();
  ASSERT_TRUE(fs::exists(out / "sensors" / "spad"));
  interruptReRender(out, SIGINT, "a re-render without sensors",
                    [&] { return !stagingFolders(out).empty(); });
  EXPECT_TRUE(fs::exists(out / "sensors" / "spad"));
  const test::CommandResult r = test::runCli("render " + test::kCornellConfig + " -o " +
                                             out.string() + kSmall + " --set sensors=[]");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_FALSE(fs::exists(out / "sensors"));
  EXPECT_TRUE(fs::exists(out / "transient.npy"));
}

TEST_F(OutputIntegrityGLTest, SenseReplacesTheSensorsAndKeepsTheRender) {
  const fs::path out = renderEarlierSet();
  const std::string volume = test::fileBytes((out / "transient.npy").string());
  const test::CommandResult r =
      test::runCli("sense " + test::kCornellConfig + " --volume " + out.string() + " -q" +
                   " --set 'sensors=[{type: streak, name: only, rows: [12]}]'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_FALSE(fs::exists(out / "sensors" / "spad")) << "the earlier sensors are replaced";
  EXPECT_TRUE(fs::exists(out / "sensors" / "only"));
  EXPECT_EQ(test::fileBytes((out / "transient.npy").string()), volume);
}

TEST_F(OutputIntegrityGLTest, OutputsOverMaxBytesFailBeforeRendering) {
  const fs::path out = dir_ / "out";
  const auto started = Clock::now();
  // 48 x 48 pixels x 2^20 bins x 3 channels x 4 B = 27 GiB per volume file.
  const test::CommandResult r =
      test::runCli("render " + test::kCornellConfig + " -o " + out.string() +
                   " --set camera.resolution=[48,48] --set time.bins=1048576 --set sensors=[]"
                   " --set output.max_bytes='16 GiB' --set output.components=[]");
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - started).count(), 5.0);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(
      r.output.find("output.max_bytes: the outputs need about 27.4 GiB: transient.npy 27.0 GiB"),
      std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("time.bins"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out)) << "nothing is written";
}

}  // namespace
}  // namespace tofsim
