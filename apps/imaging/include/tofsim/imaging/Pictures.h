#pragma once
// Pictures for people to look at (PNG through OpenCV). Numbers live in .npy
// and .exr; these are views of them and never the data of record.

#include <filesystem>
#include <string>

#include "tofsim/volume/TransientVolume.h"

namespace tofsim::imaging {

enum class ToneMap {
  Global,  ///< linear, scaled so the 99.5th percentile maps to white, then sRGB
  Log,     ///< log10 over 4 decades below the 99.5th percentile
};

/// Tone-mapped 8-bit sRGB PNG of a linear RGB (or 1-channel) image.
void writeToneMappedPng(const std::filesystem::path& path, const Image& image, ToneMap mode);

/// A 1-channel image through a colormap, titled `label` (e.g. "depth [m]"),
/// with a colour bar whose ticks give the values. `colormap` is a matplotlib
/// name mapped to OpenCV's COLORMAP_* (viridis, inferno, magma, plasma,
/// turbo, jet, hot, ...); unknown names give turbo. Non-finite values are
/// drawn black. lo == hi: a robust range of the data (its 0.5th to 99.5th
/// percentile, narrowed to the quartiles -+ 3 IQR unless a quarter of the
/// pixels sit at the minimum); values outside the range are clamped.
void writeColormappedPng(const std::filesystem::path& path, const Image& image,
                         const std::string& label, const std::string& colormap = "turbo",
                         double lo = 0.0, double hi = 0.0);

}  // namespace tofsim::imaging
