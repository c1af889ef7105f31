#pragma once
// Private to the SPAD model: crosstalk on the streamed fast path, to first
// order in the crosstalk probability p (sensors/README.md, "SPAD",
// "Crosstalk"; exact, with chains, in the event engine: SpadArrayEvents.h).
// Two passes over the pixels as they stream in:
//  1. send: from a pixel's own flux, its expected avalanches per cycle and
//     TDC bin m_i (synchronous: the first-photon probabilities P_i, the pixel
//     being dead for the rest of the cycle after its stop; free-running: the
//     steady state), delayed by the crosstalk delay into the profile
//     r = m (*) kappa its neighbours receive (prompt: r = m);
//  2. receive: before a pixel's own draw, the flux of its neighbours'
//     arrivals, a_i = p r_i from each, is added to its flux. Synchronous: a
//     neighbour avalanches at most once per cycle and so sends at most one
//     arrival; the flux whose first-photon law puts that arrival in bin i with
//     probability a_i exactly is the hazard -ln(1 - a_i / (1 - sum_{l<i} a_l)),
//     and independent neighbours' fluxes add. Free-running: -ln(1 - a_i) per
//     bin (at most one avalanche per bin, the bins independent as in the
//     free-running draw).
// Left out (O(p^2)): avalanches that crosstalk itself causes in the
// neighbours, and the chains they start. Expectations only cross pixels, so
// every pixel keeps its own random stream and the bytes do not depend on how
// the image is cut into spans or threads.
// A pixel can be received once its last neighbour, the pixel W + 1 after it,
// has been sent: the ring holds batch + 2 W + 3 pixels' fluxes and profiles
// (O(W K) memory, W the image width, K the bins).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "tofsim/sensors/Spad.h"
#include "tofsim/sensors/TimeKernel.h"

namespace tofsim::sensors::detail {

/// The shifts (s) of the delayed crosstalk's kernel, for the check of its width.
KernelSupport crosstalkDelaySupport(double delay_s);

class SpadCrosstalk {
 public:
  SpadCrosstalk(const SpadParams& p, int32_t bins, double binWidth_s, int32_t deadBins,
                int32_t width, int32_t height, std::size_t batch);

  /// Pixels sent at a time (pass 1's batch): the ring holds them besides the
  /// look-ahead.
  std::size_t batch() const { return batch_; }
  /// The slot for pixel px's own flux; fill it, then send(px).
  std::vector<double>& flux(std::size_t px) { return flux_[px % flux_.size()]; }
  const std::vector<double>& flux(std::size_t px) const { return flux_[px % flux_.size()]; }
  /// Pass 1: px's profile from its flux.
  void send(std::size_t px);
  /// Pass 2: `out` = px's own flux plus the crosstalk flux of its neighbours
  /// (each sent before).
  void receive(std::size_t px, std::vector<double>& out) const;
  /// The pixels before this one can be received once `sent` pixels have been.
  std::size_t receivable(std::size_t sent) const;

 private:
  const bool synchronous_;
  const double probability_;
  const int32_t bins_, deadBins_, width_, height_;
  const bool delayed_;
  const BinKernel delay_;  ///< the crosstalk delay in bins
  const std::size_t batch_;
  std::vector<std::array<int32_t, 2>> offsets_;   ///< (dy, dx) of the neighbours
  std::vector<std::vector<double>> flux_, sent_;  ///< ring slots: px % size
};

}  // namespace tofsim::sensors::detail
