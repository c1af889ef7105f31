#include "Downsample.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tofsim::viewer {

std::size_t reducedSize(std::size_t size, std::size_t factor) {
  return (size + factor - 1) / factor;
}

Reduction planReduction(std::size_t height, std::size_t width, std::size_t bins,
                        std::size_t channels, std::size_t budget) {
  Reduction r;
  const auto values = [&] {
    return reducedSize(height, r.pixelBlock) * reducedSize(width, r.pixelBlock) *
           reducedSize(bins, r.binRun) * channels;
  };
  bool mergeBins = true;
  while (values() > budget) {
    const std::size_t nowBins = reducedSize(bins, r.binRun);
    const std::size_t nowSide = reducedSize(std::max(height, width), r.pixelBlock);
    // Each side keeps its floor while the other can shrink; past both floors
    // they shrink in turn down to one value.
    const bool bins64 = nowBins > 64, side16 = nowSide > 16;
    bool doBins = mergeBins;
    if (bins64 != side16) doBins = bins64;
    if (!bins64 && !side16 && (nowBins == 1 || nowSide == 1)) doBins = nowBins > 1;
    if (nowBins == 1 && nowSide == 1) break;  // one value per channel: nothing shrinks
    if (doBins) {
      r.binRun *= 2;
    } else {
      r.pixelBlock *= 2;
    }
    mergeBins = !mergeBins;
  }
  return r;
}

std::size_t planPixelBlock(std::size_t height, std::size_t width, std::size_t channels,
                           std::size_t budget) {
  std::size_t block = 1;
  while (reducedSize(height, block) * reducedSize(width, block) * channels > budget &&
         (reducedSize(height, block) > 1 || reducedSize(width, block) > 1)) {
    block *= 2;
  }
  return block;
}

std::vector<float> blockMean(const std::vector<float>& image, std::size_t height, std::size_t width,
                             std::size_t channels, std::size_t pixelBlock) {
  if (pixelBlock == 1) return image;
  const std::size_t h = reducedSize(height, pixelBlock), w = reducedSize(width, pixelBlock);
  std::vector<double> sum(h * w * channels, 0.0);
  std::vector<std::size_t> count(h * w * channels, 0);
  for (std::size_t y = 0; y < height; ++y) {
    for (std::size_t x = 0; x < width; ++x) {
      for (std::size_t c = 0; c < channels; ++c) {
        const float v = image[(y * width + x) * channels + c];
        if (std::isnan(v)) continue;
        const std::size_t at = ((y / pixelBlock) * w + x / pixelBlock) * channels + c;
        sum[at] += v;
        ++count[at];
      }
    }
  }
  std::vector<float> out(sum.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = count[i] ? static_cast<float>(sum[i] / static_cast<double>(count[i]))
                      : std::numeric_limits<float>::quiet_NaN();
  }
  return out;
}

}  // namespace tofsim::viewer
