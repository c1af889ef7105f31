#include "tofsim/sensors/SpadPixelMaps.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "tofsim/sensors/Random.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr uint32_t kFixedPatternTag = 0x4650;  // "FP"
constexpr uint32_t kGateSkewTag = 0x4753;      // "GS"

SpadPixel patternPixel(const SpadParams& p, std::size_t px) {
  if (!spadHasPixelMaps(p)) return {p.pde, p.dark_count_rate_per_s, SpadPixelClass::Normal};
  Rng rng(static_cast<uint64_t>(p.fpn_seed), pixelStream(kFixedPatternTag, px));
  const double uDead = rng.uniform(), uHot = rng.uniform();
  const double zPde = rng.normal(), zDcr = rng.normal();
  if (uDead < p.dead_pixel_fraction) return {0.0, 0.0, SpadPixelClass::Dead};
  const double pde = std::clamp(p.pde * (1.0 + p.pde_spread * zPde), 0.0, 1.0);
  if (uHot < p.hot_pixel_fraction) return {pde, p.hot_pixel_rate_per_s, SpadPixelClass::Hot};
  if (p.dark_count_map.present()) {  // measured: in place of the log-normal
    TOFSIM_CHECK(px < p.dark_count_map.rates_per_s.size());
    return {pde, p.dark_count_map.rates_per_s[px], SpadPixelClass::Normal};
  }
  return {pde, p.dark_count_rate_per_s * std::exp(p.dark_count_log_sigma * zDcr),
          SpadPixelClass::Normal};
}
}  // namespace

bool spadHasPixelMaps(const SpadParams& p) {
  return p.pde_spread > 0.0 || p.dark_count_log_sigma > 0.0 || p.hot_pixel_fraction > 0.0 ||
         p.dead_pixel_fraction > 0.0 || p.dark_count_map.present();
}

SpadPixel spadPixel(const SpadParams& p, std::size_t px) {
  SpadPixel pixel = patternPixel(p, px);
  if (p.gate_skew_sigma_s > 0.0) {
    Rng rng(static_cast<uint64_t>(p.fpn_seed), pixelStream(kGateSkewTag, px));
    pixel.gate_skew_s = p.gate_skew_sigma_s * rng.normal();
  }
  return pixel;
}

SpadPixelMaps spadPixelMaps(const SpadParams& p, int32_t height, int32_t width) {
  const SpadDarkCountMap& measured = p.dark_count_map;
  if (measured.present() && (measured.height != height || measured.width != width)) {
    throw InputError("SPAD dark_count_map " + measured.file + " is " +
                     std::to_string(measured.height) + " x " + std::to_string(measured.width) +
                     " (H x W) but the image is " + std::to_string(height) + " x " +
                     std::to_string(width));
  }
  const auto n = static_cast<std::size_t>(height) * static_cast<std::size_t>(width);
  SpadPixelMaps maps;
  maps.pde.resize(n);
  maps.dcr_per_s.resize(n);
  maps.kind.resize(n);
  maps.gate_skew_s.resize(n);
  for (std::size_t px = 0; px < n; ++px) {
    const SpadPixel pixel = spadPixel(p, px);
    maps.pde[px] = pixel.pde;
    maps.dcr_per_s[px] = pixel.dcr_per_s;
    maps.kind[px] = pixel.kind;
    maps.gate_skew_s[px] = pixel.gate_skew_s;
    maps.hot += pixel.kind == SpadPixelClass::Hot;
    maps.dead += pixel.kind == SpadPixelClass::Dead;
  }
  return maps;
}

}  // namespace tofsim::sensors
