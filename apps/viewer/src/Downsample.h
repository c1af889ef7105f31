#pragma once
// How the viewer shrinks what would not fit its page: pixels averaged over
// square blocks, time bins summed in runs (a merged bin holds the light of
// its bins, as a wider bin of the render would). The page says both factors.

#include <cstddef>
#include <vector>

namespace tofsim::viewer {

/// Sizes after downsampling by whole factors (the last block or run may be
/// partial: it averages or sums what there is).
struct Reduction {
  std::size_t pixelBlock = 1;  ///< pixels averaged: pixelBlock x pixelBlock
  std::size_t binRun = 1;      ///< consecutive bins summed
};

std::size_t reducedSize(std::size_t size, std::size_t factor);

/// The smallest factors that fit height x width x bins x channels values
/// into `budget` values: bins are merged and pixels blocked in turn (bins
/// first), bins no further than 64 left while pixels can shrink, pixels no
/// further than 16 on the longer side while bins can.
Reduction planReduction(std::size_t height, std::size_t width, std::size_t bins,
                        std::size_t channels, std::size_t budget);

/// The pixel block that fits height x width x channels into `budget` values.
std::size_t planPixelBlock(std::size_t height, std::size_t width, std::size_t channels,
                           std::size_t budget);

/// An (height, width, channels) image averaged over pixelBlock x pixelBlock
/// blocks; NaN values are left out of a block's mean (all NaN: NaN).
std::vector<float> blockMean(const std::vector<float>& image, std::size_t height, std::size_t width,
                             std::size_t channels, std::size_t pixelBlock);

}  // namespace tofsim::viewer
