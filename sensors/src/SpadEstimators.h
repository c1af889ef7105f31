#pragma once
// Private helpers of the SPAD model: the estimators a lidar user expects
// beside the histogram peak (PeakDepth.h): depth by the log-matched filter
// with the instrument's kernel (pulse and jitter, or the measured IRF), the
// first, strongest and last returns with their intensities, and a per-pixel
// detection confidence. They read a per-bin estimate of the detections a
// cycle-by-cycle counter would see without losses, in counts: the counts
// themselves (free-running) or N times Coates' flux (synchronous, so that
// pile-up does not pull the estimates early). Plain functions of the
// histogram: no random numbers, the same doubles on any thread.

#include <cstdint>
#include <limits>
#include <vector>

#include "tofsim/sensors/TimeKernel.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::sensors {

struct SpadReturn {
  double depth_m = std::numeric_limits<double>::quiet_NaN();  ///< NaN: no such return
  double intensity = 0.0;  ///< signal counts of the return (least-squares pulse amplitude)
};

struct SpadEstimates {
  /// Log-matched filter: the arrival maximising sum_i h_i ln(A k_(i - tau) + B)
  /// (Poisson likelihood of a pulse of A counts on a background of B per bin:
  /// B the median bin, A the counts above it),
  /// refined by a parabola; NaN for an empty histogram.
  double matched_depth_m = std::numeric_limits<double>::quiet_NaN();
  SpadReturn first, strongest, last;  ///< among the returns above the threshold
  int32_t returns = 0;                ///< how many
  /// Detection confidence in [0, 1]: P(n' < n)^M, n the counts of the
  /// fullest window of the kernel's length W, n' ~ Poisson(W B) with B the
  /// background per bin outside it, M = K - W + 1 windows. Background alone
  /// gives P(confidence > c) <= 1 - c; a clear return gives ~1.
  double confidence = 0.0;
};

/// The estimators of one SPAD, for its TDC axis and its arrival-to-timestamp
/// kernel. A return is a run of arrival bins whose matched-filter response
/// (the counts correlated with the kernel) exceeds the background by
/// `thresholdSigma` of its background-only noise, sqrt(max(B, 1) sum k^2)
/// (B the median of the bins); runs closer than the kernel's length are one
/// return.
class SpadEstimator {
 public:
  SpadEstimator(const BinKernel& kernel, const TimeAxis& axis, double thresholdSigma);

  struct Scratch {
    std::vector<double> sorted, logLikelihood, response, weights, padded;
  };
  /// `h`: per-bin detections in counts (axis.bins values, >= 0).
  SpadEstimates estimate(const std::vector<double>& h, Scratch& scratch) const;

 private:
  double depthOf_m(int32_t arrivalBin, double offset) const;
  double confidence(const std::vector<double>& h, double total) const;

  BinKernel kernel_;
  TimeAxis axis_;
  double thresholdSigma_;
  double kernelSquares_ = 0.0;  ///< sum k_j^2
};

}  // namespace tofsim::sensors
