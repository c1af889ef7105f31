#pragma once
// OpenEXR images: float32 (FLOAT) channels, scanline, ZIP compression.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/volume/TransientVolume.h"

namespace tofsim::io {

/// Writes image.channels channels named channelNames (e.g. {"R","G","B"},
/// {"Y"}, {"Z"}; one name per channel, unique, non-empty). Atomic: written to
/// a temporary name and renamed into place; the temporary is removed on error.
void writeExr(const std::filesystem::path& path, const Image& image,
              const std::vector<std::string>& channelNames);

/// Reads every channel as float. Channel order: the order the file was
/// written in by writeExr; for other files R, G, B, A first, then the rest in
/// the file's (alphabetical) order. channelNames, if given, receives the names.
Image readExr(const std::filesystem::path& path, std::vector<std::string>* channelNames = nullptr);

}  // namespace tofsim::io
