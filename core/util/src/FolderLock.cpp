#include "tofsim/util/FolderLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
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

const char* kindOf(mode_t mode) {
  if (S_ISLNK(mode)) return "a symbolic link (tofsim does not follow links there)";
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  return "not a regular file";
}

[[noreturn]] void notALockFile(const std::filesystem::path& file, mode_t mode) {
  throw InputError(FileLoc{file.string()}, "",
                   std::string("the lock file is ") + kindOf(mode) +
                       ", not a regular file; remove it and run again");
}

// open(2) of `file` that never follows a link at its name, nor blocks on a
// FIFO; -1 with errno as open's.
int openNoFollow(const std::filesystem::path& file, int flags) {
  return ::open(file.c_str(), flags | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
}

}  // namespace

int openLockFile(const std::filesystem::path& file) {
  const int fd = openNoFollow(file, O_RDWR | O_CREAT);
  if (fd < 0) {
    const int error = errno;
    struct stat st {};
    // ELOOP: a link; EISDIR: a folder; ENXIO, EWOULDBLOCK: a socket or a FIFO.
    if (::lstat(file.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) notALockFile(file, st.st_mode);
    throw InputError(FileLoc{file.string()}, "",
                     "cannot create the lock file: " + std::string(std::strerror(error)));
  }
  // Checked on what was opened, not on the name, so nothing can swap it in between.
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    notALockFile(file, st.st_mode);
  }
  return fd;
}

FolderLock::FolderLock(const std::filesystem::path& folder) : path_(folder / kFileName) {
  fd_ = openLockFile(path_);
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
  const int fd = openNoFollow(folder / FolderLock::kFileName, O_RDONLY);
  if (fd < 0) return std::nullopt;
  struct stat st {};
  std::optional<pid_t> holder;
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {  // anything else is no one's lock
    if (::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
      holder = readPid(fd);
      if (!holder) holder = 0;
    } else {
      ::flock(fd, LOCK_UN);
    }
  }
  ::close(fd);
  return holder;
}

}  // namespace tofsim
