#include "BatchWorker.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>

#include "tofsim/gl/Context.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/FolderLock.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;

std::optional<RunLock> RunLock::tryAcquire(const fs::path& file) {
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

// The channel's messages: the batch sends a run's index (and the run whose
// render it takes, or kNoSource) with its lock as SCM_RIGHTS; the worker
// answers with the run's exit code.
constexpr std::uint64_t kNoSource = ~std::uint64_t{0};
struct Request {
  std::uint64_t run = 0;
  std::uint64_t source = kNoSource;
};

// A message of one request and room for one descriptor.
struct RequestMessage {
  iovec iov;
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
  msghdr msg{};
  explicit RequestMessage(Request& request) : iov{&request, sizeof request} {
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof control;
  }
  RequestMessage(const RequestMessage&) = delete;
  RequestMessage& operator=(const RequestMessage&) = delete;
};

bool sendRequest(int fd, std::uint64_t run, std::uint64_t source, int lockFd) {
  Request request{run, source};
  RequestMessage m(request);
  msghdr& msg = m.msg;
  cmsghdr* c = CMSG_FIRSTHDR(&msg);
  c->cmsg_level = SOL_SOCKET;
  c->cmsg_type = SCM_RIGHTS;
  c->cmsg_len = CMSG_LEN(sizeof(int));
  std::memcpy(CMSG_DATA(c), &lockFd, sizeof(int));
  ssize_t n;
  do n = ::sendmsg(fd, &msg, MSG_NOSIGNAL);
  while (n < 0 && errno == EINTR);
  return n == static_cast<ssize_t>(sizeof request);
}

// The next request, or false at the end (the batch closed the channel, or
// a signal came while waiting).
bool receiveRequest(int fd, Request& request, int& lockFd) {
  RequestMessage m(request);
  msghdr& msg = m.msg;
  const ssize_t n = ::recvmsg(fd, &msg, MSG_CMSG_CLOEXEC);
  if (n != static_cast<ssize_t>(sizeof request)) return false;
  lockFd = -1;
  if (cmsghdr* c = CMSG_FIRSTHDR(&msg); c && c->cmsg_type == SCM_RIGHTS) {
    std::memcpy(&lockFd, CMSG_DATA(c), sizeof(int));
  }
  return true;
}

// stdout and stderr into `file` (O_NOFOLLOW: a link named log.txt must not
// truncate its target), or /dev/null between runs.
void redirectOutput(const fs::path& file) {
  std::fflush(stdout);
  std::fflush(stderr);
  int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (fd < 0) return;
  ::dup2(fd, STDOUT_FILENO);
  ::dup2(fd, STDERR_FILENO);
  ::close(fd);
}

// Only the worker's own end of the channel stays open (as fd 3): not the
// other workers' channels, whose ends must close when the batch closes
// them, nor the locks of the runs they render.
void closeInheritedFiles(int keep) {
  if (keep != 3) {
    ::dup2(keep, 3);
    ::close(keep);
  }
  std::error_code ec;
  std::vector<int> open;
  for (const auto& e : fs::directory_iterator("/proc/self/fd", ec)) {
    const int fd = std::atoi(e.path().filename().c_str());
    if (fd > 3) open.push_back(fd);
  }
  for (int fd : open) ::close(fd);
}

// The worker's life: runs until the batch closes the channel or a signal
// stops it. Never returns into the batch's code.
[[noreturn]] void workerMain(int channel, pid_t parent, const WorkerTask& task) {
  // If the batch dies (SIGKILL, a crash) its runs must not write on: they get
  // SIGTERM and clean up. A parent already gone before prctl took effect
  // would never send it, hence the check after.
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() != parent) ::_exit(143);
  closeInheritedFiles(channel);
  channel = 3;
  installInterruptHandlers();  // its own one-shot handlers
  redirectOutput("/dev/null");
  {
    std::optional<PreparedRenderer> prepared;
    Request request;
    int lockFd = -1;
    while (pendingInterrupt() == 0 && receiveRequest(channel, request, lockFd)) {
      const std::size_t run = static_cast<std::size_t>(request.run);
      redirectOutput(task.logFile(run));
      if (!prepared) prepared.emplace(gl::eglPlatformFromEnvironment());
      std::optional<std::size_t> source;
      if (request.source != kNoSource) source = static_cast<std::size_t>(request.source);
      int code = task.render(run, source, *prepared);
      // After a failed run the next one starts afresh: nothing of a render
      // that threw (a device in an unknown state) is reused.
      if (code != 0) prepared.reset();
      redirectOutput("/dev/null");
      if (lockFd >= 0) ::close(lockFd);
      const auto answer = static_cast<std::int32_t>(code);
      if (::send(channel, &answer, sizeof answer, MSG_NOSIGNAL) < 0) break;
      if (code == 128 + SIGINT || code == 128 + SIGTERM) break;
    }
  }
  ::_exit(pendingInterrupt() != 0 ? 128 + pendingInterrupt() : 0);
}

}  // namespace

BatchWorker BatchWorker::spawn(const WorkerTask& task) {
  int ends[2];
  if (::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, ends) != 0) {
    throw InputError(std::string("batch: socketpair failed: ") + std::strerror(errno));
  }
  const pid_t parent = ::getpid();
  std::fflush(nullptr);  // or buffered batch output is written twice
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(ends[0]);
    ::close(ends[1]);
    throw InputError(std::string("batch: fork failed: ") + std::strerror(errno));
  }
  if (pid == 0) workerMain(ends[1], parent, task);
  ::close(ends[1]);
  return BatchWorker(pid, ends[0]);
}

BatchWorker::BatchWorker(BatchWorker&& other) noexcept
    : pid_(other.pid_), fd_(other.fd_), status_(other.status_) {
  other.pid_ = -1;
  other.fd_ = -1;
}

BatchWorker& BatchWorker::operator=(BatchWorker&& other) noexcept {
  if (this != &other) {
    waitStatus();
    pid_ = other.pid_;
    fd_ = other.fd_;
    status_ = other.status_;
    other.pid_ = -1;
    other.fd_ = -1;
  }
  return *this;
}

BatchWorker::~BatchWorker() { waitStatus(); }

bool BatchWorker::send(std::size_t run, const RunLock& lock, std::optional<std::size_t> source) {
  return fd_ >= 0 && sendRequest(fd_, run, source ? *source : kNoSource, lock.fd());
}

std::optional<int> BatchWorker::receive() {
  std::int32_t code = 0;
  ssize_t n;
  do n = ::recv(fd_, &code, sizeof code, 0);
  while (n < 0 && errno == EINTR);
  if (n != static_cast<ssize_t>(sizeof code)) return std::nullopt;
  return code;
}

int BatchWorker::waitStatus() {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (pid_ > 0) {
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    status_ = status;
    pid_ = -1;
  }
  return status_;
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
