#pragma once
// A render's saved outputs read back for the sensors: transient.npy with its
// time axis from transient.json, and direct.npy and depth.exr when present.

#include <filesystem>
#include <optional>

#include "tofsim/volume/TransientVolume.h"

namespace tofsim::pipeline {

struct SavedVolume {
  TransientVolume volume;                     ///< transient.npy, axis from transient.json
  std::optional<TransientVolume> directOnly;  ///< direct.npy, when the render wrote it
  std::optional<Image> depth_m;               ///< depth.exr, when the render wrote it
};

/// Throws InputError naming the file when transient.npy or transient.json is
/// missing or unreadable, or when the files disagree on the shape.
SavedVolume loadSavedVolume(const std::filesystem::path& directory);

}  // namespace tofsim::pipeline
