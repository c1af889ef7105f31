#include "tofsim/util/StagedFolder.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "tofsim/util/Error.h"

namespace tofsim {

namespace fs = std::filesystem;

namespace {

// Names of the folders a writer of `folder` leaves beside it (or inside it,
// when the swap cannot be atomic).
std::string siblingPrefix(const fs::path& folder) {
  return "." + folder.filename().string() + ".tofsim-staging-";
}
constexpr const char* kInsidePrefix = ".tofsim-staging-";

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

fs::path normalised(const fs::path& folder) {
  fs::path p = fs::absolute(folder).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();  // "out/" -> "out"
  return p;
}

// The folder is a mount point, or its parent cannot take a sibling: then
// nothing can be swapped with it and staging goes inside.
bool canStageBeside(const fs::path& folder) {
  struct stat self {
  }, parent{};
  if (::stat(folder.c_str(), &self) != 0 || ::stat(folder.parent_path().c_str(), &parent) != 0) {
    return false;
  }
  return self.st_dev == parent.st_dev && ::access(folder.parent_path().c_str(), W_OK) == 0;
}

bool exchange(const fs::path& a, const fs::path& b) {
  return ::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0;
}

// A link at the folder's name is written through: the results go into its
// target, and the swap is done on the target, so the link stays a link (a
// swap on the link's name would replace it by a real folder and leave the
// target as it was). A link to anything but a folder is an error.
fs::path linkTarget(const fs::path& given, const fs::path& link) {
  std::error_code ec;
  const fs::path to = fs::read_symlink(link, ec);
  const fs::path target = fs::canonical(link, ec);
  if (ec) {
    throw InputError(FileLoc{given.string()}, "",
                     "the output folder is a symbolic link to " + to.string() +
                         ", which does not exist (" + ec.message() +
                         "); create the folder it names or remove the link");
  }
  if (!fs::is_directory(target, ec)) {
    throw InputError(
        FileLoc{given.string()}, "",
        "the output folder is a symbolic link to " + to.string() + ", which is not a directory");
  }
  return target;
}

}  // namespace

void linkTree(const fs::path& from, const fs::path& to) {
  if (fs::is_symlink(from)) {
    fs::copy_symlink(from, to);
  } else if (fs::is_directory(from)) {
    fs::create_directory(to);
    for (const fs::directory_entry& e : fs::directory_iterator(from)) {
      linkTree(e.path(), to / e.path().filename());
    }
  } else {
    fs::create_hard_link(from, to);
  }
}

StagedFolder::StagedFolder(const fs::path& folder, KeepRule keep)
    : folder_(normalised(folder)), keep_(std::move(keep)) {
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(folder_, ec))) {
    linkedFrom_ = folder;
    folder_ = linkTarget(folder, folder_);
  }
  if (fs::exists(folder_, ec) && !fs::is_directory(folder_, ec)) {
    throw InputError(FileLoc{folder.string()}, "",
                     "output directory exists and is not a directory");
  }
  created_ = !fs::exists(folder_, ec);
  fs::create_directories(folder_, ec);
  if (ec) {
    throw InputError(FileLoc{folder.string()}, "",
                     "cannot create output directory: " + ec.message());
  }
  lock_ = std::make_unique<FolderLock>(folder_);
  removeDeadStaging();
  siblingStaging_ = canStageBeside(folder_);
  const std::string pid = std::to_string(::getpid());
  staging_ = siblingStaging_ ? folder_.parent_path() / (siblingPrefix(folder_) + pid)
                             : folder_ / (kInsidePrefix + pid);
  // A new folder, never one met at that name (mkdir does not follow a link
  // there): what it holds is this run's alone.
  if (::mkdir(staging_.c_str(), 0777) != 0) {
    throw InputError(FileLoc{staging_.string()}, "",
                     "cannot create staging folder: " + std::string(std::strerror(errno)));
  }
}

