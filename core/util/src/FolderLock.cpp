#include "tofsim/util/FolderLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "tofsim/util/Error.h"

namespace tofsim {

namespace {

std::optional<pid_t> readPid(int fd) {
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  if (n <= 0) return std::nullopt;
  const long pid = std::strtol(text, nullptr, 10);
  if (pid <= 0) return std::nullopt;
  return static_cast<pid_t>(pid);
}

std::string holderText(std::optional<pid_t> pid) {
  return pid ? "pid " + std::to_string(*pid) : "another process";
}

}  // namespace

FolderLock::FolderLock(const std::filesystem::path& folder) : path_(folder / kFileName) {
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw InputError(
        FileLoc{folder.string()}, "",
        "cannot create the output folder's lock file: " + std::string(std::strerror(errno)));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    const std::optional<pid_t> holder = readPid(fd_);
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK) {
      throw InputError(FileLoc{folder.string()}, "",
                       "another tofsim run (" + holderText(holder) +
                           ") is writing to this output folder; wait for it or choose another");
    }
    throw InputError(FileLoc{folder.string()}, "",
                     "cannot lock the output folder: " + std::string(std::strerror(error)));
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  // The pid is only informative (the flock is the lock), so a failed write is harmless.
  if (::ftruncate(fd_, 0) == 0) {
    [[maybe_unused]] const ssize_t n = ::pwrite(fd_, pid.data(), pid.size(), 0);
  }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the flock
}

std::optional<pid_t> folderLockHolder(const std::filesystem::path& folder) {
  const std::filesystem::path path = folder / FolderLock::kFileName;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  std::optional<pid_t> holder;
  if (::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
    holder = readPid(fd);
    if (!holder) holder = 0;
  } else {
    ::flock(fd, LOCK_UN);
  }
  ::close(fd);
  return holder;
}

}  // namespace tofsim
