#include "tofsim/pipeline/BatchRun.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <fstream>
#include <map>

#include "tofsim/pipeline/Manifest.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

struct Child {
  std::size_t slot;  // into summary.runs
  Clock::time_point start;
};

// fork + exec of `tofsim render`, output to <dir>/log.txt. Returns the pid.
pid_t spawnRender(const fs::path& exe, const fs::path& baseConfig,
                  const std::vector<config::Override>& overrides, const fs::path& dir) {
  std::vector<std::string> args = {exe.string(), "render", baseConfig.string()};
  for (const config::Override& o : overrides) {
    args.push_back("--set");
    args.push_back(o.keyPath + "=" + o.value);
  }
  args.push_back("-o");
  args.push_back(dir.string());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string log = (dir / kRunLogName).string();

  std::fflush(nullptr);  // or buffered parent output is written twice
  const pid_t pid = ::fork();
  if (pid < 0) throw InputError("fork failed for batch run in " + dir.string());
  if (pid == 0) {
    // Child: only async-signal-safe calls until exec.
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ::dup2(fd, STDOUT_FILENO);
      ::dup2(fd, STDERR_FILENO);
      ::close(fd);
    }
    ::execv(argv[0], argv.data());
    const char msg[] = "tofsim batch: exec of the tofsim binary failed\n";
    [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, msg, sizeof msg - 1);
    ::_exit(127);
  }
  return pid;
}

std::string lastLogLine(const fs::path& dir) {
  std::ifstream in(dir / kRunLogName);
  std::string line, last;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  return last.empty() ? "no output (see log.txt)" : last;
}

std::string exitText(int status) {
  if (WIFEXITED(status)) return "exit code " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return "status " + std::to_string(status);
}

const char* statusName(BatchRunStatus s) {
  switch (s) {
    case BatchRunStatus::Done:
      return "done";
    case BatchRunStatus::Skipped:
      return "skipped";
    case BatchRunStatus::Failed:
      return "failed";
    case BatchRunStatus::Pending:
      return "pending";
  }
  return "?";
}

}  // namespace

bool BatchSummary::anyFailed() const {
  for (const BatchRunResult& r : runs) {
    if (r.status == BatchRunStatus::Failed) return true;
  }
  return false;
}

void parseShard(const std::string& text, int& index, int& count) {
  int k = 0, n = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%d/%d%c", &k, &n, &tail) != 2 || n < 1 || k < 1 || k > n) {
    throw InputError("--shard expects K/N with 1 <= K <= N (got '" + text + "')");
  }
  index = k;
  count = n;
}

bool inShard(std::size_t index, int shardIndex, int shardCount) {
  return index % static_cast<std::size_t>(shardCount) == static_cast<std::size_t>(shardIndex - 1);
}

BatchSummary runBatch(const BatchOptions& options) {
  if (options.jobs < 1) throw InputError("--jobs must be >= 1");
  const config::BatchConfig batch = config::loadBatchConfig(options.batchFile, options.overrides);
  config::validateBatch(batch);
  const fs::path base = fs::absolute(batch.base_config);
  Progress progress("batch", options.quiet);

  BatchSummary summary;
  summary.totalRuns = batch.runs.size();
  std::deque<std::size_t> pending;
  for (const config::BatchRun& run : batch.runs) {
    if (!inShard(run.index, options.shardIndex, options.shardCount)) continue;
    BatchRunResult r;
    r.index = run.index;
    r.name = run.name;
    r.directory = batch.output_root / run.name;
    std::string why;
    if (runIsComplete(r.directory, options.verify, &why)) {
      r.status = BatchRunStatus::Skipped;
    } else if (options.dryRun) {
      for (const config::Override& o : run.varied) r.message += o.keyPath + "=" + o.value + "  ";
    } else {
      pending.push_back(summary.runs.size());
    }
    summary.runs.push_back(std::move(r));
  }
  if (options.dryRun) return summary;

  std::map<pid_t, Child> running;
  std::size_t finished = 0;
  const std::size_t toRun = pending.size();
  while (!pending.empty() || !running.empty()) {
    while (!pending.empty() && running.size() < static_cast<std::size_t>(options.jobs)) {
      const std::size_t slot = pending.front();
      pending.pop_front();
      BatchRunResult& r = summary.runs[slot];
      // Whatever an interrupted earlier attempt left is not trusted.
      fs::remove_all(r.directory);
      fs::create_directories(r.directory);
      const pid_t pid =
          spawnRender(options.executable, base, batch.runs[r.index].overrides, r.directory);
      running[pid] = Child{slot, Clock::now()};
    }
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, 0);
    if (pid < 0) throw InputError("batch: waitpid failed");
    const auto it = running.find(pid);
    if (it == running.end()) continue;  // not one of ours
    BatchRunResult& r = summary.runs[it->second.slot];
    r.seconds = std::chrono::duration<double>(Clock::now() - it->second.start).count();
    running.erase(it);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      try {
        writeManifest(r.directory, r.name);
        r.status = BatchRunStatus::Done;
      } catch (const std::exception& e) {
        r.status = BatchRunStatus::Failed;
        r.message = std::string("manifest: ") + e.what();
      }
    } else {
      r.status = BatchRunStatus::Failed;
      r.message = exitText(status) + ": " + lastLogLine(r.directory);
    }
    ++finished;
    char line[256];
    std::snprintf(line, sizeof line, "[%zu/%zu] %s %s (%.1f s)", finished, toRun, r.name.c_str(),
                  statusName(r.status), r.seconds);
    progress.message(line);
  }
  return summary;
}

std::string formatBatchSummary(const BatchSummary& summary, bool dryRun) {
  std::size_t width = 3;
  for (const BatchRunResult& r : summary.runs) width = std::max(width, r.name.size());
  std::string out;
  char line[1024];
  std::snprintf(line, sizeof line, "%-*s  %-7s  %8s  %s\n", static_cast<int>(width), "run",
                "status", "seconds", dryRun ? "varied keys (pending runs)" : "output");
  out += line;
  std::size_t counts[4] = {0, 0, 0, 0};
  for (const BatchRunResult& r : summary.runs) {
    ++counts[static_cast<int>(r.status)];
    const std::string last =
        dryRun && r.status == BatchRunStatus::Pending ? r.message : r.directory.string();
    std::snprintf(line, sizeof line, "%-*s  %-7s  %8.1f  %s\n", static_cast<int>(width),
                  r.name.c_str(), statusName(r.status), r.seconds, last.c_str());
    out += line;
    if (r.status == BatchRunStatus::Failed) out += "    " + r.message + "\n";
  }
  std::snprintf(line, sizeof line,
                "batch: %zu of %zu run(s) in this shard: %zu done, %zu skipped, %zu failed, %zu "
                "pending\n",
                summary.runs.size(), summary.totalRuns, counts[0], counts[1], counts[2], counts[3]);
  out += line;
  return out;
}

}  // namespace tofsim::pipeline