StagedFolder::~StagedFolder() {
  std::error_code ec;
  if (!committed_) fs::remove_all(staging_, ec);
  if (created_ && !committed_) {
    // Nothing of this run's remains; a folder it made for nothing goes too.
    bool onlyLock = true;
    for (const fs::directory_entry& e : fs::directory_iterator(folder_, ec)) {
      if (e.path().filename() != FolderLock::kFileName) onlyLock = false;
    }
    lock_.reset();
    if (onlyLock && !ec) fs::remove_all(folder_, ec);
  }
}

bool StagedFolder::isStaging(const std::string& name) {
  return startsWith(name, ".") && name.find(kInsidePrefix) != std::string::npos;
}

void StagedFolder::removeDeadStaging() const {
  // This process holds the lock, so every staging folder of this folder
  // belongs to a writer that died (or to a swap's leftover earlier set).
  std::error_code ec;
  const std::string sibling = siblingPrefix(folder_);
  std::vector<fs::path> dead;
  for (const fs::directory_entry& e : fs::directory_iterator(folder_.parent_path(), ec)) {
    if (startsWith(e.path().filename().string(), sibling)) dead.push_back(e.path());
  }
  for (const fs::directory_entry& e : fs::directory_iterator(folder_, ec)) {
    if (startsWith(e.path().filename().string(), kInsidePrefix)) dead.push_back(e.path());
  }
  for (const fs::path& p : dead) fs::remove_all(p, ec);
}

void StagedFolder::keepEarlierEntries() const {
  // The lock file moves along (same inode), so the lock stays held across the swap.
  fs::create_hard_link(lock_->lockFile(), staging_ / FolderLock::kFileName);
  if (!keep_) return;
  for (const fs::directory_entry& e : fs::directory_iterator(folder_)) {
    const std::string name = e.path().filename().string();
    if (name == FolderLock::kFileName || startsWith(name, kInsidePrefix) || !keep_(name)) continue;
    if (!fs::exists(fs::symlink_status(staging_ / name))) linkTree(e.path(), staging_ / name);
  }
}

void StagedFolder::replaceEntryByEntry() const {
  // Not atomic: the earlier entries go first, then the new ones move in.
  for (const fs::directory_entry& e : fs::directory_iterator(folder_)) {
    const std::string name = e.path().filename().string();
    if (name == FolderLock::kFileName || e.path() == staging_) continue;
    fs::remove_all(e.path());
  }
  for (const fs::directory_entry& e : fs::directory_iterator(staging_)) {
    if (e.path().filename() == FolderLock::kFileName) continue;
    fs::rename(e.path(), folder_ / e.path().filename());
  }
  fs::remove_all(staging_);
}

bool StagedFolder::commit() {
  TOFSIM_CHECK_MSG(!committed_, "StagedFolder committed twice");
  try {
    keepEarlierEntries();
  } catch (const fs::filesystem_error& e) {
    throw InputError(FileLoc{folder_.string()}, "",
                     std::string("cannot carry the earlier files into the new set: ") + e.what());
  }
  if (siblingStaging_ && exchange(staging_, folder_)) {
    committed_ = true;
    std::error_code ec;
    fs::remove_all(staging_, ec);  // now the earlier set; a leftover is cleaned by the next writer
    return true;
  }
  if (siblingStaging_ && errno != EINVAL && errno != ENOSYS && errno != ENOTSUP && errno != EXDEV &&
      errno != EBUSY) {
    throw InputError(FileLoc{folder_.string()}, "",
                     "cannot replace the folder's contents: " + std::string(std::strerror(errno)));
  }
  try {
    replaceEntryByEntry();
  } catch (const fs::filesystem_error& e) {
    throw InputError(FileLoc{folder_.string()}, "",
                     std::string("cannot replace the folder's contents: ") + e.what());
  }
  committed_ = true;
  return false;
}

}  // namespace tofsim
