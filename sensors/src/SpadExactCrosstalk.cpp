#include "SpadExactCrosstalk.h"

#include "SpadArrayEvents.h"
#include "tofsim/sensors/Random.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

bool crosstalkNeedsEvents(const SpadParams& p) {
  return p.crosstalk_probability > 0.0 &&
         (p.gate_rise_s > 0.0 || p.gate_fall_s > 0.0 || p.gate_skew_sigma_s > 0.0 ||
          (p.crosstalk_delay_s > 0.0 && p.gate_width_s > 0.0));
}

bool exactCrosstalk(const SpadParams& p) {
  return p.crosstalk_probability > 0.0 &&
         (p.engine == SpadEngine::Exact ||
          (p.engine == SpadEngine::Auto && crosstalkNeedsEvents(p)));
}

SpadExactCrosstalk::SpadExactCrosstalk(const SpadParams& p, const DetectorLaws& laws,
                                       const TdcBins& bins, int32_t width, int32_t height)
    : p_(p),
      laws_(laws),
      bins_(bins),
      gate_(spadGate(p)),
      width_(width),
      height_(height),
      flux_(static_cast<std::size_t>(width) * height),
      accept_(flux_.size()),
      h_(flux_.size()) {
  laws_.everyAvalanche = true;
}

void SpadExactCrosstalk::acceptance(std::size_t px, const SpadPixel& pixel) {
  std::vector<double>& g = accept_[px];
  if (pixel.kind == SpadPixelClass::Dead) {
    g.assign(static_cast<std::size_t>(bins_.count()), 0.0);
  } else if (p_.gate_width_s > 0.0) {
    g.assign(static_cast<std::size_t>(bins_.count()), 1.0);
    applyGate(gate_.shifted(pixel.gate_skew_s), bins_, g);
  } else {
    g.clear();  // always armed: every arrival while live avalanches
  }
}

void SpadExactCrosstalk::run(uint64_t seed, uint32_t tag) {
  std::vector<Rng> rngs;
  rngs.reserve(flux_.size());
  for (std::size_t px = 0; px < flux_.size(); ++px) {
    rngs.emplace_back(seed, pixelStream(tag, px));
    h_[px].assign(flux_[px].size(), 0.0);
  }
  CrosstalkLaw crosstalk;
  crosstalk.probability = p_.crosstalk_probability;
  crosstalk.eightNeighbours = p_.crosstalk_neighbours == CrosstalkNeighbours::Eight;
  crosstalk.delayBins = p_.crosstalk_delay_s / bins_.axis.bin_width_s;
  spadArrayEvents(width_, height_, flux_, accept_, static_cast<uint64_t>(p_.cycles), laws_,
                  crosstalk, rngs, h_);
  flux_ = {};  // drawn: only the histograms are read from now on
}

}  // namespace tofsim::sensors::detail
