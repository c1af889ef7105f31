#include "PeakDepth.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {

// The depth of bin `best` of K, refined by the parabola through its
// neighbours' values a and c (b its own).
double refinedDepth_m(int32_t best, int32_t K, double a, double b, double c, const TimeAxis& axis) {
  double offset = 0.0;
  if (best > 0 && best < K - 1) {
    const double denom = a - 2.0 * b + c;
    if (denom < 0.0) offset = std::clamp(0.5 * (a - c) / denom, -0.5, 0.5);
  }
  const double t = axis.start_s + (best + 0.5 + offset) * axis.bin_width_s;
  return axis.depthOf_m(t);
}

// Coates' flux grows with h / remaining: a bin whose ratio is this much below
// the best one's cannot reach its flux, whatever the logarithm's rounding.
constexpr double kRatioMargin = 1.0 - 1e-12;

}  // namespace

double peakDepth_m(const std::vector<double>& histogram, const TimeAxis& axis) {
  const auto K = static_cast<int32_t>(histogram.size());
  int32_t best = -1;
  for (int32_t i = 0; i < K; ++i) {
    if (histogram[i] > 0.0 && (best < 0 || histogram[i] > histogram[best])) best = i;
  }
  if (best < 0) return std::numeric_limits<double>::quiet_NaN();
  const auto at = [&](int32_t i) { return i >= 0 && i < K ? histogram[i] : 0.0; };
  return refinedDepth_m(best, K, at(best - 1), histogram[best], at(best + 1), axis);
}

double coatesPeakDepth_m(const std::vector<double>& counts, int64_t cycles, const TimeAxis& axis) {
  const auto K = static_cast<int32_t>(counts.size());
  int32_t best = -1;
  double threshold = 0.0, bestFlux = 0.0, bestRemaining = 0.0;  // threshold: best h / remaining
  double remaining = static_cast<double>(cycles);
  for (int32_t i = 0; i < K && remaining > 0.0; ++i) {
    const double h = counts[i];
    // h < threshold * remaining: a smaller ratio (a saturated bin, h == remaining, always tried).
    if (h > 0.0 && (best < 0 || h >= remaining || h >= threshold * remaining)) {
      const double flux = coatesBinFlux(h, remaining);
      if (best < 0 || flux > bestFlux) {
        best = i;
        bestFlux = flux;
        bestRemaining = remaining;
        threshold = std::min(h / remaining, 1.0) * kRatioMargin;
      }
    }
    remaining -= h;
  }
  if (best < 0) return std::numeric_limits<double>::quiet_NaN();
  const double a =
      best > 0 ? coatesBinFlux(counts[best - 1], bestRemaining + counts[best - 1]) : 0.0;
  const double c =
      best + 1 < K ? coatesBinFlux(counts[best + 1], bestRemaining - counts[best]) : 0.0;
  return refinedDepth_m(best, K, a, bestFlux, c, axis);
}

std::vector<std::array<int32_t, 2>> plotPixels(const std::vector<std::array<int32_t, 2>>& pixels,
                                               int32_t H, int32_t W) {
  std::vector<std::array<int32_t, 2>> chosen = pixels;
  if (chosen.empty()) chosen.push_back({W / 2, H / 2});
  for (const auto& [x, y] : chosen) {
    if (x < 0 || x >= W || y < 0 || y >= H) {
      throw InputError("spad plot pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                       ") is outside the " + std::to_string(W) + "x" + std::to_string(H) +
                       " image");
    }
  }
  return chosen;
}

SensorOutput histogramPlot(const std::vector<std::array<int32_t, 2>>& pixels,
                           const std::vector<std::vector<float>>& histograms,
                           const TimeAxis& axis) {
  TOFSIM_CHECK(pixels.size() == histograms.size());
  const int32_t K = axis.bins;
  SensorOutput plot;
  plot.name = "spad_histograms";
  plot.kind = SensorOutput::Kind::HistogramPlot;
  plot.shape = {static_cast<int64_t>(pixels.size()), K};
  plot.axes = {"pixel", "t"};
  plot.time = axis;
  plot.unit = "counts";
  plot.description = "SPAD histograms of selected pixels";
  plot.axis_start = axis.start_s * 1e9;
  plot.axis_step = axis.bin_width_s * 1e9;
  plot.axis_unit = "ns";
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    TOFSIM_CHECK(static_cast<int32_t>(histograms[i].size()) == K);
    plot.data.insert(plot.data.end(), histograms[i].begin(), histograms[i].end());
    plot.labels.push_back("pixel (" + std::to_string(pixels[i][0]) + ", " +
                          std::to_string(pixels[i][1]) + ")");
  }
  return plot;
}

}  // namespace tofsim::sensors
