#include "SpadImages.h"

#include <limits>
#include <utility>

#include "PeakDepth.h"

namespace tofsim::sensors::detail {

SensorOutput spadImage(const std::string& name, int32_t H, int32_t W, std::vector<float> data,
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

SpadImages::SpadImages(const SpadParams& p, const TimeAxis& axis, const BinKernel& kernel,
                       int32_t deadBins, int32_t height, int32_t width)
    : height_(height),
      width_(width),
      cycles_(p.cycles),
      stops_(p.tdc_stops),
      deadBins_(deadBins),
      synchronous_(p.mode == SpadMode::Synchronous),
      colormap_(p.colormap),
      axis_(axis),
      estimator_(kernel, axis, p.return_threshold_sigma) {
  const std::size_t HW = static_cast<std::size_t>(height) * static_cast<std::size_t>(width);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  depthPeak_.assign(HW, nan);
  depthCoates_.assign(HW, nan);
  intensity_.assign(HW, 0.0f);
  depthMatched_.assign(HW, nan);
  confidence_.assign(HW, 0.0f);
  returns_.assign(HW, 0.0f);
  for (auto& d : returnDepth_) d.assign(HW, nan);
  for (auto& v : returnIntensity_) v.assign(HW, 0.0f);
  if (p.flim) flim_.emplace(p, axis, kernel, height, width);
}

void SpadImages::pixel(std::size_t px, const std::vector<double>& h, Scratch& s) const {
  double total = 0.0;
  for (double c : h) total += c;
  intensity_[px] = static_cast<float>(total);
  depthPeak_[px] = static_cast<float>(peakDepth_m(h, axis_));
  // One stop and a dead time inside the cycle: Coates' own correction (and
  // its peak without a logarithm per bin); else its multi-stop, dead-time form.
  const bool classic = !synchronous_ || (stops_ == 1 && !deadTimeReachesNextCycle(h, deadBins_));
  if (classic) {
    depthCoates_[px] = static_cast<float>(coatesPeakDepth_m(h, cycles_, axis_));
  }
  // The estimators read the detections without pile-up: N times Coates'
  // flux in synchronous mode, the counts when free-running.
  if (synchronous_) {
    s.lossless = coatesEstimate(h, cycles_, stops_, deadBins_);
    if (!classic) depthCoates_[px] = static_cast<float>(peakDepth_m(s.lossless, axis_));
    for (double& v : s.lossless) v *= static_cast<double>(cycles_);
  } else {
    s.lossless = h;
  }
  const SpadEstimates e = estimator_.estimate(s.lossless, s.estimates);
  depthMatched_[px] = static_cast<float>(e.matched_depth_m);
  confidence_[px] = static_cast<float>(e.confidence);
  returns_[px] = static_cast<float>(e.returns);
  const SpadReturn* returns[3] = {&e.first, &e.strongest, &e.last};
  for (std::size_t r = 0; r < 3; ++r) {
    returnDepth_[r][px] = static_cast<float>(returns[r]->depth_m);
    returnIntensity_[r][px] = static_cast<float>(returns[r]->intensity);
  }
  if (flim_) flim_->pixel(px, s.lossless, s.flim);
}

SensorOutput SpadImages::depthImage(const std::string& name, std::vector<float> data,
                                    const std::string& description,
                                    SensorOutput::PointCloud cloud) const {
  SensorOutput o = spadImage(name, height_, width_, std::move(data), "m", description);
  o.point_cloud = std::move(cloud);
  return o;
}

void SpadImages::finish(std::vector<SensorOutput>& outputs) {
  const int32_t H = height_, W = width_;
  const std::size_t first = outputs.size();
  // Only pixels with a detected return are points: the peak and the matched
  // filter give a depth even for noise alone.
  const SensorOutput::PointCloud totals{"spad_intensity", "spad_confidence", "spad_returns"};
  outputs.push_back(depthImage("spad_depth_peak", std::move(depthPeak_),
                               "SPAD depth from the histogram peak (c t / 2)", totals));
  outputs.push_back(depthImage("spad_depth_coates", std::move(depthCoates_),
                               "SPAD depth from the peak of the Coates-corrected histogram",
                               totals));
  outputs.push_back(depthImage("spad_depth_matched", std::move(depthMatched_),
                               "SPAD depth by the log-matched filter with the instrument "
                               "response",
                               totals));
  outputs.push_back(spadImage("spad_intensity", H, W, std::move(intensity_), "counts",
                              "SPAD total counts per pixel"));
  outputs.push_back(spadImage("spad_confidence", H, W, std::move(confidence_), "-",
                              "SPAD detection confidence (background alone gives every "
                              "kernel-length window fewer counts than this pixel's fullest "
                              "with this probability; Poisson scan test)"));
  for (std::size_t i = first; i < first + 5; ++i) {
    SensorOutput png = outputs[i];
    png.kind = SensorOutput::Kind::ColorMappedImage;
    png.colormap = colormap_;
    png.point_cloud.reset();
    outputs.push_back(std::move(png));
  }
  static constexpr const char* kReturnNames[3] = {"first", "strongest", "last"};
  for (std::size_t r = 0; r < 3; ++r) {
    const std::string which = kReturnNames[r];
    outputs.push_back(depthImage("spad_depth_" + which, std::move(returnDepth_[r]),
                                 "SPAD depth of the " + which + " return (NaN: none)",
                                 {"spad_intensity_" + which, "spad_confidence", "spad_returns"}));
    outputs.push_back(spadImage("spad_intensity_" + which, H, W, std::move(returnIntensity_[r]),
                                "counts", "SPAD signal counts of the " + which + " return"));
  }
  outputs.push_back(spadImage("spad_returns", H, W, std::move(returns_), "-",
                              "SPAD returns above return_threshold per pixel"));
  if (flim_) flim_->finish(outputs);
}

void appendSpadMapImages(const SpadParams& p, const SpadPixelMaps& maps, int32_t H, int32_t W,
                         std::vector<SensorOutput>& outputs) {
  if (spadHasPixelMaps(p)) {
    const std::vector<std::pair<std::string, double>> counts = {
        {"hot_pixels", static_cast<double>(maps.hot)},
        {"dead_pixels", static_cast<double>(maps.dead)}};
    outputs.push_back(spadImage("spad_pde_map", H, W, {maps.pde.begin(), maps.pde.end()}, "-",
                                "SPAD photon detection efficiency per pixel (fixed pattern)"));
    outputs.back().attributes = counts;
    outputs.push_back(spadImage("spad_dcr_map", H, W,
                                {maps.dcr_per_s.begin(), maps.dcr_per_s.end()}, "counts / s",
                                "SPAD dark count rate per pixel (fixed pattern; hot pixels at "
                                "hot_pixel_rate, dead pixels 0)"));
    outputs.back().attributes = counts;
  }
  if (p.gate_skew_sigma_s > 0.0) {
    outputs.push_back(spadImage("spad_gate_skew_map", H, W,
                                {maps.gate_skew_s.begin(), maps.gate_skew_s.end()}, "s",
                                "SPAD gate skew per pixel: the whole gate moved by this time "
                                "(fixed pattern)"));
  }
}

}  // namespace tofsim::sensors::detail
