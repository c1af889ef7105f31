#pragma once
// The temporal-response stage (core/physics/temporal_response.md): a
// contribution's own delay kernel (an exponential lifetime, a Gaussian delay,
// a tabulated kernel; a share `fraction` delayed, the rest prompt) reaches the
// histogram as exact bin integrals, through one per-pixel pass per response
// class at the integrate step of both backends. This header holds the
// kernel's description (ResponseKernel, in seconds: what issue 41 fills from
// the materials), its filter in bins of the axis (ResponseTaps, computed once
// per class here, for both backends), and the CPU's pass (applyResponse),
// whose per-bin arithmetic is shaders/temporal_response.glsl, shared with the
// GL pass response_integrate.comp.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tofsim::physics {

using glm::dmat3;
using glm::dvec3;

#define TOFSIM_PHYSICS_FN inline
#include "temporal_response.glsl"
#undef TOFSIM_PHYSICS_FN

enum class ResponseModel {
  Exponential,  ///< (1 / lifetime) exp(-t / lifetime), t >= 0
  Gaussian,     ///< N(mean, sigma^2) truncated to t >= 0 and renormalised
  Table,        ///< piecewise linear through (delay, weight) points, normalised
};

/// A response class's kernel: (1 - fraction) delta(t) + fraction k(t).
struct ResponseKernel {
  ResponseModel model = ResponseModel::Exponential;
  double fraction = 1.0;     ///< share of the light delayed, in [0, 1]
  double lifetime_s = 0.0;   ///< Exponential: > 0
  double mean_s = 0.0;       ///< Gaussian: >= 0
  double sigma_s = 0.0;      ///< Gaussian: > 0
  std::vector<double> tableDelay_s;  ///< Table: >= 2 points, ascending, the first >= 0
  std::vector<double> tableWeight;   ///< Table: >= 0 at each point, a positive area
  /// Re-emission (fluorescence's Stokes shift): the delayed share's light
  /// absorbed in channel j comes back as column j (out = reemission * in),
  /// each column summing to at most 1. Identity: no change of channel.
  glm::dmat3 reemission{1.0};

  bool operator==(const ResponseKernel&) const = default;
};

/// Most FIR taps a class may have (its cost is taps x bins per pixel): a
/// Gaussian's 16 sigma or a table's extent, in bins.
inline constexpr std::size_t kMaxResponseTaps = 8192;

/// A class's filter in bins of the axis (temporal_response.glsl):
/// y[n] = prompt x[n] + sum_j taps[j] x[n - delay - j] + tail[n],
/// tail[n] = tailRatio tail[n - 1] + tailWeight x[n - delay - taps.size()].
struct ResponseTaps {
  double prompt = 1.0;
  int32_t delay = 0;
  std::vector<double> taps;
  double tailRatio = 0.0;
  double tailWeight = 0.0;
  /// The kernel's re-emission, applied to the delayed share (the FIR and the
  /// tail): y[n] = prompt x[n] + reemission (fir + tail). Identity: none, and
  /// the stage skips the product (the bytes of a kernel without it).
  glm::dmat3 reemission{1.0};

  bool reemits() const { return reemission != glm::dmat3(1.0); }
};

