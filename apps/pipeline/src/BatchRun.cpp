#include "tofsim/pipeline/BatchRun.h"

#include <poll.h>
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
#include <optional>
#include <memory>
#include <thread>

#include "BatchWorker.h"
#include "SharedRender.h"
#include "SharedRenders.h"
#include "tofsim/pipeline/BatchResults.h"
#include "tofsim/pipeline/ExitCode.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/RenderRun.h"
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

// One worker and the run it renders, if any.
struct WorkerSlot {
  std::optional<BatchWorker> worker;
  std::optional<std::size_t> run;  // into summary.runs
  Clock::time_point start;
  std::optional<RunLock> lock;
  bool signalled = false;  // the batch's interrupt was passed on to it
  bool rendersKey = false;  // renders its run's render key for the runs that wait on it
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

fs::path lockFile(const BatchRunResult& r) {
  return r.directory.parent_path() / ("." + r.name + ".lock");
}

// Whether each run of the shard can take its render from another run of its
// render key, and whether through the batch's saved volume (SharedRender.h).
struct Sharing {
  std::vector<bool> shareable;
  std::vector<bool> throughTheBatch;
};

// The content key of every run of the shard and its Sharing; the scene
// digest once per scene file, as a sweep usually renders one scene many times.
std::vector<RunContentKey> runKeys(const config::BatchConfig& batch, const fs::path& base,
                                   const std::vector<BatchRunResult>& runs, Sharing& sharing,
                                   const std::function<void(std::size_t, std::size_t)>& visited) {
  std::map<fs::path, std::string> sceneDigests;
  std::vector<RunContentKey> keys;
  for (const BatchRunResult& r : runs) {
    const config::RunConfig config = config::loadRunConfig(base, batch.run(r.index).overrides);
    std::string& scene = sceneDigests[fs::absolute(config.scene_file).lexically_normal()];
    if (scene.empty()) scene = sceneInputsDigest(config.scene_file);
    keys.push_back(runContentKey(config, scene));
    const bool shareable = sharedRenderObstacle(config).empty();
    sharing.shareable.push_back(shareable);
    sharing.throughTheBatch.push_back(shareable && sharesThroughTheBatch(config));
    visited(keys.size(), runs.size());
  }
  return keys;
}

// Takes the run's lock and sends it to the slot's worker (started when the
// slot has none); or marks it busy (another batch has it: returns false) or
// skipped (another batch finished it since it was assessed).
bool startRun(const BatchOptions& options, const WorkerTask& task, std::size_t run,
              std::optional<std::size_t> source, const RunContentKey& key, BatchRunResult& r,
              WorkerSlot& slot) {
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
  // A worker that ended while idle (a signal of its own) is replaced.
  if (!slot.worker || !slot.worker->send(run, *lock, source)) {
    slot.worker.reset();
    slot.worker = BatchWorker::spawn(task);
    if (!slot.worker->send(run, *lock, source)) {
      throw InputError("batch: a new worker process ended before its first run");
    }
  }
  slot.run = run;
  slot.start = Clock::now();
  slot.lock = std::move(lock);
  slot.signalled = false;
  return true;
}

// Passes the batch's signal on to every busy worker that has not had it. A
// worker whose handler is not armed already got it (a Ctrl-C goes to the
// whole process group): it is not asked again. Idle workers are closed.
void forwardInterrupt(int signal, std::vector<WorkerSlot>& slots) {
  for (WorkerSlot& slot : slots) {
    if (!slot.worker) continue;
    if (!slot.run) {
      slot.worker.reset();
      continue;
    }
    if (slot.signalled || !catchesSignal(slot.worker->pid(), signal)) continue;
    ::kill(slot.worker->pid(), signal);
    slot.signalled = true;
  }
}

// The run's outcome from its exit code (a worker's answer, as `tofsim
// render`'s), or from the wait status of a worker that ended without one.
void recordOutcome(std::optional<int> code, int waitStatus, int interruptSignal,
                   const RunContentKey& key, BatchRunResult& r) {
  if (code && *code == 0) {
    const RunAssessment after = assessRun(r.directory, key, false);
    r.status = after.state == RunState::Done ? BatchRunStatus::Done : BatchRunStatus::Failed;
    if (after.state != RunState::Done) r.message = "exit code 0 but " + after.text;
  } else if (interruptSignal != 0) {
    r.status = BatchRunStatus::Interrupted;
  } else {
    r.status = BatchRunStatus::Failed;
    r.message = (code ? "exit code " + std::to_string(*code) : "worker " + exitText(waitStatus)) +
                ": " + lastLogLine(r.directory);
  }
}

// The slots whose worker answered or ended, after waiting up to `timeoutMs`.
std::vector<std::size_t> answered(const std::vector<WorkerSlot>& slots, int timeoutMs) {
  std::vector<pollfd> fds;
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < slots.size(); ++i) {
    if (!slots[i].run) continue;
    fds.push_back({slots[i].worker->fd(), POLLIN, 0});
    index.push_back(i);
  }
  std::vector<std::size_t> ready;
  if (::poll(fds.data(), fds.size(), timeoutMs) <= 0) return ready;  // none, or EINTR
  for (std::size_t k = 0; k < fds.size(); ++k) {
    if (fds[k].revents != 0) ready.push_back(index[k]);
  }
  return ready;
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

// In the worker: the run rendered as `tofsim render <base> --set ... -o <dir>
// --batch-run <name>` renders it, through the worker's renderer.
int renderRun(const fs::path& base, const config::BatchRun& run, const BatchRunResult& r,
              const BatchRunResult* source, const fs::path& sharedVolume,
              PreparedRenderer& prepared) {
  return exitCodeOf([&] {
    const config::RunConfig config = config::loadRunConfig(base, run.overrides);
    RunOptions options;
    options.outputDirectory = r.directory;
    options.eglPlatform = gl::eglPlatformFromEnvironment();
    // The key from the config this render loaded: the manifest records what was rendered.
    options.batchManifest = {r.name, runContentKey(config), source ? source->name : ""};
    options.sharedVolume = sharedVolume;
    if (source) {
      const RunSummary summary = senseFromSavedRender(config, source->directory, prepared, options);
      std::fprintf(stderr, "batch: run '%s' took the render of run '%s'; wrote %zu file(s) to %s\n",
                   r.name.c_str(), source->name.c_str(), summary.files.size(),
                   summary.outputDirectory.string().c_str());
      return 0;
    }
    const RunSummary summary = runRender(config, prepared, options);
    std::fputs(renderSummaryText(config, summary).c_str(), stderr);
    std::fprintf(stderr,
                 "batch: worker %d: scene loaded %zu time(s), renderer made %zu time(s), scene "
                 "prepared %zu time(s)\n",
                 static_cast<int>(::getpid()), prepared.sceneLoads(), prepared.rendererMakes(),
                 prepared.scenePreparations());
    return 0;
  });
}

void runPending(const BatchOptions& options, const config::BatchConfig& batch, const fs::path& base,
                const std::vector<RunContentKey>& keys, const Sharing& sharing,
                std::deque<std::size_t> pending, const Progress& progress,
                BatchSummary& summary) {
  const SharedVolumes volumes(batch.output_root, keys, sharing.throughTheBatch, pending);
  const WorkerTask task{
      [&](std::size_t run) { return summary.runs[run].directory / kRunLogName; },
      [&](std::size_t run, std::optional<std::size_t> source, PreparedRenderer& prepared) {
        return renderRun(base, batch.run(summary.runs[run].index), summary.runs[run],
                         source ? &summary.runs[*source] : nullptr, volumes.folder(run), prepared);
      }};
  SharedRenders shared(keys, sharing.shareable, sharing.throughTheBatch, summary.runs);
  std::vector<WorkerSlot> slots(static_cast<std::size_t>(options.jobs));
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
      forwardInterrupt(summary.interruptSignal, slots);
    }
    if (pending.empty() && Clock::now() >= retryAt) pending.swap(waiting);
    for (WorkerSlot& slot : slots) {
      while (!slot.run) {
        const std::optional<SharedRenders::Next> next = shared.next(pending);
        if (!next) break;
        BatchRunResult& r = summary.runs[next->run];
        if (!startRun(options, task, next->run, next->source, keys[next->run], r, slot)) {
          shared.ended(next->run, next->renders, false);
          waiting.push_back(next->run);
          retryAt = Clock::now() + std::chrono::milliseconds(250);
        } else if (!slot.run) {  // skipped: another batch finished it
          shared.doneElsewhere(next->run, next->renders);
        } else {
          slot.rendersKey = next->renders;
        }
      }
    }
    const bool busy = std::any_of(slots.begin(), slots.end(), [](auto& s) { return s.run; });
    if (!busy) {
      if (pending.empty() && waiting.empty()) break;
      shared.noneRendering();  // nothing runs: no run may wait on a render
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      continue;
    }
    // Polling with a timeout rather than blocking: a signal that arrives
    // just before a blocking call would go unnoticed until some run ends.
    for (std::size_t i : answered(slots, 20)) {
      WorkerSlot& slot = slots[i];
      const std::optional<int> code = slot.worker->receive();
      const int status = code ? 0 : slot.worker->waitStatus();
      if (!code) slot.worker.reset();  // ended: the next run gets a new one
      BatchRunResult& r = summary.runs[*slot.run];
      r.seconds = std::chrono::duration<double>(Clock::now() - slot.start).count();
      recordOutcome(code, status, pendingInterrupt(), keys[*slot.run], r);
      shared.ended(*slot.run, slot.rendersKey, r.status == BatchRunStatus::Done);
      slot.run.reset();
      slot.lock.reset();  // the batch's hold on the run's lock; the worker let go already
      char line[256];
      std::snprintf(line, sizeof line, "[%zu/%zu] %s %s (%.1f s)", ++finished, toRun,
                    r.name.c_str(), batchRunStatusName(r.status), r.seconds);
      progress.message(line);
    }
  }
  // Every worker ends (its channel closed) before the batch returns.
  slots.clear();
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
  Sharing sharing;
  const std::vector<RunContentKey> keys =
      runKeys(batch, base, summary.runs, sharing, pass("runs keyed"));
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
    runPending(options, batch, base, keys, sharing, std::move(pending), progress, summary);
    try {
      writeBatchResults(batch, options, summary);
    } catch (const std::exception& e) {  // the runs' own outputs stand: a note, not a failure
      std::fprintf(stderr, "batch: results table not written: %s\n", e.what());
    }
  }
  return summary;
}

}  // namespace tofsim::pipeline
