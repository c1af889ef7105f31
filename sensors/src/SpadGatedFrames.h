#pragma once
// Private to the SPAD model: gated 1-bit frames as SPAD512S-class arrays
// deliver them. Each frame integrates M laser pulses into a 1-bit latch that
// is set by at least one detection inside the gate, so with Lambda_k the
// expected detections per pulse inside gate position k (the gate moved by
// k gate_step), a frame fires with P_k = 1 - exp(-M Lambda_k) and the N_f
// frames' sum is Binomial(N_f, P_k), exact (Poisson arrivals, independent
// pulses; the latch does not care about pile-up). The counts clip at
// 2^counter_bits - 1. Outputs spad_gated_counts and their inversion
// spad_gated_flux = -ln(1 - c / N_f) / M, (H, W, positions) each.

#include <cstddef>
#include <memory>
#include <vector>

#include "SpadGate.h"
#include "tofsim/sensors/Random.h"
#include "tofsim/sensors/SensorStream.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors::detail {

/// min(count, 2^bits - 1); bits 0: count.
double clipCount(double count, int32_t bits);

/// Expected detections per pulse inside each gate position of a pixel whose
/// gate is skewed by skew_s, from its ungated flux per cycle.
void gatedFluxes(const SpadParams& p, const SpadGate& gate, const TdcBins& bins,
                 const std::vector<double>& flux, double skew_s, std::vector<double>& lambda);

class SpadGatedFrames {
 public:
  /// Inactive (every call a no-op) when p.gated_frames is 0.
  SpadGatedFrames(const SpadParams& p, const VolumeShape& shape, const StreamOptions& options);
  bool active() const { return positions_ > 0; }
  /// Before a span's pixels: where their values go.
  void beginSpan(std::size_t firstPixel, std::size_t pixelCount);
  /// Pixel px of the span (any thread, each pixel once): its frames from the
  /// ungated flux per cycle and its gate skew.
  void pixel(std::size_t px, const std::vector<double>& flux, double skew_s,
             std::vector<double>& lambda) const;
  /// After the span: streamed arrays get its values.
  void endSpan();
  void finish(std::vector<SensorOutput>& outputs);

 private:
  struct Array {
    SensorOutput out;
    std::unique_ptr<ArrayWriter> writer;
    std::vector<float> chunk;
    float* span = nullptr;
  };
  void open(Array& a, const char* name, const char* unit, const std::string& description,
            const VolumeShape& shape);

  const SpadParams p_;
  const StreamOptions options_;
  const TdcBins bins_;
  const SpadGate gate_;
  const std::size_t positions_;
  std::size_t firstPixel_ = 0;
  Array counts_, flux_;
};

}  // namespace tofsim::sensors::detail