namespace detail {

// Mass of N(mu, sigma^2) on [a, b], without cancellation in either tail.
inline double gaussianMass(double a, double b, double mu, double sigma) {
  const double s = sigma * std::sqrt(2.0);
  const double za = (a - mu) / s, zb = (b - mu) / s;
  if (za >= 0.0) return 0.5 * (std::erfc(za) - std::erfc(zb));
  if (zb <= 0.0) return 0.5 * (std::erfc(-zb) - std::erfc(-za));
  return 0.5 * (std::erf(zb) - std::erf(za));
}

inline double gaussianDensity(double u, double mu, double sigma) {
  const double z = (u - mu) / sigma;
  return std::exp(-0.5 * z * z) / (sigma * std::sqrt(2.0 * M_PI));
}

// The integral of (u - c) N(u; mu, sigma^2) over [a, b] (a <= b).
inline double gaussianRamp(double a, double b, double c, double mu, double sigma) {
  if (b <= a) return 0.0;
  return (mu - c) * gaussianMass(a, b, mu, sigma) -
         sigma * sigma * (gaussianDensity(b, mu, sigma) - gaussianDensity(a, mu, sigma));
}

inline void requireTaps(std::size_t count) {
  if (count > kMaxResponseTaps) {
    throw std::invalid_argument("a response kernel spans " + std::to_string(count) +
                                " bins, over the " + std::to_string(kMaxResponseTaps) +
                                " the stage allows");
  }
}

// Before a kernel's last bin is cast to an integer (a huge one would
// overflow the cast): its reach from zero delay, in bins.
inline void requireReach(double bins) {
  if (!(bins < static_cast<double>(kMaxResponseTaps))) {
    throw std::invalid_argument("a response kernel reaches " + std::to_string(bins) +
                                " bins past zero delay, over the " +
                                std::to_string(kMaxResponseTaps) + " the stage allows");
  }
}

// Exponential of lifetime tau (bins): bin-integral coefficients of the
// exponential convolved with a bin's box. Tap 0 = int_0^1 (1 - u) k(u) du
// = 1 - tau (1 - a); tap m >= 1 = tau (1 - a)^2 a^(m - 1), a = exp(-1/tau):
// tap 1 and the tail's ratio a. They sum to 1.
inline ResponseTaps exponentialTaps(double tau, double fraction) {
  const double oneMinusA = -std::expm1(-1.0 / tau);
  ResponseTaps r;
  r.prompt = 1.0 - fraction;
  r.taps = {fraction * (1.0 - tau * oneMinusA)};
  r.tailRatio = std::exp(-1.0 / tau);
  r.tailWeight = fraction * tau * oneMinusA * oneMinusA;
  return r;
}

// Tap j = int k(u) hat(u - j) du, hat the triangle on [-1, 1] (the bin box
// convolved with the bin box), k = N(mu, sigma^2) on [lo, hi] = [max(0, mu -
// 8 sigma), mu + 8 sigma], renormalised to 1 there.
inline ResponseTaps gaussianTaps(double mu, double sigma, double fraction) {
  const double lo = std::max(0.0, mu - 8.0 * sigma), hi = mu + 8.0 * sigma;
  const auto first = static_cast<int64_t>(std::floor(lo));
  const auto last = static_cast<int64_t>(std::floor(hi)) + 1;
  requireTaps(static_cast<std::size_t>(last - first + 1));
  const double mass = gaussianMass(lo, hi, mu, sigma);
  ResponseTaps r;
  r.prompt = 1.0 - fraction;
  r.delay = static_cast<int32_t>(first);
  for (int64_t j = first; j <= last; ++j) {
    const auto c = static_cast<double>(j);
    const double rising = gaussianRamp(std::max(lo, c - 1.0), std::min(hi, c), c - 1.0, mu, sigma);
    const double falling = -gaussianRamp(std::max(lo, c), std::min(hi, c + 1.0), c + 1.0, mu, sigma);
    r.taps.push_back(fraction * (rising + falling) / mass);
  }
  return r;
}

// A table's taps: on each piece between its points and the bin edges the
// density is linear and the hat too, so Simpson's rule is exact.
inline ResponseTaps tableTaps(const std::vector<double>& u, const std::vector<double>& w,
                              double fraction) {
  const auto first = static_cast<int64_t>(std::floor(u.front()));
  const auto last = static_cast<int64_t>(std::floor(u.back())) + 1;
  requireTaps(static_cast<std::size_t>(last - first + 1));
  std::vector<double> taps(static_cast<std::size_t>(last - first + 1), 0.0);
  double area = 0.0;
  for (std::size_t i = 0; i + 1 < u.size(); ++i) {
    const double u0 = u[i], u1 = u[i + 1];
    if (u1 <= u0) continue;
    area += 0.5 * (u1 - u0) * (w[i] + w[i + 1]);
    const auto density = [&](double x) { return w[i] + (w[i + 1] - w[i]) * (x - u0) / (u1 - u0); };
    for (double p = u0; p < u1;) {
      const double k = std::floor(p);
      const double q = std::min(u1, k + 1.0);
      const double m = 0.5 * (p + q);
      const auto simpson = [&](auto f) { return (q - p) / 6.0 * (f(p) + 4.0 * f(m) + f(q)); };
      const auto j = static_cast<std::size_t>(static_cast<int64_t>(k) - first);
      taps[j] += simpson([&](double x) { return (k + 1.0 - x) * density(x); });
      taps[j + 1] += simpson([&](double x) { return (x - k) * density(x); });
      p = q;
    }
  }
  if (!(area > 0.0)) throw std::invalid_argument("a response table has no area");
  ResponseTaps r;
  r.prompt = 1.0 - fraction;
  r.delay = static_cast<int32_t>(first);
  for (double& t : taps) t = fraction * t / area;
  r.taps = std::move(taps);
  return r;
}


// The filter of the kernel's model (responseTaps without the re-emission).
inline ResponseTaps modelTaps(const ResponseKernel& kernel, double binWidth_s) {
  if (!(binWidth_s > 0.0) || !(kernel.fraction >= 0.0 && kernel.fraction <= 1.0)) {
    throw std::invalid_argument("a response needs a bin width > 0 and a fraction in [0, 1]");
  }
  switch (kernel.model) {
    case ResponseModel::Exponential:
      if (!(kernel.lifetime_s > 0.0) || !std::isfinite(kernel.lifetime_s)) {
        throw std::invalid_argument("an exponential response needs a lifetime > 0");
      }
      return detail::exponentialTaps(kernel.lifetime_s / binWidth_s, kernel.fraction);
    case ResponseModel::Gaussian:
      if (!(kernel.mean_s >= 0.0 && kernel.sigma_s > 0.0) || !std::isfinite(kernel.mean_s + kernel.sigma_s)) {
        throw std::invalid_argument("a Gaussian response needs a mean >= 0 and a sigma > 0");
      }
      detail::requireReach((kernel.mean_s + 8.0 * kernel.sigma_s) / binWidth_s);
      return detail::gaussianTaps(kernel.mean_s / binWidth_s, kernel.sigma_s / binWidth_s,
                                  kernel.fraction);
    case ResponseModel::Table: {
      const std::vector<double>& t = kernel.tableDelay_s;
      bool valid = t.size() >= 2 && t.size() == kernel.tableWeight.size() && t.front() >= 0.0 &&
                   std::isfinite(t.back());
      for (std::size_t i = 0; valid && i < t.size(); ++i) {
        valid = kernel.tableWeight[i] >= 0.0 && std::isfinite(kernel.tableWeight[i]) &&
                (i == 0 || t[i] >= t[i - 1]);
      }
      if (!valid) {
        throw std::invalid_argument(
            "a response table needs >= 2 ascending delays >= 0 with weights >= 0");
      }
      detail::requireReach(t.back() / binWidth_s);
      std::vector<double> u(t.size());
      for (std::size_t i = 0; i < t.size(); ++i) u[i] = t[i] / binWidth_s;
      return detail::tableTaps(u, kernel.tableWeight, kernel.fraction);
    }
  }
  throw std::invalid_argument("unknown response model");
}

}  // namespace detail

