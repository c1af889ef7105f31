#pragma once
// depth.exr: one float image of metres that every common reader finds. The
// same values are stored twice, as channel Y (luminance: what OpenCV,
// imageio/FreeImage and image viewers read as a grey image; OpenCV ignores
// any other name) and as channel Z (the depth channel compositing tools such
// as Nuke and Blender look for). Both hold identical floats.

#include <filesystem>

#include "tofsim/volume/TransientVolume.h"

namespace tofsim::io {

/// Writes a one-channel image as channels Y and Z (atomic, as writeExr).
void writeDepthExr(const std::filesystem::path& path, const Image& depth_m);

/// The depth of a file written by writeDepthExr, or of one with a single
/// channel Z or Y (older tofsim versions wrote Z alone): one channel.
/// Throws InputError, naming the file, for anything else.
Image readDepthExr(const std::filesystem::path& path);

}  // namespace tofsim::io
