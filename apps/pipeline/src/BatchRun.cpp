#include "tofsim/pipeline/BatchRun.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <deque>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <thread>

#include "BatchChild.h"
#include "tofsim/pipeline/Manifest.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

// A batch of fewer runs passes them in seconds (about 10 ms a run, most of it
// the content key): no progress lines, which end each pass with a line.
constexpr std::size_t kRunsWithProgress = 1000;

struct Child {
  std::size_t slot;  // into summary.runs
  Clock::time_point start;
  RunLock lock;
  bool signalled = false;  // the batch's interrupt was passed on to it
};

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
    case BatchRunStatus::Interrupted:
      return "interrupted";
    case BatchRunStatus::Busy:
      return "busy";
  }
  return "?";
}

fs::path lockFile(const BatchRunResult& r) {
  return r.directory.parent_path() / ("." + r.name + ".lock");
}

// The content key of every run of the shard; the scene digest once per scene
// file, as a sweep usually renders one scene many times.
std::vector<RunContentKey> runKeys(const config::BatchConfig& batch, const fs::path& base,
                                   const std::vector<BatchRunResult>& runs,
                                   const std::function<void(std::size_t, std::size_t)>& visited) {
  std::map<fs::path, std::string> sceneDigests;
  std::vector<RunContentKey> keys;
  for (const BatchRunResult& r : runs) {
    const config::RunConfig config = config::loadRunConfig(base, batch.run(r.index).overrides);
    std::string& scene = sceneDigests[fs::absolute(config.scene_file).lexically_normal()];
    if (scene.empty()) scene = sceneInputsDigest(config.scene_file);
    keys.push_back(runContentKey(config, scene));
    visited(keys.size(), runs.size());
  }
  return keys;
}

// Takes the run's lock and starts its render; or marks it busy (another batch
// has it: returns false) or skipped (another batch finished it since it was
// assessed).
bool startRun(const BatchOptions& options, const config::BatchConfig& batch, const fs::path& base,
              std::size_t slot, const RunContentKey& key, BatchRunResult& r,
              std::map<pid_t, Child>& running) {
  fs::create_directories(r.directory);
  std::optional<RunLock> lock = RunLock::tryAcquire(lockFile(r));
  if (!lock) {
    r.status = BatchRunStatus::Busy;
    r.message = "another batch (pid " + RunLock::holder(lockFile(r)) + ") is running it";
    return false;
  }
  r.message.clear();
  if (assessRun(r.directory, key, options.verify).state == RunState::Done) {
    r.status = BatchRunStatus::Skipped;
    return true;
  }
  // The folder is not emptied: the render replaces the earlier outputs only
  // once its own set is complete, and its manifest lists only its own files.
  RenderChildArgs args{options.executable, base,   batch.run(r.index).overrides,
                       r.directory,        r.name, lock->fd()};
  const pid_t pid = spawnRender(args);
  running.emplace(pid, Child{slot, Clock::now(), std::move(*lock)});
  return true;
}

// Passes the batch's signal on to every child that has not had it. A child
// whose handler is not armed either already got it (a Ctrl-C goes to the
// whole process group) or has not installed it yet: asked again next time.
void forwardInterrupt(int signal, std::map<pid_t, Child>& running) {
  for (auto& [pid, child] : running) {
    if (child.signalled || !catchesSignal(pid, signal)) continue;
    ::kill(pid, signal);
    child.signalled = true;
  }
}

void recordExit(int status, int interruptSignal, const RunContentKey& key, BatchRunResult& r) {
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    const RunAssessment after = assessRun(r.directory, key, false);
    r.status = after.state == RunState::Done ? BatchRunStatus::Done : BatchRunStatus::Failed;
    if (after.state != RunState::Done) r.message = "exit code 0 but " + after.text;
  } else if (interruptSignal != 0) {
    r.status = BatchRunStatus::Interrupted;
  } else {
    r.status = BatchRunStatus::Failed;
    r.message = exitText(status) + ": " + lastLogLine(r.directory);
  }
}

