#pragma once
// Blur kernels on a grid of bins: Gaussian point-spread functions given by FWHM,
// optionally with an exponential tail, or a measured response constant over
// its own samples, turned into bin-to-bin transfer weights for energy spread
// uniformly within each source bin.

#include <cstdint>
#include <functional>
#include <vector>

namespace tofsim::sensors {

/// sigma = fwhm / (2 sqrt(2 ln 2)).
double fwhmToSigma(double fwhm);

/// weights[j] is the fraction of a bin's energy that moves by (first + j) bins.
/// The weights sum to 1.
struct BinKernel {
  int32_t first = 0;
  std::vector<double> weights{1.0};
};

/// Kernel for a shift distribution given by its integrated CDF G(x) =
/// int_-inf^x cdf (argument in the unit of `binWidth`), nonzero on [lo, hi]:
/// exactly, weights[d] = (G((d+1)w) - 2 G(d w) + G((d-1)w)) / w for a source
/// uniform in its bin, normalised over [lo, hi] plus a bin each side.
BinKernel makeBinKernel(const std::function<double(double)>& integratedCdf, double binWidth,
                        double lo, double hi);

/// A measured response: a shift distribution that is constant over each of
/// its samples, density[k] on [start + k sampleWidth, start + (k+1)
/// sampleWidth) (values >= 0, any scale: normalised to 1), transferred into
/// bins of `binWidth` exactly (its integrated CDF is piecewise quadratic).
BinKernel piecewiseConstantKernel(const std::vector<double>& density, double start,
                                  double sampleWidth, double binWidth);

/// Gaussian of standard deviation sigma (identity for sigma = 0), exact.
BinKernel gaussianKernel(double sigma, double binWidth);

/// Mixture: with probability 1 - tailFraction a Gaussian(sigma) shift, otherwise
/// a Gaussian(sigma) plus an exponential delay of time constant tailTau
/// (exponentially modified Gaussian). Identity for sigma = 0 and no tail.
/// Exact (closed-form integrated CDFs, makeBinKernel).
BinKernel gaussianTailKernel(double sigma, double tailFraction, double tailTau, double binWidth);

/// out[i + first + j] += in[i] * weights[j] for target bins inside [0, n). The
/// part of a kernel that falls outside is folded back by renormalising the
/// inside weights, so sum(out) == sum(in).
void convolveConserving(const double* in, int32_t n, int64_t stride, const BinKernel& kernel,
                        double* out);

}  // namespace tofsim::sensors
