#pragma once
// A render's arrays in one HDF5 file (output.format: hdf5, `capture.h5`):
// float32 datasets, C order, named by path ("transient", "sensors/spad/
// spad_counts"), each chunked along its pixels (a pixel's histogram or a time
// slice reads a few chunks, not the file: Hdf5Chunks.h) and compressed with
// shuffle + deflate, filters every HDF5 build and h5py read without plugins;
// metadata as attributes (strings, numbers, lists of strings). HDF5 stays in
// tofsim_io: this header names none of its types.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "tofsim/io/Npy.h"

namespace tofsim::io {

/// One attribute of a dataset: a UTF-8 string, a float64, an int64 or a list
/// of strings (what h5py reads back as str, float, int and an array of str).
struct H5Attribute {
  std::string name;
  std::variant<std::string, double, int64_t, std::vector<std::string>> value;
};

/// A dataset whose values arrive in pieces, in C order (a volume's segments):
/// it holds at most one block of chunks (one row's run of chunk columns) and
/// writes each block when it is complete, so every chunk is written once,
/// whole. Owned by its H5CaptureWriter.
class H5FloatStream {
 public:
  ~H5FloatStream();
  H5FloatStream(const H5FloatStream&) = delete;
  H5FloatStream& operator=(const H5FloatStream&) = delete;

  /// Appends `count` values in C order; InputError naming the file and the
  /// dataset past the end or when HDF5 fails.
  void append(const float* data, std::size_t count);
  std::size_t appended() const { return appended_; }
  std::size_t expected() const { return expected_; }

 private:
  friend class H5CaptureWriter;
  struct Impl;
  explicit H5FloatStream(std::unique_ptr<Impl> impl, std::size_t expected);
  void flushBlock();

  std::unique_ptr<Impl> impl_;
  std::size_t expected_ = 0, appended_ = 0;
};

/// Writes one file atomically: into "<path>.tmp-<pid>" (tofsim/util/AtomicFile.h),
/// renamed over `path` by commit(); destroyed without commit() (an exception,
/// an interrupted run) it removes the temporary and leaves an earlier file at
/// `path` as it was. The objects carry no time stamps: the same calls give
/// the same bytes.
class H5CaptureWriter {
 public:
  /// `threads`: how many compress a streamed block's chunks at once (0 =
  /// every core; the bytes do not depend on it).
  explicit H5CaptureWriter(std::filesystem::path path, int threads = 0);
  ~H5CaptureWriter();
  H5CaptureWriter(const H5CaptureWriter&) = delete;
  H5CaptureWriter& operator=(const H5CaptureWriter&) = delete;

  /// A float32 dataset of `shape` (rank >= 3: rows, columns, then each
  /// pixel's values) written piece by piece; valid until commit().
  H5FloatStream& stream(const std::string& name, const NpyShape& shape);
  /// A float32 dataset of any rank written whole.
  void write(const std::string& name, const NpyShape& shape, const float* data);
  /// Adds attributes to the dataset `name` (written already or streaming).
  void setAttributes(const std::string& name, const std::vector<H5Attribute>& attributes);
  /// A one-dimensional float64 dataset `name` holding an axis's coordinates,
  /// made an HDF5 dimension scale (H5DSset_scale, libhdf5's high-level
  /// library: what netCDF-4 and xarray read as a coordinate), with
  /// `attributes` (units, long_name).
  void writeScale(const std::string& name, const std::vector<double>& values,
                  const std::vector<H5Attribute>& attributes);
  /// Attaches the scale `scale` (writeScale) to axis `axis` of the dataset
  /// `name` and labels that axis with the scale's name.
  void attachScale(const std::string& name, unsigned axis, const std::string& scale);
  /// Checks that every stream is complete, closes the file and renames it
  /// into place; InputError naming the file (and the dataset) otherwise.
  void commit();

  const std::filesystem::path& path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Reads a file written by H5CaptureWriter (or any HDF5 file of float
/// datasets whose chunks are all written). Every failure, a missing or
/// damaged file included, is an InputError naming the file and the dataset;
/// a shape that declares more values than the file's stored bytes can hold
/// is one, so callers may allocate from shape(). libhdf5's own parser is not
/// safe on hostile files (fuzz/README.md): read files of trusted origin.
class H5CaptureReader {
 public:
  explicit H5CaptureReader(std::filesystem::path path);
  ~H5CaptureReader();
  H5CaptureReader(const H5CaptureReader&) = delete;
  H5CaptureReader& operator=(const H5CaptureReader&) = delete;

  const std::filesystem::path& path() const;
  /// Whether the dataset `name` exists.
  bool has(const std::string& name) const;
  NpyShape shape(const std::string& name) const;
  /// The whole dataset.
  NpyArray read(const std::string& name) const;
  /// The box start .. start + count (one entry per axis), C order.
  std::vector<float> readSlab(const std::string& name, const NpyShape& start,
                              const NpyShape& count) const;
  /// `pixels` consecutive pixels from `firstPixel` (row-major over the first
  /// two axes, each pixel all of the axes after them) into `out`.
  void readPixels(const std::string& name, std::size_t firstPixel, std::size_t pixels,
                  float* out) const;
  /// The string attribute `attribute` of `name`, if it has one.
  std::optional<std::string> stringAttribute(const std::string& name,
                                             const std::string& attribute) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tofsim::io
