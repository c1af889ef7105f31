#pragma once
// The process side of `tofsim batch`: the per-run lock that lets two batches
// share an output tree, the fork + exec of one run's render, and whether a
// child still has its interrupt handler armed (so that a signal is forwarded
// to it exactly once).

#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"

namespace tofsim::pipeline {

/// An exclusive flock(2) on <output root>/.<run name>.lock, held for as long
/// as this object (and the child that inherits it) lives; the kernel drops it
/// when both are gone, however they end. Move-only.
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

struct RenderChildArgs {
  std::filesystem::path executable;  ///< the tofsim binary
  std::filesystem::path baseConfig;
  std::vector<config::Override> overrides;
  std::filesystem::path directory;  ///< the run folder; log.txt goes there
  std::string runName;              ///< --batch-run: the render writes the manifest
  int inheritedFd = -1;             ///< the run's lock, kept open across exec
};

/// fork + exec of `tofsim render <base> --set ... -o <dir> --batch-run <name>`
/// in this process's process group, with SIGTERM as its parent-death signal.
/// Returns the pid; throws InputError when fork fails.
pid_t spawnRender(const RenderChildArgs& args);

/// True while `pid` catches `signal` (its tofsim handler is installed and has
/// not fired yet). The handler is one-shot, so a child that already got the
/// signal (a Ctrl-C reaches the whole process group) must not get it again:
/// the second one would kill it before it cleans up.
bool catchesSignal(pid_t pid, int signal);

}  // namespace tofsim::pipeline
