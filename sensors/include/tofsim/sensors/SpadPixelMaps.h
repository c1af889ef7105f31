#pragma once
// A SPAD array's fixed pattern: per-pixel PDE and dark count rate, hot and
// dead pixels, drawn from the sensor's fpn_seed alone (SpadParams), so a
// device keeps its pattern under every noise seed, thread count and frame.
// Model: sensors/README.md, "Array non-uniformity".

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {

enum class SpadPixelClass : uint8_t { Normal, Hot, Dead };

struct SpadPixel {
  double pde;
  double dcr_per_s;
  SpadPixelClass kind;
  double gate_skew_s = 0.0;  ///< the pixel's gate shift (gate_skew_sigma_s)
};

struct SpadPixelMaps {
  std::vector<double> pde;           ///< per pixel, row-major (y, x)
  std::vector<double> dcr_per_s;     ///< per pixel, counts / s
  std::vector<SpadPixelClass> kind;  ///< per pixel
  std::vector<double> gate_skew_s;   ///< per pixel, s (0 without gate_skew_sigma_s)
  int64_t hot = 0, dead = 0;         ///< pixels of each class
};

/// True when any fixed-pattern parameter is set (otherwise every pixel has
/// pde and dark_count_rate_per_s, and no map is written).
bool spadHasPixelMaps(const SpadParams& p);

/// Pixel px = y * width + x: from its own stream of fpn_seed, four numbers
/// in a fixed order (dead, hot, PDE, DCR), whichever parameters are set, so
/// changing one fraction leaves the others' pattern as it was; the gate skew
/// from a stream of its own (the pattern above does not change with it).
SpadPixel spadPixel(const SpadParams& p, std::size_t px);

/// spadPixel of every pixel of a height x width array, and the class counts.
SpadPixelMaps spadPixelMaps(const SpadParams& p, int32_t height, int32_t width);

}  // namespace tofsim::sensors
