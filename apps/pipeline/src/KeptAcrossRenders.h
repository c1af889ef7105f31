#pragma once
// Private to the pipeline: the files of an output folder that a render's
// staged replacement keeps (StagedFolder's `keep`), for camera and NLOS runs.

#include <string>

namespace tofsim::pipeline {

/// A batch's log.txt is written by the batch while this run goes: it belongs
/// to the folder, not to any one set of results.
inline bool keptAcrossRenders(const std::string& name) { return name == "log.txt"; }

}  // namespace tofsim::pipeline