/// The filter of `kernel` on an axis of bins `binWidth_s` wide. Throws
/// std::invalid_argument for a kernel outside its ranges (the config reports
/// them with their location first), one over kMaxResponseTaps bins, or a
/// re-emission matrix with an entry outside [0, 1] (the config checks that
/// its columns sum to at most 1).
inline ResponseTaps responseTaps(const ResponseKernel& kernel, double binWidth_s) {
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      if (!(kernel.reemission[j][i] >= 0.0 && kernel.reemission[j][i] <= 1.0)) {
        throw std::invalid_argument("a re-emission matrix needs entries in [0, 1]");
      }
    }
  }
  ResponseTaps r = detail::modelTaps(kernel, binWidth_s);
  r.reemission = kernel.reemission;
  return r;
}

namespace detail {

// One stage of a class's cascade over bins [first, bins) of one pixel, in
// the order of response_integrate.comp. `in` (bins x 3 doubles, zero before
// `first`) is the stage's input: with kDifference the class's difference
// buffer, summed twice into its bin integrals x (left in `in`, read by the
// later bins' taps), else the previous stage's output. y goes to `out`
// (doubles) or, with kLast, is added to `histogram` (floats). sumIn adds up
// x (first stage), sumOut y (last stage).
template <bool kDifference, bool kLast>
void responseStage(double* in, int32_t bins, int32_t first, const ResponseTaps& r, double* out,
                   float* histogram, dvec3& sumIn, dvec3& sumOut) {
  const auto at = [](double* d, int32_t k) { return d + static_cast<std::size_t>(k) * 3; };
  const auto load = [&](int32_t k) { const double* e = at(in, k); return dvec3(e[0], e[1], e[2]); };
  const auto taps = static_cast<int32_t>(r.taps.size());
  const bool reemits = r.reemits();
  dvec3 slope(0.0), value(0.0), tail(0.0);
  for (int32_t n = first; n < bins; ++n) {
    double* e = at(in, n);
    if constexpr (kDifference) {
      slope += dvec3(e[0], e[1], e[2]);
      value += slope;
      e[0] = value.x, e[1] = value.y, e[2] = value.z;  // x[n], read by the later bins' taps
    } else {
      value = dvec3(e[0], e[1], e[2]);
    }
    dvec3 fir(0.0);
    for (int32_t j = 0; j < taps; ++j) {
      const int32_t m = n - r.delay - j;
      if (m < first) break;
      fir = responseFirTerm(fir, r.taps[static_cast<std::size_t>(j)], load(m));
    }
    const int32_t entering = n - r.delay - taps;
    tail = responseTail(r.tailRatio, r.tailWeight, tail,
                        entering >= first ? load(entering) : dvec3(0.0));
    const dvec3 y = reemits ? responseReemittedOutput(r.prompt, value, fir, tail, r.reemission)
                            : responseOutput(r.prompt, value, fir, tail);
    if constexpr (kLast) {
      float* h = histogram + static_cast<std::size_t>(n) * 3;
      h[0] += static_cast<float>(y.x);
      h[1] += static_cast<float>(y.y);
      h[2] += static_cast<float>(y.z);
    } else {
      double* o = at(out, n);
      o[0] = y.x, o[1] = y.y, o[2] = y.z;
    }
    if constexpr (kDifference) sumIn += value;
    if constexpr (kLast) sumOut += y;
  }
}

}  // namespace detail

