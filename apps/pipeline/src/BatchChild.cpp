#include "BatchChild.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <fstream>

#include "tofsim/pipeline/Manifest.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/FolderLock.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;

std::optional<RunLock> RunLock::tryAcquire(const fs::path& file) {
  // Close-on-exec: only the child of this run may inherit it (spawnRender).
  // Not through a link at its name (the run's folder lock's rules).
  const int fd = openLockFile(file);
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    return std::nullopt;
  }
  // The holder's pid, for the message of the batch that finds it taken.
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) < 0) {
    // Only the message suffers; the lock itself is held.
  }
  return RunLock(fd);
}

std::string RunLock::holder(const fs::path& file) {
  std::ifstream in(file);
  std::string pid;
  return (in >> pid) ? pid : "?";
}

RunLock& RunLock::operator=(RunLock&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = other.fd_;
    other.fd_ = -1;
  }
  return *this;
}

RunLock::~RunLock() {
  if (fd_ >= 0) ::close(fd_);
}

namespace {

// Between fork and exec: async-signal-safe calls only.
[[noreturn]] void execChild(char* const* argv, const char* log, pid_t parent, int keepFd) {
  // The batch's own handlers would only set a flag in this copy of its
  // memory, which exec discards: until the render installs its handlers, a
  // signal takes the default action (the child has written nothing yet).
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(SIGINT, &dfl, nullptr);
  ::sigaction(SIGTERM, &dfl, nullptr);
  // If the batch dies (SIGKILL, a crash) its runs must not write on: they get
  // SIGTERM and clean up. A parent already gone before prctl took effect
  // would never send it, hence the check after.
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() != parent) ::_exit(143);
  if (keepFd >= 0) ::fcntl(keepFd, F_SETFD, 0);  // the run's lock lives as long as the run
  // O_NOFOLLOW: a link named log.txt must not truncate its target.
  const int fd = ::open(log, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd >= 0) {
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
  }
  // No setpgid/setsid: the child stays in the batch's process group, so a
  // Ctrl-C or a `kill -- -PGID` reaches every run.
  ::execv(argv[0], argv);
  const char msg[] = "tofsim batch: exec of the tofsim binary failed\n";
  [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, msg, sizeof msg - 1);
  ::_exit(127);
}

}  // namespace

pid_t spawnRender(const RenderChildArgs& a) {
  std::vector<std::string> args = {a.executable.string(), "render", a.baseConfig.string()};
  for (const config::Override& o : a.overrides) {
    args.push_back("--set");
    args.push_back(o.keyPath + "=" + o.value);
  }
  args.insert(args.end(), {"-o", a.directory.string(), "--batch-run", a.runName});
  std::vector<char*> argv;
  for (std::string& s : args) argv.push_back(s.data());
  argv.push_back(nullptr);
  const std::string log = (a.directory / kRunLogName).string();

  const pid_t parent = ::getpid();
  std::fflush(nullptr);  // or buffered parent output is written twice
  const pid_t pid = ::fork();
  if (pid < 0) throw InputError("fork failed for batch run in " + a.directory.string());
  if (pid == 0) execChild(argv.data(), log.c_str(), parent, a.inheritedFd);
  return pid;
}

bool catchesSignal(pid_t pid, int signal) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("SigCgt:", 0) != 0) continue;
    const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
    return (mask >> (signal - 1)) & 1ull;
  }
  return false;  // gone, or a zombie
}

}  // namespace tofsim::pipeline
