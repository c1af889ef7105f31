#pragma once
// One writer per output folder: an exclusive flock(2) on `<folder>/.tofsim.lock`,
// held for the lifetime of the object and released by the kernel when the
// process dies (SIGKILL included), so a lock is never stale. The holder's pid
// is written into the file so that a second writer can say who holds it.
//
// The lock file is an inode, not a name: StagedFolder hard-links it into the
// folder that replaces this one, so a writer that opens the name after the
// swap still meets the same lock.
//
// A lock file is opened without following a link at its name: a link there
// (or a folder, a FIFO) is an error naming it, never a file written through it.

#include <sys/types.h>

#include <filesystem>
#include <optional>

namespace tofsim {

class FolderLock {
 public:
  /// Name of the lock file inside a locked folder.
  static constexpr const char* kFileName = ".tofsim.lock";

  /// Takes the lock on `folder` (which must exist) without waiting; throws
  /// InputError naming the folder and the holder's pid when another process
  /// holds it, or naming the lock file when it is not a regular file.
  explicit FolderLock(const std::filesystem::path& folder);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  const std::filesystem::path& lockFile() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

/// Opens (creating) the lock file `file` for reading and writing, without
/// following a link at its name; InputError naming it when it is a link, a
/// folder or anything but a regular file, or cannot be made. The descriptor
/// is close-on-exec.
int openLockFile(const std::filesystem::path& file);

/// The pid of the process that holds `folder`'s lock, or nothing when no one
/// does (or the folder has no lock file). Does not take the lock.
std::optional<pid_t> folderLockHolder(const std::filesystem::path& folder);

}  // namespace tofsim