/// The stage for one pixel and one delayed class, the cascade of `stages`
/// (its members' filters, in order). `diff` is the class's difference buffer
/// (bins x 3 doubles, footprint_kernel.md's layout, zero before bin `first`):
/// it is summed twice into the class's bin integrals x, stage 1 filters x,
/// each next stage the previous one's output (double: ping-pong between
/// `diff` and `scratch`, bins x 3 doubles, needed with two stages or more),
/// and the last stage's output y is added to `histogram` (bins x 3 floats).
/// `diff` is left dirty from `first` on (the caller zeroes it). Returns the
/// light the kernels carry past the last bin, summed over channels: sum x -
/// sum y, where a stage that re-emits first takes sum x through its matrix
/// (responseExpected: the light it absorbs without re-emitting is not past
/// the axis). The GL pass response_integrate.comp runs the same operations
/// in the same order from bin 0 (the terms before `first` add exact zeros).
inline double applyResponse(double* diff, double* scratch, int32_t bins, int32_t first,
                            const ResponseTaps* stages, std::size_t count, float* histogram) {
  dvec3 sumIn(0.0), sumOut(0.0);
  const std::size_t last = count - 1;
  double* buffers[2] = {scratch, diff};  // stage k >= 1 reads buffers[(k + 1) % 2]
  for (std::size_t k = 0; k < count; ++k) {
    double* out = buffers[k % 2];
    if (k == 0 && k == last) {
      detail::responseStage<true, true>(diff, bins, first, stages[k], nullptr, histogram, sumIn,
                                        sumOut);
    } else if (k == 0) {
      detail::responseStage<true, false>(diff, bins, first, stages[k], out, nullptr, sumIn, sumOut);
    } else if (k == last) {
      detail::responseStage<false, true>(buffers[(k + 1) % 2], bins, first, stages[k], nullptr,
                                         histogram, sumIn, sumOut);
    } else {
      detail::responseStage<false, false>(buffers[(k + 1) % 2], bins, first, stages[k], out,
                                          nullptr, sumIn, sumOut);
    }
    if (stages[k].reemits()) {
      sumIn = responseExpected(stages[k].prompt, stages[k].reemission, sumIn);
    }
  }
  return (sumIn.x - sumOut.x) + (sumIn.y - sumOut.y) + (sumIn.z - sumOut.z);
}

inline double applyResponse(double* diff, double* scratch, int32_t bins, int32_t first,
                            const std::vector<ResponseTaps>& stages, float* histogram) {
  return applyResponse(diff, scratch, bins, first, stages.data(), stages.size(), histogram);
}

/// A class of one member (no scratch needed).
inline double applyResponse(double* diff, int32_t bins, int32_t first, const ResponseTaps& r,
                            float* histogram) {
  return applyResponse(diff, nullptr, bins, first, &r, 1, histogram);
}

}  // namespace tofsim::physics
