// A capture sequence is one result (issue 39): a re-render swaps its frames
// and its own files in together. SIGINT mid-way through a re-render with a
// new seed leaves the earlier set byte for byte, and a rerun of the new
// inputs completes it without rendering again the frames it finished; a
// rerun with fewer frames leaves no stale frame folder; frames' staging
// folders left by a dead writer go with the next run. Through the CLI on the
// CPU backend ($TOFSIM_TEST_CLI runs them against another build).

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "hardening/SpawnCli.h"
#include "pipeline/CliRun.h"
#include "pipeline/MovingPlaneTest.h"
#include "tofsim/io/Npy.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Snapshot = std::map<std::string, std::string>;  // visible file -> bytes

Snapshot snapshot(const fs::path& dir) {
  Snapshot s;
  for (const std::string& f : test::visibleFiles(dir)) s[f] = test::fileBytes((dir / f).string());
  return s;
}

json jsonOf(const fs::path& file) { return json::parse(test::fileBytes(file.string())); }

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

class SequenceSwapTest : public pipeline::test_sequence::MovingPlaneTest {
 protected:
  void SetUp() override {
    MovingPlaneTest::SetUp();
    writeScene(1.0);
  }
  // A sequence of `frames` frames at 30 Hz (within the animation's second).
  std::string configFile(int frames) {
    const fs::path file = dir_ / ("c" + std::to_string(frames) + ".yaml");
    test::writeText(
        file,
        configYaml("sequence: {rate: 30 Hz, count: " + std::to_string(frames) + "}\n", kTime));
    return file.string();
  }
  std::string renderArgs(int frames, int seed) {
    return "render " + configFile(frames) + " -o " + out().string() +
           " --set render.seed=" + std::to_string(seed);
  }
  test::CommandResult render(int frames, int seed, const std::string& more = " -q") {
    return test::runCli(renderArgs(frames, seed) + more);
  }
  fs::path out() const { return dir_ / "out"; }
};

TEST_F(SequenceSwapTest, SigintDuringAReRenderKeepsTheEarlierSetAndTheRerunResumes) {
  constexpr int kFrames = 12;
  const test::CommandResult first = render(kFrames, 1);
  ASSERT_EQ(first.exitCode, 0) << first.output;
  const Snapshot before = snapshot(out());
  ASSERT_EQ(before.count("frame_00011/frame.json"), 1u);

  // A new seed: every frame is rendered again. SIGINT once the third frame
  // began (frames 0 and 1 are done), long before the last.
  const fs::path log = dir_ / "log";
  const pid_t pid = test::spawnCli(renderArgs(kFrames, 2), log.string());
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (test::fileBytes(log.string()).find("frame 3/12") == std::string::npos &&
         std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(pid, SIGINT);
  const int code = test::waitCli(pid);
  const std::string interrupted = test::fileBytes(log.string());
  ASSERT_NE(interrupted.find("frame 3/12"), std::string::npos) << interrupted;
  ASSERT_EQ(code, 130) << "the run ended before SIGINT came: " << interrupted;

  // "earlier results are unchanged": every file of the earlier set.
  const Snapshot after = snapshot(out());
  EXPECT_EQ(after.size(), before.size());
  for (const auto& [name, bytes] : before) {
    EXPECT_TRUE(after.count(name) && after.at(name) == bytes) << name << " changed";
  }

  // The same new inputs again: the frames the interrupted run finished are kept.
  const test::CommandResult rerun = render(kFrames, 2, "");
  ASSERT_EQ(rerun.exitCode, 0) << rerun.output;
  for (int k = 0; k < 2; ++k) {
    EXPECT_NE(rerun.output.find("frame " + std::to_string(k) + " (t = "), std::string::npos)
        << "frame " << k << " rendered again:\n"
        << rerun.output;
  }
  EXPECT_GE(count(rerun.output, "kept from an earlier run"), 2u) << rerun.output;
  // One result: every frame and the sequence's files are the new run's.
  const json sequence = jsonOf(out() / "sequence.json");
  for (int k = 0; k < kFrames; ++k) {
    const json frame =
        jsonOf(out() / sequence.at("frames").at(k).at("folder").get<std::string>() / "frame.json");
    EXPECT_EQ(frame.at("seed"), sequence.at("frames").at(k).at("seed")) << k;
    EXPECT_EQ(frame.at("run_key"), sequence.at("run_key")) << k;
  }
  EXPECT_NE(before.at("sequence.json"), test::fileBytes((out() / "sequence.json").string()));
  EXPECT_FALSE(fs::exists(out() / ".tofsim-sequence-partial")) << "the swap takes it away";
}

TEST_F(SequenceSwapTest, FewerFramesLeaveNoStaleFrameFolder) {
  ASSERT_EQ(render(3, 1).exitCode, 0);
  ASSERT_TRUE(fs::exists(out() / "frame_00002/frame.json"));
  const test::CommandResult two = render(2, 1);
  ASSERT_EQ(two.exitCode, 0) << two.output;
  EXPECT_FALSE(fs::exists(out() / "frame_00002")) << "a frame of the 3-frame result";
  EXPECT_EQ(jsonOf(out() / "sequence.json").at("count"), 2);
  EXPECT_EQ(io::readNpy(out() / "depth_sequence.npy").shape.at(0), 2u);
}

TEST_F(SequenceSwapTest, FramesStagingLeftByADeadWriterGoWithTheNextRun) {
  ASSERT_EQ(render(3, 1).exitCode, 0);
  // What kill -9 (or an abort) during a frame leaves: that frame's staging
  // folder, where frames were rendered before (beside them in the
  // sequence's folder) and where they are now (the partial folder); a frame
  // past the next run's count too.
  const std::vector<fs::path> dead = {
      out() / ".frame_00000.tofsim-staging-999999", out() / ".frame_00005.tofsim-staging-999999",
      out() / ".tofsim-sequence-partial" / ".frame_00001.tofsim-staging-999999"};
  for (const fs::path& d : dead) {
    fs::create_directories(d);
    test::writeText(d / "transient.npy", "half");
  }
  // The same inputs: every frame is kept, nothing is rendered.
  const test::CommandResult again = render(3, 1);
  ASSERT_EQ(again.exitCode, 0) << again.output;
  for (const fs::path& d : dead) EXPECT_FALSE(fs::exists(d)) << d;
}

}  // namespace
}  // namespace tofsim
