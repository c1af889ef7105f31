#pragma once
// A render's saved outputs read back for the sensors: transient.npy with its
// time axis from transient.json, and direct.npy and depth.exr when present.
// A render with output.format: hdf5 saved its volumes as the datasets of
// capture.h5 (transient, direct, ...) instead: where the folder has a
// capture.h5, every volume is read from it (a run of pixels through one
// hyperslab selection), with the same checks and the same values.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/sensors/SensorStream.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::pipeline {

namespace detail {
class ComponentReader;  // one saved volume, .npy or a dataset of capture.h5
}

/// Whether the render in `directory` saved the volume `component`
/// (`transient`, `direct`, `indirect`, `bounce<k>`): <component>.npy, or
/// the dataset of its capture.h5.
bool hasSavedComponent(const std::filesystem::path& directory, const std::string& component);
/// Where `component` is or would be saved, for messages: <component>.npy, or
/// "capture.h5:/<component>".
std::string savedComponentName(const std::filesystem::path& directory,
                               const std::string& component);

struct SavedVolume {
  TransientVolume volume;                     ///< transient.npy, axis from transient.json
  std::optional<TransientVolume> directOnly;  ///< direct.npy, when the render wrote it
  std::optional<Image> depth_m;               ///< depth.exr, when the render wrote it
};

/// Throws InputError naming the file when transient.npy or transient.json is
/// missing or unreadable, or when the files disagree on the shape; and
/// naming the value too when one is NaN, infinite or negative past
/// round-off (no radiance). SavedVolumeStream and loadSavedComponent check
/// the values alike, each run of pixels as it is read.
SavedVolume loadSavedVolume(const std::filesystem::path& directory);

/// The render's `indirect_bounces` from its transient.json (how many bounces
/// its light has: what bounce<k>.npy can hold); InputError naming the file
/// when it is not there (a transient.json of an older tofsim).
int32_t savedIndirectBounces(const std::filesystem::path& transientJson);

/// A saved render opened to be read a run of pixels at a time, never whole:
/// transient.npy and those of `components` saved beside it (`direct`,
/// `bounce<k>`: `<name>.npy`; absent ones are skipped), their headers and
/// sizes checked as loadSavedVolume checks them before any value is read;
/// depth.exr (one image) is read whole. What it holds is one run of each
/// file.
class SavedVolumeStream {
 public:
  SavedVolumeStream(const std::filesystem::path& directory,
                    const std::vector<std::string>& components);
  ~SavedVolumeStream();
  SavedVolumeStream(const SavedVolumeStream&) = delete;
  SavedVolumeStream& operator=(const SavedVolumeStream&) = delete;

  const sensors::VolumeShape& shape() const { return shape_; }
  /// Whether `component`'s .npy was saved.
  bool has(const std::string& component) const;
  const Image* depth_m() const { return depth_m_ ? &*depth_m_ : nullptr; }

  /// Reads the next run of at most maxPixels pixels (>= 1) of every file;
  /// returns its length, 0 once every pixel has been read.
  std::size_t read(std::size_t maxPixels);
  /// The first pixel of the run read last.
  std::size_t firstPixel() const { return firstPixel_; }
  /// The run read last of `component` ("transient" for the total), nullptr
  /// when it was not saved; valid until the next read().
  const float* values(const std::string& component) const;

 private:
  struct File {
    std::string name;
    std::unique_ptr<detail::ComponentReader> reader;
    std::vector<float> values;
  };
  sensors::VolumeShape shape_;
  std::vector<File> files_;
  std::optional<Image> depth_m_;
  std::size_t next_ = 0, firstPixel_ = 0;
};

/// A light component saved beside transient.npy (`direct`, `indirect`,
/// `bounce<k>`: `<name>.npy`), read with transient.json's time axis, or
/// nothing when the render did not write it. Throws InputError like
/// loadSavedVolume when the file's shape disagrees with transient.json.
std::optional<TransientVolume> loadSavedComponent(const std::filesystem::path& directory,
                                                  const std::string& name);

}  // namespace tofsim::pipeline
