#pragma once
// Pictures for people to look at (PNG through OpenCV). Numbers live in .npy
// and .exr; these are views of them and never the data of record.

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "tofsim/volume/TransientVolume.h"

namespace tofsim::imaging {

enum class ToneMap {
  Global,  ///< linear, scaled so the 99.5th percentile maps to white, then sRGB
  Log,     ///< log10 over 4 decades below the 99.5th percentile
};

/// Tone-mapped 8-bit sRGB PNG of a linear RGB (or 1-channel) image. With
/// `range`, values lo..hi map linearly to black..white (the same for every
/// run; the tone map's automatic white is ignored).
void writeToneMappedPng(const std::filesystem::path& path, const Image& image, ToneMap mode,
                        const std::optional<std::array<double, 2>>& range = std::nullopt);

/// Image rows that are samples of an axis (a streak image's time bins): row r
/// covers [start + r step, start + (r + 1) step), ticked on the left.
struct RowAxis {
  double start = 0.0;
  double step = 1.0;
  std::string label;  ///< e.g. "time [ns]"
};

/// How a scalar picture maps values to colours.
struct ColorScale {
  /// A matplotlib name mapped to OpenCV's COLORMAP_* (viridis, inferno,
  /// magma, plasma, turbo, jet, hot, ...) or "coolwarm" (diverging); unknown
  /// names give turbo.
  std::string colormap = "turbo";
  /// Fixed [lo, hi] (the same colours across runs). Unset: a robust range
  /// of the data (its 0.5th to 99.5th percentile, narrowed to the quartiles
  /// -+ 3 IQR unless a quarter of the pixels sit at the minimum).
  std::optional<std::array<double, 2>> range;
  /// Who fixed `range`, for the picture's caption: "fixed range (<this>)".
  std::string rangeSource = "plot_ranges";
  /// Signed values centred on 0: the colormap becomes "coolwarm" and the
  /// automatic range symmetric about 0, so white-grey means no error.
  bool diverging = false;
  /// Also treat values <= 0 as no data (depth.png: 0 = no surface), so the
  /// range spans the surfaces only.
  bool nonPositiveIsNoData = false;
  /// What no-data pixels (non-finite, or <= 0 as above) mean, shown beside
  /// the grey swatch under the colour bar.
  std::string noDataLabel = "NaN";
  std::optional<RowAxis> rows;
};

/// What a colour-mapped picture showed, and where.
struct ColorScaleUsed {
  double lo = 0.0, hi = 1.0;
  bool automatic = true;  ///< the range came from the data, not ColorScale::range
  /// Values below lo / above hi exist: drawn in the end colour, and the bar
  /// has a triangle at that end (matplotlib's "extend").
  bool clippedLow = false, clippedHigh = false;
  double loPercentile = 0.0, hiPercentile = 100.0;  ///< of lo and hi among the valid pixels
  int noDataPixels = 0;
  std::array<int, 4> imageRect{}, barRect{};  ///< x, y, width, height in the PNG
};

/// No-data pixels are drawn in this grey (BGR = RGB), never a colormap colour.
inline constexpr unsigned char kNoDataGrey = 128;

/// A 1-channel image through a colormap, titled `label` (e.g. "depth [m]"),
/// with a colour bar whose ticks give the values, end triangles where values
/// are clipped, a caption saying the range (automatic: at which percentiles,
/// or fixed) and a grey no-data swatch when there are such pixels.
ColorScaleUsed writeColormappedPng(const std::filesystem::path& path, const Image& image,
                                   const std::string& label, const ColorScale& scale = {});

}  // namespace tofsim::imaging
