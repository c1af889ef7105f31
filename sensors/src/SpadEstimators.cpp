#include "SpadEstimators.h"

#include <algorithm>
#include <cmath>

#include "KernelCorrelation.h"
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
  double zMax = -std::numeric_limits<double>::infinity();
  for (int32_t i = 0; i < K;) {
    zMax = std::max(zMax, (s.response[i] - background) / sigma);
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
    for (int32_t j = i; j < end; ++j) zMax = std::max(zMax, (s.response[j] - background) / sigma);
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
  // P(max of K background-only z < zMax) = Phi(zMax)^K.
  const double tail = 0.5 * std::erfc(zMax / std::sqrt(2.0));
  e.confidence = tail >= 1.0 ? 0.0 : std::exp(K * std::log1p(-tail));
  return e;
}

}  // namespace tofsim::sensors