// One reaped child, or none after a short sleep. Polling rather than a
// blocking waitpid: a signal that arrives just before a blocking call would
// go unnoticed until some run ends by itself.
pid_t reapOne(int& status) {
  const pid_t pid = ::waitpid(-1, &status, WNOHANG);
  if (pid < 0 && errno != EINTR) {
    throw InputError(std::string("batch: waitpid failed: ") + std::strerror(errno));
  }
  if (pid <= 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  return pid;
}

}  // namespace

bool BatchSummary::anyFailed() const {
  for (const BatchRunResult& r : runs) {
    if (r.status == BatchRunStatus::Failed) return true;
  }
  return false;
}

int BatchSummary::exitCode() const {
  if (interruptSignal != 0) return 128 + interruptSignal;
  for (const BatchRunResult& r : runs) {
    if (r.status == BatchRunStatus::Failed || r.status == BatchRunStatus::Busy) return 1;
  }
  return 0;
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

namespace {

void runPending(const BatchOptions& options, const config::BatchConfig& batch, const fs::path& base,
                const std::vector<RunContentKey>& keys, std::deque<std::size_t> pending,
                const Progress& progress, BatchSummary& summary) {
  std::map<pid_t, Child> running;
  // Runs another batch is rendering: asked again when this batch has nothing
  // else to start, so that both batches end with every run done.
  std::deque<std::size_t> waiting;
  Clock::time_point retryAt;
  std::size_t finished = 0;
  const std::size_t toRun = pending.size();
  for (;;) {
    summary.interruptSignal = pendingInterrupt();
    if (summary.interruptSignal != 0) {
      pending.clear();  // never started: they stay `pending` (or `busy`)
      waiting.clear();
      forwardInterrupt(summary.interruptSignal, running);
    }
    if (pending.empty() && Clock::now() >= retryAt) pending.swap(waiting);
    while (!pending.empty() && running.size() < static_cast<std::size_t>(options.jobs)) {
      const std::size_t slot = pending.front();
      pending.pop_front();
      if (!startRun(options, batch, base, slot, keys[slot], summary.runs[slot], running)) {
        waiting.push_back(slot);
        retryAt = Clock::now() + std::chrono::milliseconds(250);
      }
    }
    if (running.empty()) {
      if (pending.empty() && waiting.empty()) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      continue;
    }
    int status = 0;
    const pid_t pid = reapOne(status);
    const auto it = running.find(pid);
    if (it == running.end()) continue;  // nothing yet, or not one of ours
    BatchRunResult& r = summary.runs[it->second.slot];
    r.seconds = std::chrono::duration<double>(Clock::now() - it->second.start).count();
    recordExit(status, pendingInterrupt(), keys[it->second.slot], r);
    running.erase(it);  // and with it the run's lock
    char line[256];
    std::snprintf(line, sizeof line, "[%zu/%zu] %s %s (%.1f s)", ++finished, toRun, r.name.c_str(),
                  statusName(r.status), r.seconds);
    progress.message(line);
  }
}

}  // namespace

BatchSummary runBatch(const BatchOptions& options) {
  if (options.jobs < 1 || options.jobs > kMaxJobs) {
    throw InputError("--jobs must be between 1 and " + std::to_string(kMaxJobs) + " (got " +
                     std::to_string(options.jobs) + ")");
  }
  const config::BatchConfig batch = config::loadBatchConfig(options.batchFile, options.overrides);
  // Every run is visited three times before anything renders (its config
  // checked, its content key, its folder's state): each pass stops at an
  // interrupt, and a long one (a large sweep) reports its progress, timed
  // from the pass's start.
  const auto pass = [&](const char* what) {
    auto progress = std::make_shared<Progress>("batch", options.quiet);
    return [progress, what](std::size_t done, std::size_t total) {
      throwIfInterrupted();
      if (total >= kRunsWithProgress) progress->update(done, total, what);
    };
  };
  config::validateBatch(batch, pass("run configs checked"));
  const fs::path base = fs::absolute(batch.base_config);

  BatchSummary summary;
  summary.totalRuns = batch.runCount();
  for (std::size_t i = 0; i < summary.totalRuns; ++i) {
    throwIfInterrupted();
    if (!inShard(i, options.shardIndex, options.shardCount)) continue;
    const config::BatchRun run = batch.run(i);
    BatchRunResult r;
    r.index = run.index;
    r.name = run.name;
    r.directory = batch.output_root / run.name;
    for (const config::Override& o : run.varied) r.message += o.keyPath + "=" + o.value + "  ";
    summary.runs.push_back(std::move(r));
  }
  const std::vector<RunContentKey> keys = runKeys(batch, base, summary.runs, pass("runs keyed"));
  const auto assessed = pass("runs assessed");
  std::deque<std::size_t> pending;
  for (std::size_t i = 0; i < summary.runs.size(); ++i) {
    BatchRunResult& r = summary.runs[i];
    const RunAssessment a = assessRun(r.directory, keys[i], options.verify);
    r.state = a.text;
    if (a.state == RunState::Done) {
      r.status = BatchRunStatus::Skipped;
    } else {
      pending.push_back(i);
    }
    if (!options.dryRun) r.message.clear();
    assessed(i + 1, summary.runs.size());
  }
  if (options.dryRun) {
    summary.interruptSignal = pendingInterrupt();  // one that came after the last check
  } else {
    const Progress progress("batch", options.quiet);
    runPending(options, batch, base, keys, std::move(pending), progress, summary);
  }
  return summary;
}

std::string formatBatchSummary(const BatchSummary& summary, bool dryRun) {
  std::size_t width = 3, statusWidth = std::string("interrupted").size();
  for (const BatchRunResult& r : summary.runs) {
    width = std::max(width, r.name.size());
    if (dryRun) statusWidth = std::max(statusWidth, r.state.size());
  }
  std::string out;
  char line[2048];
  const int w = static_cast<int>(width), sw = static_cast<int>(statusWidth);
  if (dryRun) {
    std::snprintf(line, sizeof line, "%-*s  %-*s  %s\n", w, "run", sw, "state", "varied keys");
  } else {
    std::snprintf(line, sizeof line, "%-*s  %-*s  %8s  %s\n", w, "run", sw, "status", "seconds",
                  "output");
  }
  out += line;
  std::size_t counts[6] = {0, 0, 0, 0, 0, 0};
  for (const BatchRunResult& r : summary.runs) {
    ++counts[static_cast<int>(r.status)];
    if (dryRun) {
      std::snprintf(line, sizeof line, "%-*s  %-*s  %s\n", w, r.name.c_str(), sw, r.state.c_str(),
                    r.message.c_str());
    } else {
      std::snprintf(line, sizeof line, "%-*s  %-*s  %8.1f  %s\n", w, r.name.c_str(), sw,
                    statusName(r.status), r.seconds, r.directory.string().c_str());
    }
    out += line;
    if (!dryRun && !r.message.empty()) out += "    " + r.message + "\n";
  }
  if (dryRun) {
    std::snprintf(line, sizeof line,
                  "batch: %zu of %zu run(s) in this shard: %zu done, %zu to run\n",
                  summary.runs.size(), summary.totalRuns, counts[1], counts[3]);
  } else {
    std::snprintf(line, sizeof line,
                  "batch: %zu of %zu run(s) in this shard: %zu done, %zu skipped, %zu failed, "
                  "%zu interrupted, %zu busy, %zu pending\n",
                  summary.runs.size(), summary.totalRuns, counts[0], counts[1], counts[2],
                  counts[4], counts[5], counts[3]);
  }
  out += line;
  if (summary.interruptSignal != 0) {
    out += std::string("batch: interrupted by ") +
           (summary.interruptSignal == SIGINT ? "SIGINT" : "SIGTERM") +
           "; rerun the batch to finish the interrupted and pending runs\n";
  }
  return out;
}

}  // namespace tofsim::pipeline
