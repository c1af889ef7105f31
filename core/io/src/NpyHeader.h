#pragma once
// Encoding and decoding of the .npy preamble (magic, version, header dict).

#include <cstddef>
#include <string>
#include <string_view>

#include "tofsim/io/Npy.h"

namespace tofsim::io::detail {

/// Whole v1.0 preamble for a '<f4' C-order array: magic, version, length and
/// the dict padded with spaces and '\n' to a multiple of 64 bytes.
std::string encodeNpyHeader(const NpyShape& shape);

struct NpyHeaderInfo {
  NpyShape shape;
  std::size_t dataOffset = 0;  ///< bytes from the start of the file to the data
  bool float64 = false;        ///< '<f8' (only with allowFloat64)
};

/// Parses the preamble at the start of prefix (which holds at least the whole
/// preamble, or the whole file if it is shorter). Throws InputError naming file.
/// The dtype is '<f4', or with allowFloat64 '<f4' or '<f8'.
NpyHeaderInfo decodeNpyHeader(std::string_view prefix, const std::string& file,
                              bool allowFloat64 = false);

/// product(shape), throwing InputError naming file on size_t overflow.
std::size_t checkedElementCount(const NpyShape& shape, const std::string& file);

}  // namespace tofsim::io::detail
