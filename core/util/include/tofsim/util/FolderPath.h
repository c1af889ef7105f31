#pragma once
// Whether an output folder can be made where a user asked for it, before any
// work starts: a file in its place (or in place of a folder above it) would
// otherwise end in the standard library's bare "filesystem error: cannot
// create directories", with neither the option nor the key that named it.

#include <filesystem>
#include <string>

namespace tofsim {

/// "" when `folder` is a folder, or when the nearest part of its path that
/// exists is one (so create_directories can make the rest); else what is in
/// the way: "/x/out.txt is a file, not a folder". Links are followed: a link
/// to a folder is a folder here.
std::string folderPathProblem(const std::filesystem::path& folder);

}  // namespace tofsim
