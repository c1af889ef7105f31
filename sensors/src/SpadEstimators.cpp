#include "SpadEstimators.h"

#include <algorithm>
#include <cmath>

#include "KernelCorrelation.h"
#include "PoissonTail.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {

// Offset of the vertex of the parabola through (-1, a), (0, b), (1, c), in
// [-1/2, 1/2]; 0 where b is not a strict local maximum of a concave fit.
double parabolaOffset(double a, double b, double c) {
  const double denom = a - 2.0 * b + c;
  return denom < 0.0 ? std::clamp(0.5 * (a - c) / denom, -0.5, 0.5) : 0.0;
}

double median(const std::vector<double>& h, std::vector<double>& sorted) {
  sorted.assign(h.begin(), h.end());
  const std::size_t mid = sorted.size() / 2;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(mid), sorted.end());
  return sorted[mid];
}

}  // namespace

SpadEstimator::SpadEstimator(const BinKernel& kernel, const TimeAxis& axis, double thresholdSigma)
    : kernel_(kernel), axis_(axis), thresholdSigma_(thresholdSigma) {
  TOFSIM_CHECK(!kernel_.weights.empty() && axis_.bins > 0 && thresholdSigma_ > 0.0);
  for (double k : kernel_.weights) kernelSquares_ += k * k;
}

double SpadEstimator::depthOf_m(int32_t arrivalBin, double offset) const {
  // An arrival in bin tau is spread over that bin (the resampled energy).
  return axis_.depthOf_m(axis_.start_s + (arrivalBin + 0.5 + offset) * axis_.bin_width_s);
}

double SpadEstimator::confidence(const std::vector<double>& h, double total) const {
  // A scan test: the counts n of the pixel's fullest window of W bins (the
  // kernel's length, where a return's counts fall) against Poisson(W B), B
  // the background per bin estimated from the bins outside that window (so
  // that the return itself does not lift it; the median is 0 at the low
  // rates of dark counts and ambient light, which made every dark count look
  // like a return). One more count than seen outside keeps B above 0 where
  // none was (a single dark count is then no return). The W-bin windows
  // start at M = K - W + 1 places: confidence = P(n' < n)^M, the probability
  // that background alone gives each window fewer counts (independent
  // windows: it lies below the exact law of the maximum, so that background
  // alone gives P(confidence > c) <= 1 - c, a median <= 1/2).
  const int32_t K = axis_.bins;
  const int32_t W = std::min(static_cast<int32_t>(kernel_.weights.size()), K);
  double window = 0.0;
  for (int32_t i = 0; i < W; ++i) window += h[i];
  double fullest = window;
  int32_t fullestAt = 0;
  for (int32_t i = W; i < K; ++i) {
    window += h[i] - h[i - W];
    if (window > fullest) {
      fullest = window;
      fullestAt = i - W + 1;
    }
  }
  const double outside = std::max(total - fullest, 0.0);
  const double background = (outside + 1.0) / std::max(K - W, 1);
  // Quasi-Poisson: N x Coates' flux is over-dispersed (a late bin's estimate
  // has variance mean / P(reaching it)), and afterpulses and crosstalk come
  // in bunches; the bins outside the window give the dispersion D =
  // variance / mean (>= 1), and counts and mean are divided by it.
  double squares = 0.0;
  int32_t outsideBins = 0;
  for (int32_t i = 0; i < K; ++i) {
    if (i >= fullestAt && i < fullestAt + W) continue;
    squares += (h[i] - background) * (h[i] - background);
    ++outsideBins;
  }
  const double dispersion =
      outsideBins > 1 ? std::max(1.0, squares / (outsideBins - 1) / background) : 1.0;
  const detail::PoissonTail tail =
      detail::poissonTail(fullest / dispersion, W * background / dispersion);
  return std::exp(static_cast<double>(K - W + 1) * tail.logNotTail);
}

SpadEstimates SpadEstimator::estimate(const std::vector<double>& h, Scratch& s) const {
  const int32_t K = axis_.bins;
  TOFSIM_CHECK(static_cast<int32_t>(h.size()) == K);
  SpadEstimates e;
  double total = 0.0;
  for (double v : h) total += v;
  if (!(total > 0.0)) return e;
  const double background = median(h, s.sorted);
  // The signal: the counts above the background (a long tail can lift the
  // median so far that total - K B is no longer positive).
  double signal = 0.0;
  for (double v : h) signal += std::max(0.0, v - background);
  const std::vector<double>& k = kernel_.weights;
  const auto L = static_cast<int32_t>(k.size());
  const int32_t first = kernel_.first;

  // Log-matched filter: sum_i h_i [ln(A k_(i-tau) + B) - ln B], the terms of
  // the Poisson log-likelihood that depend on the arrival tau. A floor on B
  // keeps the weights finite without background (then it is ln k alone).
  const double floorB = std::max(background, 1e-9 * signal + 1e-300);
  s.weights.resize(k.size());
  for (int32_t j = 0; j < L; ++j) s.weights[j] = std::log1p(signal * k[j] / floorB);
  detail::correlateWithTwo(h, first, s.weights, k, s.logLikelihood, s.response, s.padded);
  const auto at = [K](const std::vector<double>& v, int32_t i) {
    return v[std::clamp(i, 0, K - 1)];
  };
  const auto peakOf = [&](const std::vector<double>& v, int32_t b, int32_t end) {
    int32_t best = b;
    for (int32_t i = b + 1; i < end; ++i) {
      if (v[i] > v[best]) best = i;
    }
    return best;
  };
  const int32_t best = peakOf(s.logLikelihood, 0, K);
  e.matched_depth_m =
      depthOf_m(best, parabolaOffset(at(s.logLikelihood, best - 1), s.logLikelihood[best],
                                     at(s.logLikelihood, best + 1)));

  // Returns: runs of arrival bins whose response is thresholdSigma noise
  // sigmas above the background's B sum k = B.
  const double sigma = std::sqrt(std::max(background, 1.0) * kernelSquares_);
  const double threshold = background + thresholdSigma_ * sigma;
  for (int32_t i = 0; i < K;) {
    if (s.response[i] < threshold) {
      ++i;
      continue;
    }
    // A run ends where the response stays below the threshold for the
    // kernel's length: noise at a return's flanks does not split it.
    int32_t end = i + 1;
    for (int32_t j = end; j < K && j < end + L; ++j) {
      if (s.response[j] >= threshold) end = j + 1;
    }
    const int32_t peak = peakOf(s.response, i, end);
    SpadReturn r;
    r.depth_m = depthOf_m(
        peak, parabolaOffset(at(s.response, peak - 1), s.response[peak], at(s.response, peak + 1)));
    r.intensity = (s.response[peak] - background) / kernelSquares_;
    if (e.returns == 0) e.first = r;
    if (e.returns == 0 || r.intensity > e.strongest.intensity) e.strongest = r;
    e.last = r;
    ++e.returns;
    i = end;
  }
  e.confidence = confidence(h, total);
  return e;
}

}  // namespace tofsim::sensors
