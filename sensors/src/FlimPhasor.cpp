#include "FlimPhasor.h"

#include <algorithm>
#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

Phasor monoExponentialPhasor(double lifetime_s, double frequency_Hz) {
  const double wt = 2.0 * M_PI * frequency_Hz * lifetime_s;
  const double d = 1.0 + wt * wt;
  return {1.0 / d, wt / d};
}

FlimPhasor::FlimPhasor(const BinKernel& kernel, const TimeAxis& axis)
    : axis_(axis), frequency_Hz_(1.0 / (axis.bins * axis.bin_width_s)) {
  TOFSIM_CHECK(axis.bins > 0 && axis.bin_width_s > 0.0);
  const double step = 2.0 * M_PI / axis.bins;  // w x bin_width
  for (int32_t n = 0; n < axis.bins; ++n) {
    cos_.push_back(std::cos(step * (n + 0.5)));
    sin_.push_back(std::sin(step * (n + 0.5)));
  }
  for (std::size_t j = 0; j < kernel.weights.size(); ++j) {
    kernel_ += kernel.weights[j] * std::polar(1.0, step * (kernel.first + static_cast<double>(j)));
  }
}

Phasor FlimPhasor::of(const std::vector<double>& h, double background, double onset_s) const {
  TOFSIM_CHECK(h.size() == cos_.size());
  double total = 0.0, re = 0.0, im = 0.0;
  for (std::size_t n = 0; n < h.size(); ++n) {
    total += h[n];
    re += h[n] * cos_[n];
    im += h[n] * sin_[n];
  }
  const double signal = total - background * static_cast<double>(h.size());
  if (!(signal > 0.0) || !std::isfinite(onset_s)) return {};
  const double turn = -2.0 * M_PI * frequency_Hz_ * (onset_s - axis_.start_s);
  const std::complex<double> p = std::complex<double>(re, im) / signal / kernel_ *
                                 std::polar(1.0, turn);
  return {p.real(), p.imag()};
}

std::vector<float> phasorPlot(const std::vector<float>& g, const std::vector<float>& s) {
  const int32_t W = kPhasorPlotWidth, H = kPhasorPlotHeight;
  std::vector<float> cells(static_cast<std::size_t>(W) * H, 0.0f);
  const auto cell = [&](double gv, double sv) -> float* {
    // Outside the plot (or NaN): no cell (and no cast of a huge double).
    if (!(gv >= 0.0 && gv < W * kPhasorCell && sv >= 0.0 && sv < H * kPhasorCell)) return nullptr;
    const auto x = static_cast<int64_t>(std::floor(gv / kPhasorCell));
    const auto y = static_cast<int64_t>(H - 1 - std::floor(sv / kPhasorCell));  // row 0 = top
    if (!(x >= 0 && x < W && y >= 0 && y < H)) return nullptr;
    return &cells[static_cast<std::size_t>(y) * W + static_cast<std::size_t>(x)];
  };
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (float* c = cell(g[i], s[i])) *c += 1.0f;
  }
  // Each cell drawn as a square of kPhasorMark x kPhasorMark cells (the
  // largest count under it): a lifetime's pixels gather in a cell or two,
  // one picture pixel each otherwise.
  std::vector<float> marked(cells.size(), 0.0f);
  const int32_t r = kPhasorMark / 2;
  for (int32_t y = 0; y < H; ++y) {
    for (int32_t x = 0; x < W; ++x) {
      const float v = cells[static_cast<std::size_t>(y) * W + static_cast<std::size_t>(x)];
      if (v == 0.0f) continue;
      for (int32_t dy = std::max(0, y - r); dy <= std::min(H - 1, y + r); ++dy) {
        for (int32_t dx = std::max(0, x - r); dx <= std::min(W - 1, x + r); ++dx) {
          float& m = marked[static_cast<std::size_t>(dy) * W + static_cast<std::size_t>(dx)];
          m = std::max(m, v);
        }
      }
    }
  }
  cells = std::move(marked);
  const float top = std::max(1.0f, *std::max_element(cells.begin(), cells.end()));
  // The semicircle (g - 1/2)^2 + s^2 = 1/4, s >= 0, a point per half cell, at
  // kPhasorCircleLevel of the top count and only in empty cells: a
  // mono-exponential's pixels lie on it, and must stay visible there.
  const int32_t points = 4 * W;
  for (int32_t k = 0; k <= points; ++k) {
    const double angle = M_PI * k / points;
    float* c = cell(0.5 + 0.5 * std::cos(angle), 0.5 * std::sin(angle));
    if (c != nullptr && *c == 0.0f) *c = kPhasorCircleLevel * top;
  }
  return cells;
}

}  // namespace tofsim::sensors::detail
