#pragma once
// NumPy .npy files of float32 ('<f4'), C order, any rank.
//
// Format: https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html
// Written files are version 1.0 with the header padded so that the data starts
// at a multiple of 64 bytes. The reader accepts versions 1.0 and 2.0.
// Every writer is atomic: the file appears under its final name only when
// complete (see tofsim/util/AtomicFile.h).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tofsim/util/AtomicFile.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::io {

using NpyShape = std::vector<std::size_t>;

/// Number of elements of an array of this shape (1 for rank 0).
std::size_t elementCount(const NpyShape& shape);

struct NpyArray {
  NpyShape shape;
  std::vector<float> data;  ///< C order, elementCount(shape) values
};

/// Writes product(shape) floats from data.
void writeNpy(const std::filesystem::path& path, const NpyShape& shape, const float* data);
/// Shape (H, W, T, C).
void writeNpy(const std::filesystem::path& path, const TransientVolume& volume);
/// Shape (H, W, C).
void writeNpy(const std::filesystem::path& path, const Image& image);

/// Reads a float32 little-endian C-order array. Throws InputError naming the
/// file for anything else (bad magic, other dtype, Fortran order, truncation).
NpyArray readNpy(const std::filesystem::path& path);

/// A .npy read piece by piece in C order (volumes too large to hold:
/// `tofsim sense`); readNpy reads through one.
class NpyStreamReader {
 public:
  /// Opens the file and checks its header and size as readNpy does (throws
  /// InputError naming the file: bad magic, other dtype, Fortran order,
  /// truncation, trailing bytes); reads no data.
  explicit NpyStreamReader(const std::filesystem::path& path);

  const NpyShape& shape() const { return shape_; }
  /// Values not read yet.
  std::size_t remaining() const { return count_ - read_; }
  /// The next `count` values (at most remaining()) into `out`. Throws
  /// InputError naming the file when the read fails.
  void read(float* out, std::size_t count);

 private:
  std::string name_;
  std::ifstream in_;
  NpyShape shape_;
  std::size_t count_ = 0;
  std::size_t read_ = 0;
};

/// Writes a .npy whose data arrives in pieces (e.g. row tiles of an
/// out-of-core render). The header is written first; commit() checks that
/// exactly product(shape) floats were appended, then renames into place.
/// Destroyed without commit(), it leaves no file behind.
class NpyStreamWriter {
 public:
  NpyStreamWriter(std::filesystem::path path, NpyShape shape);
  NpyStreamWriter(NpyStreamWriter&&) noexcept = default;
  NpyStreamWriter& operator=(NpyStreamWriter&&) noexcept = default;

  /// Appends count floats in C order. Throws InputError past product(shape).
  void append(const float* data, std::size_t count);
  /// Throws InputError (and removes the temporary) unless complete.
  void commit();

  std::size_t appended() const { return appended_; }
  std::size_t expected() const { return expected_; }

 private:
  AtomicFile file_;
  NpyShape shape_;
  std::size_t expected_ = 0;
  std::size_t appended_ = 0;
};

}  // namespace tofsim::io
