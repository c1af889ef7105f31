#pragma once
// Private to the pipeline: what a run says about its output folder's staged
// replacement (StagedFolder), worded once for render, sequence, nlos and sense.

#include "tofsim/pipeline/Progress.h"
#include "tofsim/util/StagedFolder.h"

namespace tofsim::pipeline {

/// A folder given as a symbolic link is written through (StagedFolder.h):
/// said once, before the run writes anything.
inline void noteLinkedOutput(const StagedFolder& folder, const Progress& progress) {
  if (folder.linkedFrom().empty()) return;
  progress.message(folder.linkedFrom().string() + " -> " + folder.folder().string() +
                   ": writing into the link's target");
}

/// Commits the staged set, saying so when the swap could not be atomic.
inline void commitOutput(StagedFolder& folder, const Progress& progress) {
  if (!folder.commit()) {
    progress.message("note: " + folder.folder().string() +
                     " could not be swapped atomically (mount point or file system without "
                     "RENAME_EXCHANGE); its files were replaced one by one");
  }
}

}  // namespace tofsim::pipeline
