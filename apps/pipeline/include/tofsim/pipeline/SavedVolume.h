#pragma once
// A render's saved outputs read back for the sensors: transient.npy with its
// time axis from transient.json, and direct.npy and depth.exr when present.

#include <filesystem>
#include <optional>
#include <string>

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

/// The render's `indirect_bounces` from its transient.json (how many bounces
/// its light has: what bounce<k>.npy can hold); InputError naming the file
/// when it is not there (a transient.json of an older tofsim).
int32_t savedIndirectBounces(const std::filesystem::path& transientJson);

/// A light component saved beside transient.npy (`direct`, `indirect`,
/// `bounce<k>`: `<name>.npy`), read with transient.json's time axis, or
/// nothing when the render did not write it. Throws InputError like
/// loadSavedVolume when the file's shape disagrees with transient.json.
std::optional<TransientVolume> loadSavedComponent(const std::filesystem::path& directory,
                                                  const std::string& name);

}  // namespace tofsim::pipeline
