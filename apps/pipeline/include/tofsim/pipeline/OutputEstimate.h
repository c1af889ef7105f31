#pragma once
// How many bytes a render's outputs will take, known before rendering, so
// that a run that cannot fit fails in a second instead of after writing
// gigabytes (a million time bins at 48x48 are two 29 GB files).
//
// The figures are upper bounds for what is uncompressed (the .npy volumes,
// EXR frames, sensor arrays) and rough for what is compressed (PNG, MP4).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"

namespace tofsim::pipeline {

struct OutputItem {
  std::string what;  ///< "transient.npy", "frames/*.exr", "sensors/spad"
  std::uintmax_t bytes;
  std::string drivenBy;  ///< the keys that set its size
};

struct OutputEstimate {
  std::vector<OutputItem> items;
  /// Disk needed during the run only (the video's and frames' bin-major
  /// copy of the volume): counted against the free space, not max_bytes.
  std::uintmax_t temporaryBytes = 0;
  std::uintmax_t totalBytes() const;
};

OutputEstimate estimateOutputs(const config::RunConfig& config);

/// Throws InputError naming the sizes and their keys when the estimate
/// exceeds output.max_bytes.
void checkMaxBytes(const OutputEstimate& estimate, const config::RunConfig& config);

/// What `validate` checks of a run's size, from the config alone: its outputs
/// against output.max_bytes, and an NLOS scan's memory against
/// render.memory_budget (NlosEstimate.h).
void checkRunSizes(const config::RunConfig& config);

/// checkMaxBytes, then the outputs with the temporary bytes against the free
/// space of `directory`'s file system.
void checkOutputsFit(const OutputEstimate& estimate, const config::RunConfig& config,
                     const std::filesystem::path& directory);

/// "27.0 GiB", "512.0 MiB", "12 B" (binary units, as the config's sizes).
std::string formatBytes(std::uintmax_t bytes);

}  // namespace tofsim::pipeline
