#include "tofsim/sensors/Spad.h"

#include <cmath>
#include <limits>
#include <string>

#include "PeakDepth.h"
#include "tofsim/sensors/Random.h"
#include "tofsim/sensors/TimeKernel.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr uint32_t kSpadStreamTag = 0x5350;  // "SP"

BinKernel spadKernel(const SpadParams& p, const TimeAxis& axis) {
  const double sp = fwhmToSigma(p.pulse_fwhm_s);
  const double sj = fwhmToSigma(p.jitter_fwhm_s);
  return gaussianTailKernel(std::sqrt(sp * sp + sj * sj), p.jitter_tail_fraction, p.jitter_tail_s,
                            axis.bin_width_s);
}

void checkParams(const SpadParams& p) {
  TOFSIM_CHECK(p.cycles >= 1);
  TOFSIM_CHECK(p.pulse_fwhm_s >= 0.0 && p.jitter_fwhm_s >= 0.0 && p.jitter_tail_s >= 0.0);
  TOFSIM_CHECK(p.jitter_tail_fraction >= 0.0 && p.jitter_tail_fraction <= 1.0);
  TOFSIM_CHECK(p.pde >= 0.0 && p.pde <= 1.0);
  TOFSIM_CHECK(p.ambient_rate_per_s >= 0.0 && p.dark_count_rate_per_s >= 0.0);
  TOFSIM_CHECK(p.dead_time_s >= 0.0);
}

void fluxWithKernel(const TransientVolume& volume, const SpadParams& p, const TimeAxis& axis,
                    const BinKernel& kernel, int32_t y, int32_t x, std::vector<double>& flux) {
  std::vector<double> signal, resampled;
  pixelSignal(volume, p.common, y, x, signal);
  resampleEnergy(signal, volume.axis(), axis, resampled);
  flux.assign(resampled.size(), 0.0);
  convolveConserving(resampled.data(), axis.bins, 1, kernel, flux.data());
  const double background =
      p.pde * p.ambient_rate_per_s * axis.bin_width_s + p.dark_count_rate_per_s * axis.bin_width_s;
  for (double& f : flux) f = p.pde * std::max(0.0, f) + background;
}

SensorOutput image(const std::string& name, int32_t H, int32_t W, std::vector<float> data,
                   const std::string& unit, const std::string& description) {
  SensorOutput o;
  o.name = name;
  o.kind = SensorOutput::Kind::Image;
  o.shape = {H, W};
  o.axes = {"y", "x"};
  o.data = std::move(data);
  o.unit = unit;
  o.description = description;
  return o;
}
}  // namespace

void spadFluxPerCycle(const TransientVolume& volume, const SpadParams& params, const TimeAxis& axis,
                      int32_t y, int32_t x, std::vector<double>& flux) {
  checkParams(params);
  fluxWithKernel(volume, params, axis, spadKernel(params, axis), y, x, flux);
}

std::vector<SensorOutput> runSpad(const TransientVolume& volume, const SpadParams& p,
                                  uint64_t seed) {
  checkParams(p);
  checkChannelSelection(p.common.channel, volume);
  const TimeAxis axis = resolveBins(p.bins, volume.axis());
  const BinKernel kernel = spadKernel(p, axis);
  const int32_t H = volume.height(), W = volume.width(), K = axis.bins;
  const auto deadBins = static_cast<int32_t>(std::lround(p.dead_time_s / axis.bin_width_s));
  const auto N = static_cast<uint64_t>(p.cycles);

  SensorOutput counts;
  counts.name = "spad_counts";
  counts.kind = SensorOutput::Kind::Array;
  counts.shape = {H, W, K};
  counts.axes = {"y", "x", "t"};
  counts.time = axis;
  counts.unit = "counts";
  counts.description = "SPAD detections per TDC bin over " + std::to_string(p.cycles) +
                       " laser cycles (" +
                       (p.mode == SpadMode::Synchronous ? "synchronous" : "free-running") + ")";
  counts.data.resize(static_cast<std::size_t>(H) * W * K);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> depthPeak(static_cast<std::size_t>(H) * W, nan);
  std::vector<float> depthCoates(depthPeak.size(), nan), intensity(depthPeak.size(), 0.0f);

  std::vector<double> flux, h(static_cast<std::size_t>(K));
  for (int32_t y = 0; y < H; ++y) {
    for (int32_t x = 0; x < W; ++x) {
      const std::size_t pixel = static_cast<std::size_t>(y) * W + x;
      fluxWithKernel(volume, p, axis, kernel, y, x, flux);
      Rng rng(seed, pixelStream(kSpadStreamTag, pixel));
      double total = 0.0;
      if (p.mode == SpadMode::Synchronous) {
        // Multinomial over "first detection in bin i" and "none", drawn as
        // sequential conditional binomials: given no detection before bin i,
        // the first one is in bin i with probability q_i.
        uint64_t remaining = N;
        for (int32_t i = 0; i < K; ++i) {
          const uint64_t n = remaining == 0 ? 0 : rng.binomial(remaining, -std::expm1(-flux[i]));
          h[i] = static_cast<double>(n);
          remaining -= n;
        }
      } else {
        const std::vector<double> m = freeRunningProbabilities(flux, deadBins);
        for (int32_t i = 0; i < K; ++i) h[i] = static_cast<double>(rng.binomial(N, m[i]));
      }
      float* out = counts.data.data() + pixel * K;
      for (int32_t i = 0; i < K; ++i) {
        out[i] = static_cast<float>(h[i]);
        total += h[i];
      }
      intensity[pixel] = static_cast<float>(total);
      depthPeak[pixel] = static_cast<float>(peakDepth_m(h, axis));
      depthCoates[pixel] = static_cast<float>(peakDepth_m(coatesEstimate(h, p.cycles), axis));
    }
  }

  std::vector<SensorOutput> outputs;
  outputs.push_back(std::move(counts));
  outputs.push_back(image("spad_depth_peak", H, W, std::move(depthPeak), "m",
                          "SPAD depth from the histogram peak (c t / 2)"));
  outputs.push_back(image("spad_depth_coates", H, W, std::move(depthCoates), "m",
                          "SPAD depth from the peak of the Coates-corrected histogram"));
  outputs.push_back(
      image("spad_intensity", H, W, std::move(intensity), "counts", "SPAD total counts per pixel"));
  for (std::size_t i = 1; i < 4; ++i) {
    SensorOutput png = outputs[i];
    png.kind = SensorOutput::Kind::ColorMappedImage;
    png.colormap = p.colormap;
    outputs.push_back(std::move(png));
  }
  outputs.push_back(histogramPlot(outputs[0], p.plot_pixels, axis, H, W));
  return outputs;
}

}  // namespace tofsim::sensors
