#include "SpadHistogramDraw.h"

#include <cmath>

#include "SpadAfterpulseFlux.h"
#include "SpadEventEngine.h"
#include "SpadGatedFrames.h"
#include "tofsim/sensors/Random.h"

namespace tofsim::sensors::detail {

namespace {
// The event engine's laws of the model's detector (free-running: every
// detection recorded).
DetectorLaws detectorLaws(const SpadParams& p, const TimeAxis& axis) {
  DetectorLaws laws;
  laws.deadBins = static_cast<int32_t>(std::lround(p.dead_time_s / axis.bin_width_s));
  laws.stops = p.mode == SpadMode::Synchronous ? p.tdc_stops : 0;
  AfterpulseLaw& ap = laws.afterpulses;
  ap.count = p.afterpulse_count == SpadAfterpulseCount::Poisson ? AfterpulseLaw::Count::Poisson
                                                                : AfterpulseLaw::Count::Bernoulli;
  ap.mean = p.afterpulse_probability;
  ap.delays_bins.clear();
  for (double d : p.afterpulse_delays_s) ap.delays_bins.push_back(d / axis.bin_width_s);
  ap.weights = p.afterpulse_weights;
  if (ap.weights.empty()) ap.weights.assign(ap.delays_bins.size(), 1.0);
  ap.reset = p.afterpulse_traps == SpadAfterpulseTraps::Reset;
  if (p.afterpulse_delay_table.present()) {
    setAfterpulseTable(ap, p.afterpulse_delay_table, axis.bin_width_s);
  }
  return laws;
}
}  // namespace

SpadHistogramDraw::SpadHistogramDraw(const SpadParams& p, const TimeAxis& axis)
    : mode_(p.mode),
      engine_(p.engine),
      stops_(p.tdc_stops),
      cycles_(static_cast<uint64_t>(p.cycles)),
      counterBits_(p.counter_bits),
      laws_(detectorLaws(p, axis)) {}

// Where the fast draws are not exact: the first-photon law needs one stop,
// no afterpulse and a detector live again at the next pulse; the
// free-running binomials (exact marginals) no afterpulse. `flux` is the
// one the fast draws would use (with `engine: fast`, afterpulses in it).
// `engine: fast` takes afterpulses to first order when free-running only:
// a synchronous avalanche's releases follow the stop it made, and extra flux
// on the first-photon law cannot know that (SpadFastAfterpulseTest).
bool SpadHistogramDraw::firstOrderAfterpulses() const {
  return engine_ == SpadEngine::Fast && mode_ == SpadMode::FreeRunning;
}

bool SpadHistogramDraw::needsEngine(const std::vector<double>& flux) const {
  if (engine_ == SpadEngine::Exact) return true;
  if (laws_.afterpulses.on() && !firstOrderAfterpulses()) return true;
  return mode_ == SpadMode::Synchronous &&
         (stops_ != 1 || !deadTimeEndsInItsCycle(flux, laws_.deadBins));
}

void SpadHistogramDraw::draw(std::size_t px, uint64_t seed, const std::vector<double>& flux,
                             Scratch& s, std::vector<double>& h) const {
  const auto K = static_cast<int32_t>(flux.size());
  Rng rng(seed, pixelStream(kSpadStreamTag, px));
  const bool firstOrder = firstOrderAfterpulses() && laws_.afterpulses.on();
  const std::vector<double>& fast =
      firstOrder
          ? detail::firstOrderAfterpulses(flux, laws_.deadBins, laws_.afterpulses, s.fast).flux
          : flux;
  if (needsEngine(fast)) {
    // Multi-stop TDCs, dead time past the cycle's end and afterpulses
    // correlate bins and cycles: the exact event engine draws the pixel.
    h.assign(static_cast<std::size_t>(K), 0.0);
    spadEvents(flux, cycles_, laws_, rng, h);
  } else if (mode_ == SpadMode::Synchronous) {
    firstPhotonHistogram(fast, cycles_, rng, s.firstPhoton, h);
  } else {
    const std::vector<double>& m =  // the fixed point gives flux' with its steady state
        firstOrder ? s.fast.detections : (s.m = freeRunningProbabilities(fast, laws_.deadBins));
    h.resize(static_cast<std::size_t>(K));
    for (int32_t i = 0; i < K; ++i) h[i] = static_cast<double>(rng.binomial(cycles_, m[i]));
  }
  saturate(h);
}

void SpadHistogramDraw::saturate(std::vector<double>& h) const {
  if (counterBits_ > 0) {  // the histogram memory saturates
    for (double& c : h) c = clipCount(c, counterBits_);
  }
}

}  // namespace tofsim::sensors::detail
