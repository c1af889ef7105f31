#pragma once
// The process side of `tofsim batch`: the per-run lock that lets two batches
// share an output tree, and the worker processes that render the runs.
//
// A worker is a fork of the batch (no exec: it has the batch's expanded runs
// in its memory) that renders the runs it is sent one after another through
// one PreparedRenderer, so runs of one scene and backend load the scene,
// make the renderer and prepare the scene once. It writes each run's stdout
// and stderr into the run's log.txt and answers with the run's exit code (0,
// 1, 130, 143: those of `tofsim render`). Processes rather than threads:
// stdout and stderr are per process (a log.txt per run), every renderer owns
// a GL context and large buffers, and a crash (or a driver abort) in one run
// must not take the batch down: the batch counts the run failed and starts
// another worker.

#include <sys/types.h>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace tofsim::pipeline {

class PreparedRenderer;

/// An exclusive flock(2) on <output root>/.<run name>.lock, held for as long
/// as this object (and the worker it is sent to) holds it; the kernel drops
/// it when both are done with it, however they end. Move-only.
class RunLock {
 public:
  /// The lock, or nullopt when another process holds it.
  static std::optional<RunLock> tryAcquire(const std::filesystem::path& file);
  /// The pid recorded in a held lock file ("?" when unreadable).
  static std::string holder(const std::filesystem::path& file);

  RunLock(RunLock&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
  RunLock& operator=(RunLock&& other) noexcept;
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;
  ~RunLock();
  int fd() const { return fd_; }

 private:
  explicit RunLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

/// What a worker does, in the worker process.
struct WorkerTask {
  /// Where run `run`'s stdout and stderr go (its log.txt).
  std::function<std::filesystem::path(std::size_t run)> logFile;
  /// Renders run `run` through `prepared` (or, given `source`, takes that
  /// run's render: SharedRender.h) and returns its exit code.
  std::function<int(std::size_t run, std::optional<std::size_t> source, PreparedRenderer& prepared)>
      render;
};

/// The batch's handle on one worker process. Move-only; its end closes the
/// worker's channel (an idle worker then exits) and waits for the process.
class BatchWorker {
 public:
  /// Forks a worker that runs `task` for every run it is sent, in this
  /// process's process group (a Ctrl-C reaches it), with SIGTERM as its
  /// parent-death signal. Throws InputError when fork fails.
  static BatchWorker spawn(const WorkerTask& task);

  BatchWorker(BatchWorker&& other) noexcept;
  BatchWorker& operator=(BatchWorker&& other) noexcept;
  BatchWorker(const BatchWorker&) = delete;
  BatchWorker& operator=(const BatchWorker&) = delete;
  ~BatchWorker();

  pid_t pid() const { return pid_; }
  /// The batch's end of the channel: readable when the answer came or the
  /// worker ended (for poll(2) over the busy workers).
  int fd() const { return fd_; }
  /// Sends run `run` with its lock, which the worker holds until the run
  /// ends, and the run whose render it takes, if any. False when the worker
  /// is gone.
  bool send(std::size_t run, const RunLock& lock, std::optional<std::size_t> source = {});
  /// The answer to the run sent, when fd() is readable: its exit code, or
  /// nullopt when the worker ended without answering (waitStatus() says how).
  std::optional<int> receive();
  /// Closes the channel and waits for the process; its wait(2) status.
  int waitStatus();

 private:
  BatchWorker(pid_t pid, int fd) : pid_(pid), fd_(fd) {}
  pid_t pid_ = -1;
  int fd_ = -1;
  int status_ = 0;
};

/// True while `pid` catches `signal` (its tofsim handler is installed and has
/// not fired yet). The handler is one-shot, so a worker that already got the
/// signal (a Ctrl-C reaches the whole process group) must not get it again:
/// the second one would kill it before it cleans up.
bool catchesSignal(pid_t pid, int signal);

}  // namespace tofsim::pipeline
