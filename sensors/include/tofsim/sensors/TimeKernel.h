#pragma once
// Blur kernels on a grid of bins: Gaussian point-spread functions given by FWHM,
// optionally with an exponential tail, or a measured response constant over
// its own samples, turned into bin-to-bin transfer weights for energy spread
// uniformly within each source bin.

#include <cstddef>
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

/// The shifts [lo, hi] a kernel is laid out over (in the unit of its bin
/// width): makeBinKernel's, named once for the kernels below and for the
/// check that refuses one too wide (SensorType<>::timeKernels).
struct KernelSupport {
  double lo = 0.0;
  double hi = 0.0;
};

/// The farthest a kernel may reach from zero delay, in bins (its weights are
/// laid out from there, 32 MiB at most). Wider is bad input (a jitter of
/// seconds on picosecond bins, a response file in the wrong unit): the
/// config layer refuses it with the key that sets it, and makeBinKernel
/// CHECKs it.
inline constexpr double kMaxKernelReachBins = 4194304.0;

/// How many bins of `binWidth` the support reaches from zero delay, a bin of
/// margin included (as a double: any support, even a non-finite one, gives a
/// number, NaN compares false).
double kernelReachBins(const KernelSupport& support, double binWidth);

/// gaussianTailKernel's support: 6 sigma each side, and 14 tailTau more after.
KernelSupport gaussianTailSupport(double sigma, double tailFraction, double tailTau);

/// piecewiseConstantKernel's support: [start, start + samples sampleWidth].
KernelSupport piecewiseConstantSupport(std::size_t samples, double start, double sampleWidth);

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
