#pragma once
// Private to the SPAD model: one pixel's histogram over its cycles, drawn
// from its flux per cycle with the pixel's own random stream. The fast draws
// (first-photon multinomial, free-running binomials) where they are exact,
// the exact event engine where an effect correlates bins or cycles
// (multi-stop TDCs, dead time past the cycle's end, afterpulses); then the
// histogram memory's counter bits.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "SpadAfterpulseFlux.h"
#include "SpadDetector.h"
#include "SpadSampling.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::sensors::detail {

/// The SPAD's tag of each pixel's random stream (pixelStream, Random.h).
inline constexpr uint32_t kSpadStreamTag = 0x5350;  // "SP"

class SpadHistogramDraw {
 public:
  SpadHistogramDraw(const SpadParams& p, const TimeAxis& axis);

  /// Whole bins of dead time after an avalanche's bin.
  int32_t deadBins() const { return laws_.deadBins; }
  /// The event engine's laws of this detector.
  const DetectorLaws& laws() const { return laws_; }

  /// Reused buffers (one per thread).
  struct Scratch {
    FirstOrderAfterpulses fast;
    std::vector<double> m;
    FirstPhotonScratch firstPhoton;
  };
  /// `h` gets pixel px's counts per TDC bin (flux.size() of them) under
  /// `seed`: the same flux, pixel and seed give the same counts on any thread.
  void draw(std::size_t px, uint64_t seed, const std::vector<double>& flux, Scratch& s,
            std::vector<double>& h) const;
  /// The histogram memory's counter bits on counts drawn elsewhere (the
  /// exact crosstalk driver), as draw() applies them.
  void saturate(std::vector<double>& h) const;

 private:
  bool firstOrderAfterpulses() const;
  bool needsEngine(const std::vector<double>& flux) const;

  const SpadMode mode_;
  const SpadEngine engine_;
  const int64_t stops_;
  const uint64_t cycles_;
  const int32_t counterBits_;
  const DetectorLaws laws_;
};

}  // namespace tofsim::sensors::detail
