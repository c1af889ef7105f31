#pragma once
// Private to the SPAD model: the FLIM user's per-pixel lifetime. A
// mono-exponential decay that starts at an onset s (the light's arrival on
// the TDC axis), reconvolved with the instrument's kernel (pulse and jitter,
// or the measured IRF: the same BinKernel the histogram was made with), on a
// constant background, fitted by maximum likelihood on Poisson counts:
//   mu_n = A (k * e(tau, s))_n + B,   max sum_n h_n ln mu_n - mu_n,
// e(tau, s) the exact bin integrals of (1/tau) exp(-(t - s)/tau), t >= s,
// cut at the TDC's last bin as the simulator cuts the light there (no
// wrap-around into the next laser period). Fisher scoring with Levenberg
// damping on (ln A, ln B, ln tau, s); the convolution is a recursion (the
// decay is geometric past its first bin), O(bins + kernel) per evaluation.
// The lifetime's uncertainty is the Cramer-Rao bound from the Fisher
// information at the optimum. Plain functions of the histogram: no random
// numbers, the same doubles on any thread. Model: sensors/README.md, "FLIM:
// lifetime and phasor".

#include <cstdint>
#include <limits>
#include <vector>

#include "tofsim/sensors/TimeKernel.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::sensors::detail {

struct FlimFit {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double lifetime_s = kNaN;        ///< tau; NaN: no fit
  double lifetime_sigma_s = kNaN;  ///< its standard deviation (Cramer-Rao)
  double onset_s = kNaN;           ///< s, the decay's start on the TDC axis (absolute time)
  double amplitude = 0.0;          ///< A, counts of the whole (uncut) decay
  double background = 0.0;         ///< B, counts per bin
  int32_t iterations = 0;
  bool converged = false;
};

class FlimFitter {
 public:
  /// `kernel`: arrival-to-timestamp shifts in bins of `axis` (an identity
  /// kernel fits without reconvolution).
  FlimFitter(const BinKernel& kernel, const TimeAxis& axis);

  struct Scratch {
    std::vector<double> z, zUp, zDown, mu;
    std::size_t end = 0;  ///< bins fitted
  };
  /// The fit to `h` (axis.bins counts >= 0); not converged (NaN) for an
  /// empty histogram or one the model cannot follow.
  /// Only bins before `endBin` enter the likelihood (the start still reads all).
  FlimFit fit(const std::vector<double>& h, Scratch& scratch,
              int32_t endBin = std::numeric_limits<int32_t>::max()) const;

  /// Expected counts per bin, mu_n above (for tests and the bench).
  void expected(double amplitude, double background, double lifetime_s, double onset_s,
                std::vector<double>& mu) const;

  const TimeAxis& axis() const { return axis_; }
  const BinKernel& kernel() const { return kernel_; }

 private:
  struct Point;        // a parameter vector and its likelihood
  struct Information;  // the Fisher information and score at a point
  /// z = k * e(tau, s), tau and s in bins.
  void decay(double tauBins, double onsetBins, std::vector<double>& z) const;
  double logLikelihood(const std::vector<double>& h, const Point& p, Scratch& s) const;
  void information(const std::vector<double>& h, const Point& q, Scratch& s,
                   Information& out) const;
  Point start(const std::vector<double>& h, Scratch& s) const;

  BinKernel kernel_;
  TimeAxis axis_;
  double kernelMean_ = 0.0;    ///< mean shift, bins
  int32_t kernelHalfRise_ = 0;  ///< shift of the first weight at half the largest, bins
};

}  // namespace tofsim::sensors::detail
