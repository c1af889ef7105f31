#pragma once
// A small input file read whole, opened without following a link
// (O_NOFOLLOW: a symbolic link planted at the configured name is refused,
// not read through) and only if it is a regular file of at most maxBytes,
// and a .npy decoded from those bytes (the checks of readNpy, Npy.h).

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "tofsim/io/Npy.h"

namespace tofsim::io {

/// The file's bytes. Throws InputError naming the file when it is a link,
/// not a regular file, larger than maxBytes, or cannot be read.
std::string readFileNoFollow(const std::filesystem::path& path, std::size_t maxBytes);

/// The float32 .npy in `bytes` (`name` for errors): throws InputError as
/// readNpy does (bad magic, other dtype, Fortran order, truncation, trailing
/// bytes).
NpyArray parseNpy(std::string_view bytes, const std::string& name);

}  // namespace tofsim::io
