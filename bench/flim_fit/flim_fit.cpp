// The SPAD's FLIM fit per pixel (sensors/src/FlimFit, SpadFlimImages): the
// maximum-likelihood mono-exponential fit with the IRF reconvolved, and the
// pixel's whole FLIM step (the fit, the rising edge's second fit and the
// phasor), in microseconds per pixel, on Poisson histograms of a 40 MHz
// laser (25 ns range) at several bin counts, IRF widths and photon counts;
// the SPAD's other per-pixel estimators (the log-matched filter and returns)
// on the same histograms for scale. One thread, its CPU time.
//   ./build/bench/tofsim_flim_fit [pixels per case]
#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "FlimFit.h"
#include "FlimPhasor.h"
#include "SpadEstimators.h"
#include "SpadFlimImages.h"
#include "tofsim/sensors/Random.h"
#include "tofsim/sensors/TimeKernel.h"

#include "../BenchArgs.h"

using namespace tofsim;
using namespace tofsim::sensors;
using namespace tofsim::sensors::detail;

namespace {
// This thread's CPU time, s: on a shared machine wall time counts the
// other processes' share too.
double threadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double microsecondsPerPixel(const std::vector<std::vector<double>>& hs, auto&& step) {
  const double t0 = threadSeconds();
  for (const auto& h : hs) step(h);
  return 1e6 * (threadSeconds() - t0) / static_cast<double>(hs.size());
}
}  // namespace

int main(int argc, char** argv) {
  const int pixels = bench::arg(argc, argv, 1, 2000);
  std::printf("%6s %8s %9s %10s %12s %12s %12s %8s\n", "bins", "irf_ps", "photons", "fit_us",
              "flim_us", "estim_us", "tau_ns", "iters");
  for (const int bins : {256, 1024, 4096}) {
    for (const double irf_ps : {100.0, 300.0}) {
      for (const double photons : {1e3, 1e5}) {
        TimeAxis axis;
        axis.bins = bins;
        axis.bin_width_s = 25e-9 / bins;
        const BinKernel k = gaussianKernel(fwhmToSigma(irf_ps * 1e-12), axis.bin_width_s);
        const FlimFitter fitter(k, axis);
        const FlimPhasor phasor(k, axis);
        const SpadEstimator estimator(k, axis, 5.0);
        std::vector<double> mu;
        fitter.expected(photons, 2.0 * 256 / bins, 2.5e-9, 3e-9, mu);
        std::vector<std::vector<double>> hs(static_cast<std::size_t>(pixels));
        for (int p = 0; p < pixels; ++p) {
          Rng rng(7, static_cast<uint64_t>(p));
          for (double m : mu) hs[p].push_back(static_cast<double>(rng.poisson(m)));
        }
        FlimFitter::Scratch s;
        SpadEstimator::Scratch es;
        double tau = 0.0, iterations = 0.0;
        const double fit = microsecondsPerPixel(hs, [&](const std::vector<double>& h) {
          const FlimFit f = fitter.fit(h, s);
          tau += f.lifetime_s / pixels;
          iterations += static_cast<double>(f.iterations) / pixels;
        });
        volatile double sink = 0.0;
        const double flim = microsecondsPerPixel(hs, [&](const std::vector<double>& h) {
          const FlimFit f = fitter.fit(h, s);
          sink = sink + flimPhasorOf(fitter, phasor, h, f, s).g;
        });
        const double estim = microsecondsPerPixel(hs, [&](const std::vector<double>& h) {
          sink = sink + estimator.estimate(h, es).confidence;
        });
        std::printf("%6d %8.0f %9.0f %10.1f %12.1f %12.1f %12.4f %8.1f\n", bins, irf_ps, photons,
                    fit, flim, estim, tau * 1e9, iterations);
      }
    }
  }
  return 0;
}
