// Work refused or stopped before it starts, through the CLI (issue 39): a
// large sweep's dry run is interrupted with 130 like any batch (its runs'
// configs are checked one by one, which for 90000 runs takes minutes),
// --jobs says its real range, compare's -o names itself when a file is in the
// way, and validate refuses an NLOS scan that cannot fit. Nothing renders.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <string>
#include <thread>

#include "batch/BatchTestSupport.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

using Clock = std::chrono::steady_clock;

class BoundsCliTest : public test::TempDirTest {};

// "key: [1, .., n]".
std::string valuesList(const std::string& key, int n) {
  std::string list = "    " + key + ": [";
  for (int i = 0; i < n; ++i) list += (i ? ", " : "") + std::to_string(i + 1);
  return list + "]\n";
}

TEST_F(BoundsCliTest, AnInterruptedDryRunExits130) {
  const std::string batch = test::writeBatchFile(
      dir_, test::kCornellConfig,
      "sweep:\n  product:\n" + valuesList("render.seed", 300) + valuesList("time.bins", 300));
  const std::string cli = test::cliPath();
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (!std::freopen("/dev/null", "w", stdout)) ::_exit(126);
    ::execl(cli.c_str(), cli.c_str(), "batch", batch.c_str(), "--dry-run", "-q",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));  // into its checks
  ::kill(pid, SIGINT);
  int status = 0;
  const auto end = Clock::now() + std::chrono::seconds(15);
  while (::waitpid(pid, &status, WNOHANG) != pid) {
    if (Clock::now() > end) {  // still going: the interrupt was not heard
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      FAIL() << "the dry run went on for 15 s after SIGINT";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
}

TEST_F(BoundsCliTest, JobsOutOfRangeSaysTheRange) {
  const std::string batch = test::writeBatchFile(dir_, test::kCornellConfig, "");
  const test::CommandResult r = test::runCli("batch " + batch + " --dry-run --jobs 0");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.output.find("--jobs: Value 0 not in range 1 to 256"), std::string::npos) << r.output;
  EXPECT_LT(r.output.size(), 200u) << r.output;  // no 300-digit bound
}

TEST_F(BoundsCliTest, CompareIntoAFileNamesTheOption) {
  const std::string file = (dir_ / "taken.txt").string();
  std::ofstream(file) << "x";
  const test::CommandResult r =
      test::runCli("compare " + (dir_ / "a").string() + " " + (dir_ / "b").string() + " -o " + file);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.output.find("-o/--output: " + file + " is a file, not a folder"), std::string::npos)
      << r.output;
}

// 4096 x 4096 wall points: H alone is 8 GiB at 128 bins, against the default
// 512 MiB budget; validate says so (it said ok, and a render ran out of memory
// naming camera.resolution).
TEST_F(BoundsCliTest, ValidateRefusesAnNlosScanOverTheMemoryBudget) {
  const std::string config = std::string(TOFSIM_SOURCE_DIR) + "/configs/nlos_single.yaml";
  const test::CommandResult r = test::runCli(
      "validate " + config + " --set 'nlos.sensor_grid=[4096, 4096]' --set time.bins=128");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  for (const char* words : {"nlos_single.yaml: render.memory_budget: the NLOS scan holds about",
                            "nlos.sensor_grid", "time.bins", "over render.memory_budget"}) {
    EXPECT_NE(r.output.find(words), std::string::npos) << words << "\n" << r.output;
  }
  EXPECT_EQ(r.output.find("camera.resolution"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace tofsim
