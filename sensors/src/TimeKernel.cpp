#include "tofsim/sensors/TimeKernel.h"

#include <algorithm>
#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
double normalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }
double normalPdf(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * M_PI); }

/// exp(u^2) erfc(u) for u >= 0, without overflow (asymptotic series beyond 26,
/// relative error < 1e-13 there).
double erfcx(double u) {
  if (u < 26.0) return std::exp(u * u) * std::erfc(u);
  const double v = 1.0 / (2.0 * u * u);
  return (1.0 - v * (1.0 - 3.0 * v * (1.0 - 5.0 * v * (1.0 - 7.0 * v)))) / (u * std::sqrt(M_PI));
}

}  // namespace

double fwhmToSigma(double fwhm) { return fwhm / (2.0 * std::sqrt(2.0 * std::log(2.0))); }

double kernelReachBins(const KernelSupport& support, double binWidth) {
  return std::max(std::fabs(std::floor(support.lo / binWidth)),
                  std::fabs(std::ceil(support.hi / binWidth))) +
         1.0;
}

KernelSupport gaussianTailSupport(double sigma, double tailFraction, double tailTau) {
  const bool tail = tailFraction > 0.0 && tailTau > 0.0;
  return {-6.0 * sigma, 6.0 * sigma + (tail ? 14.0 * tailTau : 0.0)};
}

KernelSupport piecewiseConstantSupport(std::size_t samples, double start, double sampleWidth) {
  return {start, start + static_cast<double>(samples) * sampleWidth};
}

BinKernel makeBinKernel(const std::function<double(double)>& integratedCdf, double binWidth,
                        double lo, double hi) {
  TOFSIM_CHECK(binWidth > 0.0 && hi >= lo);
  // Bad input never gets here (the config checks each model's kernels):
  // beyond this the bin indices below would not fit an int32.
  TOFSIM_CHECK(kernelReachBins({lo, hi}, binWidth) <= kMaxKernelReachBins);
  const auto dLo = static_cast<int32_t>(std::floor(lo / binWidth)) - 1;
  const auto dHi = static_cast<int32_t>(std::ceil(hi / binWidth)) + 1;
  BinKernel k;
  k.first = dLo;
  k.weights.assign(static_cast<std::size_t>(dHi - dLo + 1), 0.0);
  // A source uniform in [0, w) shifted by X lands in [d w, (d + 1) w) with
  // probability (1/w) int_0^w F((d+1)w - u) - F(dw - u) du, the second
  // difference of G = int F.
  double gPrev = integratedCdf((dLo - 1) * binWidth), gHere = integratedCdf(dLo * binWidth);
  double total = 0.0;
  for (int32_t d = dLo; d <= dHi; ++d) {
    const double gNext = integratedCdf((d + 1) * binWidth);
    const double w = std::max(0.0, (gNext - gHere) - (gHere - gPrev)) / binWidth;
    k.weights[d - dLo] = w;
    total += w;
    gPrev = gHere;
    gHere = gNext;
  }
  TOFSIM_CHECK(total > 0.0);
  for (double& w : k.weights) w /= total;
  return k;
}

BinKernel piecewiseConstantKernel(const std::vector<double>& density, double start,
                                  double sampleWidth, double binWidth) {
  TOFSIM_CHECK(!density.empty() && sampleWidth > 0.0);
  // Probabilities p_k of the samples, their CDF F_k and int F G_k at the
  // leading edges; inside sample k both are polynomials (linear, quadratic).
  const std::size_t n = density.size();
  double sum = 0.0;
  for (double v : density) {
    TOFSIM_CHECK(v >= 0.0);
    sum += v;
  }
  TOFSIM_CHECK(sum > 0.0);
  std::vector<double> p(n), F(n + 1, 0.0), G(n + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    p[k] = density[k] / sum;
    F[k + 1] = F[k] + p[k];
    G[k + 1] = G[k] + (F[k] + 0.5 * p[k]) * sampleWidth;
  }
  const double end = piecewiseConstantSupport(n, start, sampleWidth).hi;
  auto integrated = [&](double x) {
    if (x <= start) return 0.0;
    if (x >= end) return G[n] + F[n] * (x - end);
    const auto k = std::min(n - 1, static_cast<std::size_t>((x - start) / sampleWidth));
    const double dx = x - (start + static_cast<double>(k) * sampleWidth);
    return G[k] + F[k] * dx + 0.5 * p[k] / sampleWidth * dx * dx;
  };
  return makeBinKernel(integrated, binWidth, start, end);
}

BinKernel gaussianKernel(double sigma, double binWidth) {
  return gaussianTailKernel(sigma, 0.0, 0.0, binWidth);
}

BinKernel gaussianTailKernel(double sigma, double tailFraction, double tailTau, double binWidth) {
  TOFSIM_CHECK(sigma >= 0.0 && tailTau >= 0.0 && tailFraction >= 0.0 && tailFraction <= 1.0);
  const bool tail = tailFraction > 0.0 && tailTau > 0.0;
  if (sigma == 0.0 && !tail) return BinKernel{};
  // Integrated CDFs G(x) = int_-inf^x F, in closed form, so the bin weights
  // (second differences of G) are exact.
  auto gaussG = [sigma](double x) {
    if (sigma == 0.0) return std::max(0.0, x);
    return x * normalCdf(x / sigma) + sigma * normalPdf(x / sigma);
  };
  // Exponentially modified Gaussian: F = Phi(x/s) - E(x), E = exp(-x/tau +
  // s^2/(2 tau^2)) Phi(x/s - s/tau); int E = tau Phi(x/s) - tau E.
  auto tailE = [sigma, tailTau](double x) {
    if (sigma == 0.0) return x > 0.0 ? std::exp(-x / tailTau) : 1.0;
    const double z = x / sigma - sigma / tailTau;
    if (z >= 0.0) {
      const double r = sigma / tailTau;
      return std::exp(-x / tailTau + 0.5 * r * r) * normalCdf(z);
    }
    // E = 0.5 exp(-x^2 / (2 s^2)) erfcx(-z / sqrt 2): no overflow.
    return 0.5 * std::exp(-0.5 * (x / sigma) * (x / sigma)) * erfcx(-z / std::sqrt(2.0));
  };
  auto exGaussG = [=](double x) {
    if (sigma == 0.0) return x > 0.0 ? x - tailTau * (1.0 - std::exp(-x / tailTau)) : 0.0;
    return gaussG(x) - tailTau * normalCdf(x / sigma) + tailTau * tailE(x);
  };
  auto integrated = [=](double x) {
    return tail ? (1.0 - tailFraction) * gaussG(x) + tailFraction * exGaussG(x) : gaussG(x);
  };
  const KernelSupport support = gaussianTailSupport(sigma, tailFraction, tailTau);
  return makeBinKernel(integrated, binWidth, support.lo, support.hi);
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
