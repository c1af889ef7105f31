#pragma once
// Private to the SPAD model: the stream's side of exact crosstalk
// (SpadArrayEvents.h). SpadStream hands it every pixel's gated flux as the
// spans come in; once the last pixel is in, run() draws the whole array with
// the array driver on the pixels' own streams, and the stream reads each
// pixel's histogram back for its estimators and outputs.
// Where it is used (exactCrosstalk): `engine: exact`, and `engine: auto`
// where the first-order path (SpadCrosstalk.h) cannot follow the gate: ramps,
// per-pixel skew, or a delayed arrival into a gate.

#include <cstdint>
#include <vector>

#include "SpadDetector.h"
#include "SpadGate.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/sensors/SpadPixelMaps.h"

namespace tofsim::sensors::detail {

/// Crosstalk with a gate the first-order path does not follow.
bool crosstalkNeedsEvents(const SpadParams& p);
/// Crosstalk drawn by the exact array driver.
bool exactCrosstalk(const SpadParams& p);

class SpadExactCrosstalk {
 public:
  /// `laws`: the model's detector (everyAvalanche is set here: a detector
  /// keeps running after its last stop, and those avalanches send crosstalk).
  SpadExactCrosstalk(const SpadParams& p, const DetectorLaws& laws, const TdcBins& bins,
                     int32_t width, int32_t height);

  /// The slot for pixel px's own (gated) flux.
  std::vector<double>& flux(std::size_t px) { return flux_[px]; }
  /// px's acceptance of crosstalk arrivals: its gate moved by its skew (a
  /// disarmed detector takes none), none at all for a dead pixel.
  void acceptance(std::size_t px, const SpadPixel& pixel);
  /// Draws the whole array, pixel px on Rng(seed, pixelStream(tag, px)).
  void run(uint64_t seed, uint32_t tag);
  const std::vector<double>& histogram(std::size_t px) const { return h_[px]; }

 private:
  const SpadParams& p_;
  DetectorLaws laws_;
  const TdcBins& bins_;
  const SpadGate gate_;
  const int32_t width_, height_;
  std::vector<std::vector<double>> flux_, accept_, h_;
};

}  // namespace tofsim::sensors::detail
