#pragma once
// A folder whose whole contents are replaced at once. A run writes its new
// set of files into staging() and commit() swaps it with the folder's earlier
// set in one rename(2) (renameat2 with RENAME_EXCHANGE on a sibling staging
// folder), so SIGINT, SIGTERM or SIGKILL at any moment leave either the
// complete earlier set or the complete new one: never a mix, never nothing
// where something was. Files of the earlier set that the new run does not
// produce go at the commit, not before.
//
// The folder is locked (FolderLock) for the object's lifetime: one writer per
// folder. Staging folders of dead writers (a SIGKILL leaves one behind) are
// removed when the next writer takes the lock.
//
// A folder path that is a symbolic link to a directory is written through:
// the new set goes into the link's target (staged beside the target and
// swapped there), and the link stays a link; linkedFrom() says so. A link to
// anything else, or a dangling one, is an error.
//
// Where the swap cannot be atomic (the folder is a mount point, its parent is
// not writable, or the file system has no RENAME_EXCHANGE, e.g. NFS), entries
// are moved one by one and replaced() says so.

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "tofsim/util/FolderLock.h"

namespace tofsim {

class StagedFolder {
 public:
  /// Which top-level entries of the earlier set the new set keeps; they are
  /// hard-linked into the new set at commit unless the new run wrote its own.
  using KeepRule = std::function<bool(const std::string& name)>;

  /// Creates `folder` when absent, locks it (InputError when another process
  /// holds it), removes dead writers' staging folders, and makes a staging folder.
  explicit StagedFolder(const std::filesystem::path& folder, KeepRule keep = {});
  /// Without commit(): removes the staging folder, and the folder itself when
  /// this object created it and it holds nothing but the lock.
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  const std::filesystem::path& folder() const { return folder_; }
  /// Where the new set is written.
  const std::filesystem::path& staging() const { return staging_; }
  /// Whether this object created the folder.
  bool created() const { return created_; }
  /// The path given, when it is a symbolic link (folder() is then its
  /// target); empty otherwise.
  const std::filesystem::path& linkedFrom() const { return linkedFrom_; }

  /// Whether `name` is that of a staging folder a StagedFolder makes (of any
  /// folder; beside it or inside it).
  static bool isStaging(const std::string& name);

  /// Makes the staged set the folder's contents. Returns false when the swap
  /// had to be done entry by entry (not atomic, see above).
  bool commit();

 private:
  void removeDeadStaging() const;
  void keepEarlierEntries() const;
  void replaceEntryByEntry() const;

  std::filesystem::path folder_;
  std::filesystem::path linkedFrom_;
  std::filesystem::path staging_;
  KeepRule keep_;
  bool created_ = false;
  bool siblingStaging_ = true;  ///< staging beside the folder (swap) or inside it (moves)
  bool committed_ = false;
  std::unique_ptr<FolderLock> lock_;
};

/// Hard links (files) or copies of the structure (folders) of `from` at
/// `to`, links copied as links: a tree carried into a staged set at no cost
/// in copies or space. `to` and `from` must be on one file system.
void linkTree(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace tofsim
