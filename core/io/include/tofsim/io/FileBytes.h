#pragma once
// A small input file read whole, opened without following a link
// (O_NOFOLLOW: a symbolic link planted at the configured name is refused,
// not read through) and only if it is a regular file of at most maxBytes
// (a .npy among them is decoded by io::parseNpy, NpyBytes.h).

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "tofsim/io/NpyBytes.h"  // parseNpy: the .npy in those bytes

namespace tofsim::io {

/// The file's bytes. Throws InputError naming the file when it is a link,
/// not a regular file, larger than maxBytes, or cannot be read.
std::string readFileNoFollow(const std::filesystem::path& path, std::size_t maxBytes);


}  // namespace tofsim::io
