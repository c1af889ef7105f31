// `tofsim batch` and signals (issue 11): SIGINT or SIGTERM to the batch, or a
// Ctrl-C to its whole process group, stops it with 130 / 143 after its
// children have ended, with the summary table; SIGKILL of the batch ends its
// children too (their parent-death signal). No child outlives the batch.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>
#include <vector>

#include "batch/BatchTestSupport.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The demo at full size without sensors: a few seconds per run on llvmpipe,
// long enough to be caught in the middle.
const char* kSlowRuns =
    "set:\n"
    "  sensors: []\n"
    "sweep:\n"
    "  zip:\n"
    "    render.seed: [1, 2, 3]\n";

// `tofsim <args>` in a process group of its own (so that a signal to the
// group spares the test), stdout and stderr into `log`.
pid_t spawnInOwnGroup(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> all = {test::cliPath()};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    if (!std::freopen(log.c_str(), "w", stdout)) ::_exit(126);
    ::dup2(STDOUT_FILENO, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also here: the test may signal before the child ran
  return pid;
}

// Alive and not a zombie (an orphan's zombie may wait for a reaper for a while).
bool alive(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!std::getline(in, stat)) return false;
  const std::size_t close = stat.rfind(')');
  return close != std::string::npos && close + 2 < stat.size() && stat[close + 2] != 'Z' &&
         stat[close + 2] != 'X';
}

std::vector<pid_t> childrenOf(pid_t parent) {
  std::vector<pid_t> children;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(e.path() / "stat");
    std::string stat;
    if (!std::getline(in, stat)) continue;
    const std::size_t close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 2));
    char state = 0;
    pid_t ppid = 0;
    if (rest >> state >> ppid && ppid == parent && state != 'Z')
      children.push_back(std::stoi(name));
  }
  return children;
}

// Exit code (128 + signal when killed), or -1 after `limit`.
int waitFor(pid_t pid, std::chrono::seconds limit) {
  const auto end = Clock::now() + limit;
  int status = 0;
  while (Clock::now() < end) {
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(-pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return -1;
}

// Every file under `dir` with its size and modification time.
std::map<std::string, std::pair<std::uintmax_t, fs::file_time_type>> snapshot(const fs::path& dir) {
  std::map<std::string, std::pair<std::uintmax_t, fs::file_time_type>> files;
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec)) {
    if (e.is_regular_file(ec)) files[e.path().string()] = {e.file_size(ec), e.last_write_time(ec)};
  }
  return files;
}

class BatchSignalGLTest : public test::TempDirTest {
 protected:
  // Starts the batch (-j2, three runs), waits until both children are
  // rendering, and returns their pids.
  std::vector<pid_t> startBatch() {
    const std::string batch = test::writeBatchFile(dir_, test::kCornellConfig, kSlowRuns);
    pid_ = spawnInOwnGroup({"batch", batch, "--jobs", "2", "-q"}, dir_ / "batch.log");
    std::vector<pid_t> children;
    const auto end = Clock::now() + std::chrono::seconds(20);
    while (Clock::now() < end && children.size() < 2) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      children = childrenOf(pid_);
    }
    // Past start-up, into the render.
    std::this_thread::sleep_for(std::chrono::milliseconds(800));
    return children;
  }

  // The batch printed its table and left nothing running
  // or writing.
  void expectCleanStop(const std::vector<pid_t>& children) {
    const std::string out = test::fileBytes((dir_ / "batch.log").string());
    EXPECT_NE(out.find("batch: 3 of 3 run(s) in this shard"), std::string::npos) << out;
    EXPECT_EQ(out.find("waitpid failed"), std::string::npos) << out;
    EXPECT_EQ(test::stateOf(out, "run0002_seed-3"), "pending") << out;
    for (const char* run : {"run0000_seed-1", "run0001_seed-2"}) {
      const std::string status = test::stateOf(out, run);
      EXPECT_TRUE(status == "interrupted" || status == "done") << out;
    }
    const auto before = snapshot(dir_ / "out");
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
    EXPECT_EQ(snapshot(dir_ / "out"), before);
    for (pid_t c : children) EXPECT_FALSE(alive(c)) << "child " << c << " survived";
  }

  pid_t pid_ = -1;
};

TEST_F(BatchSignalGLTest, SigintToTheBatchStopsItsRuns) {
  const std::vector<pid_t> children = startBatch();
  ASSERT_EQ(children.size(), 2u);
  ::kill(pid_, SIGINT);
  const int code = waitFor(pid_, std::chrono::seconds(20));
  EXPECT_EQ(code, 130);
  expectCleanStop(children);
}

TEST_F(BatchSignalGLTest, SigtermToTheBatchStopsItsRuns) {
  const std::vector<pid_t> children = startBatch();
  ASSERT_EQ(children.size(), 2u);
  ::kill(pid_, SIGTERM);
  const int code = waitFor(pid_, std::chrono::seconds(20));
  EXPECT_EQ(code, 143);
  expectCleanStop(children);
}

TEST_F(BatchSignalGLTest, CtrlCToTheProcessGroupStopsTheBatch) {
  const std::vector<pid_t> children = startBatch();
  ASSERT_EQ(children.size(), 2u);
  ::kill(-pid_, SIGINT);  // what a terminal's Ctrl-C does
  const int code = waitFor(pid_, std::chrono::seconds(20));
  EXPECT_EQ(code, 130);
  expectCleanStop(children);
}

TEST_F(BatchSignalGLTest, SigkillOfTheBatchEndsItsChildren) {
  const std::vector<pid_t> children = startBatch();
  ASSERT_EQ(children.size(), 2u);
  ::kill(pid_, SIGKILL);
  EXPECT_EQ(waitFor(pid_, std::chrono::seconds(5)), 128 + SIGKILL);
  // Their parent-death signal is SIGTERM: they clean up and exit, at the
  // next interrupt check, which under the sanitizers on a loaded machine
  // took more than 10 s once (a GL dispatch runs to its end).
  const auto end = Clock::now() + std::chrono::seconds(30);
  auto anyAlive = [&] {
    for (pid_t c : children) {
      if (alive(c)) return true;
    }
    return false;
  };
  while (anyAlive() && Clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_FALSE(anyAlive());
  // And no run looks done.
  for (const char* run : {"run0000_seed-1", "run0001_seed-2"}) {
    EXPECT_FALSE(fs::exists(dir_ / "out" / run / "manifest.json")) << run;
  }
}

}  // namespace
}  // namespace tofsim
