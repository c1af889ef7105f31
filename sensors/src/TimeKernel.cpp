#include "tofsim/sensors/TimeKernel.h"

#include <algorithm>
#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
double normalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

constexpr int kSubSamples = 64;  // source positions inside a bin
}  // namespace

double fwhmToSigma(double fwhm) { return fwhm / (2.0 * std::sqrt(2.0 * std::log(2.0))); }

BinKernel makeBinKernel(const std::function<double(double)>& cdf, double binWidth, double lo,
                        double hi) {
  TOFSIM_CHECK(binWidth > 0.0 && hi >= lo);
  const auto dLo = static_cast<int32_t>(std::floor(lo / binWidth)) - 1;
  const auto dHi = static_cast<int32_t>(std::ceil(hi / binWidth)) + 1;
  BinKernel k;
  k.first = dLo;
  k.weights.assign(static_cast<std::size_t>(dHi - dLo + 1), 0.0);
  double total = 0.0;
  for (int32_t d = dLo; d <= dHi; ++d) {
    double sum = 0.0;
    for (int s = 0; s < kSubSamples; ++s) {
      const double u = (s + 0.5) * binWidth / kSubSamples;  // source position in its bin
      sum += cdf((d + 1) * binWidth - u) - cdf(d * binWidth - u);
    }
    k.weights[d - dLo] = sum / kSubSamples;
    total += k.weights[d - dLo];
  }
  TOFSIM_CHECK(total > 0.0);
  for (double& w : k.weights) w /= total;
  return k;
}

BinKernel gaussianKernel(double sigma, double binWidth) {
  return gaussianTailKernel(sigma, 0.0, 0.0, binWidth);
}

BinKernel gaussianTailKernel(double sigma, double tailFraction, double tailTau, double binWidth) {
  TOFSIM_CHECK(sigma >= 0.0 && tailTau >= 0.0 && tailFraction >= 0.0 && tailFraction <= 1.0);
  const bool tail = tailFraction > 0.0 && tailTau > 0.0;
  if (sigma == 0.0 && !tail) return BinKernel{};
  auto gauss = [sigma](double x) {
    return sigma > 0.0 ? normalCdf(x / sigma) : (x >= 0.0 ? 1.0 : 0.0);
  };
  auto exGauss = [sigma, tailTau, gauss](double x) {
    if (sigma == 0.0) return x > 0.0 ? -std::expm1(-x / tailTau) : 0.0;
    const double z = x / sigma - sigma / tailTau;
    const double phi = normalCdf(z);
    if (phi == 0.0) return gauss(x);
    return gauss(x) - std::exp(-x / tailTau + 0.5 * (sigma / tailTau) * (sigma / tailTau)) * phi;
  };
  auto cdf = [=](double x) {
    return tail ? (1.0 - tailFraction) * gauss(x) + tailFraction * exGauss(x) : gauss(x);
  };
  const double lo = -6.0 * sigma;
  const double hi = 6.0 * sigma + (tail ? 14.0 * tailTau : 0.0);
  return makeBinKernel(cdf, binWidth, lo, hi);
}

void convolveConserving(const double* in, int32_t n, int64_t stride, const BinKernel& kernel,
                        double* out) {
  const auto m = static_cast<int32_t>(kernel.weights.size());
  for (int32_t i = 0; i < n; ++i) out[i * stride] = 0.0;
  for (int32_t i = 0; i < n; ++i) {
    const double v = in[i * stride];
    if (v == 0.0) continue;
    const int32_t jLo = std::max(0, -(i + kernel.first));
    const int32_t jHi = std::min(m - 1, n - 1 - (i + kernel.first));
    if (jLo > jHi) {  // the whole kernel falls outside: keep the energy in place
      out[i * stride] += v;
      continue;
    }
    double inside = 0.0;
    for (int32_t j = jLo; j <= jHi; ++j) inside += kernel.weights[j];
    if (inside <= 0.0) {
      out[i * stride] += v;
      continue;
    }
    const double scale = v / inside;
    for (int32_t j = jLo; j <= jHi; ++j) {
      out[static_cast<int64_t>(i + kernel.first + j) * stride] += scale * kernel.weights[j];
    }
  }
}

}  // namespace tofsim::sensors
