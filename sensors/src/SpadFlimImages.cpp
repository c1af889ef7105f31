#include "SpadFlimImages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "SpadImages.h"

namespace tofsim::sensors::detail {

Phasor flimPhasorOf(const FlimFitter& fitter, const FlimPhasor& phasor, const std::vector<double>& h,
                    const FlimFit& fit, FlimFitter::Scratch& scratch) {
  const TimeAxis& axis = fitter.axis();
  const BinKernel& k = fitter.kernel();
  const double onset = (fit.onset_s - axis.start_s) / axis.bin_width_s;
  const double tau = fit.lifetime_s / axis.bin_width_s;
  // The kernel's rise, from its first weight to its peak, taken as its
  // spread after the peak too (a long diffusion tail would reach too far).
  const auto peak = std::max_element(k.weights.begin(), k.weights.end()) - k.weights.begin();
  const double spread = static_cast<double>(peak) + 1.0;
  const double end = std::min(onset + 0.5 * tau + spread, static_cast<double>(axis.bins));
  const FlimFit edge = fitter.fit(h, scratch, static_cast<int32_t>(std::ceil(end)));
  const double onset_s = edge.converged ? edge.onset_s : fit.onset_s;
  // The bins before the edge: before the onset less the kernel's lead.
  const double before = (onset_s - axis.start_s) / axis.bin_width_s + std::min(0, k.first) - 1.0;
  double background = fit.background;
  if (before >= 4.0) {
    const auto n = static_cast<std::size_t>(before);
    background = 0.0;
    for (std::size_t i = 0; i < n; ++i) background += h[i];
    background /= static_cast<double>(n);
  }
  return phasor.of(h, background, onset_s);
}

SpadFlimImages::SpadFlimImages(const SpadParams& p, const TimeAxis& axis, const BinKernel& kernel,
                               int32_t height, int32_t width)
    : height_(height),
      width_(width),
      minCounts_(p.flim_min_counts),
      colormap_(p.colormap),
      fitter_(kernel, axis),
      phasor_(kernel, axis) {
  const std::size_t HW = static_cast<std::size_t>(height) * static_cast<std::size_t>(width);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  lifetime_.assign(HW, nan);
  sigma_.assign(HW, nan);
  g_.assign(HW, nan);
  s_.assign(HW, nan);
  status_.assign(HW, kFewCounts);
}

void SpadFlimImages::pixel(std::size_t px, const std::vector<double>& h,
                           FlimFitter::Scratch& s) const {
  double total = 0.0;
  for (double v : h) total += v;
  if (!(total >= minCounts_) || !(total > 0.0)) return;  // stays NaN, kFewCounts
  const FlimFit fit = fitter_.fit(h, s);
  if (!fit.converged) {
    status_[px] = kNotConverged;
    return;
  }
  status_[px] = kFitted;
  lifetime_[px] = static_cast<float>(fit.lifetime_s);
  sigma_[px] = static_cast<float>(fit.lifetime_sigma_s);
  const Phasor ph = flimPhasorOf(fitter_, phasor_, h, fit, s);
  g_[px] = static_cast<float>(ph.g);
  s_[px] = static_cast<float>(ph.s);
}

void SpadFlimImages::finish(std::vector<SensorOutput>& outputs) {
  const int32_t H = height_, W = width_;
  std::size_t counts[3] = {0, 0, 0};
  for (uint8_t st : status_) ++counts[st];
  const std::vector<std::pair<std::string, double>> fitCounts = {
      {"min_counts", minCounts_},
      {"pixels_fitted", static_cast<double>(counts[kFitted])},
      {"pixels_below_min_counts", static_cast<double>(counts[kFewCounts])},
      {"pixels_not_converged", static_cast<double>(counts[kNotConverged])}};
  const double f = phasor_.frequency_Hz();
  const std::vector<std::pair<std::string, double>> phasorAttributes = {
      {"frequency_Hz", f}, {"period_s", 1.0 / f}, {"pixels_fitted", static_cast<double>(counts[kFitted])}};

  std::vector<float> lifetime_ns(lifetime_.begin(), lifetime_.end());
  for (float& v : lifetime_ns) v *= 1e9f;
  std::vector<float> plot = phasorPlot(g_, s_);
  outputs.push_back(spadImage("spad_lifetime", H, W, std::move(lifetime_), "s",
                              "FLIM lifetime: mono-exponential maximum-likelihood fit with the "
                              "instrument response (NaN: too few counts or no fit)"));
  outputs.back().attributes = fitCounts;
  SensorOutput picture = outputs.back();
  outputs.push_back(spadImage("spad_lifetime_sigma", H, W, std::move(sigma_), "s",
                              "FLIM lifetime's standard deviation (Cramer-Rao bound of the fit)"));
  outputs.back().attributes = fitCounts;
  outputs.push_back(spadImage("spad_phasor_g", H, W, std::move(g_), "-",
                              "FLIM phasor g at the laser's repetition frequency, IRF-calibrated"));
  outputs.back().attributes = phasorAttributes;
  outputs.push_back(spadImage("spad_phasor_s", H, W, std::move(s_), "-",
                              "FLIM phasor s at the laser's repetition frequency, IRF-calibrated"));
  outputs.back().attributes = phasorAttributes;

  picture.kind = SensorOutput::Kind::ColorMappedImage;
  picture.data = std::move(lifetime_ns);
  picture.unit = "ns";
  picture.colormap = colormap_;
  outputs.push_back(std::move(picture));
  char title[256];
  std::snprintf(title, sizeof title,
                "FLIM phasor plot at %.4g MHz: pixels per (g, s) cell of 0.0025 (drawn 5 wide), g 0..1 left to right, "
                "s 0..0.6 bottom to top, universal semicircle at 30 %% of the top count",
                f * 1e-6);
  SensorOutput phasorPicture = spadImage("spad_phasor_plot", kPhasorPlotHeight, kPhasorPlotWidth,
                                         std::move(plot), "pixels", title);
  phasorPicture.kind = SensorOutput::Kind::ColorMappedImage;
  phasorPicture.colormap = "viridis";
  // The counts' whole range: the semicircle's many cells would set a robust
  // range's top and saturate the pixels' cells.
  const float top = *std::max_element(phasorPicture.data.begin(), phasorPicture.data.end());
  phasorPicture.picture_range = std::array<double, 2>{0.0, std::max(1.0, static_cast<double>(top))};
  phasorPicture.attributes = phasorAttributes;
  phasorPicture.attributes.push_back({"g_left", 0.0});
  phasorPicture.attributes.push_back({"g_right", kPhasorPlotWidth * kPhasorCell});
  phasorPicture.attributes.push_back({"s_bottom", 0.0});
  phasorPicture.attributes.push_back({"s_top", kPhasorPlotHeight * kPhasorCell});
  outputs.push_back(std::move(phasorPicture));
}

}  // namespace tofsim::sensors::detail
