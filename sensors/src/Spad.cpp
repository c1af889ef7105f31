#include "tofsim/sensors/Spad.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ParallelPixels.h"
#include "PeakDepth.h"
#include "SpadAfterpulseFlux.h"
#include "SpadCrosstalk.h"
#include "SpadEstimators.h"
#include "SpadEventEngine.h"
#include "SpadExactCrosstalk.h"
#include "SpadGate.h"
#include "SpadGatedFrames.h"
#include "SpadSampling.h"
#include "tofsim/sensors/Random.h"
#include "tofsim/sensors/SpadPixelMaps.h"
#include "tofsim/sensors/TimeKernel.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr uint32_t kSpadStreamTag = 0x5350;  // "SP"

BinKernel spadKernel(const SpadParams& p, const TimeAxis& axis) {
  if (p.irf.present()) {
    const SpadIrf& irf = p.irf;
    const double start = irf.first_time_s - 0.5 * irf.sample_width_s - irfTimeZero_s(irf);
    return piecewiseConstantKernel(irf.values, start, irf.sample_width_s, axis.bin_width_s);
  }
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
  TOFSIM_CHECK(p.dead_time_s >= 0.0 && p.tdc_stops >= 0);
  TOFSIM_CHECK(p.gate_width_s >= 0.0 && p.gate_skew_sigma_s >= 0.0);
  TOFSIM_CHECK(p.gated_frames >= 0 && p.pulses_per_frame >= 1 && p.gate_positions >= 1);
  TOFSIM_CHECK(p.counter_bits >= 0 && p.counter_bits <= 62);
  TOFSIM_CHECK(p.afterpulse_probability >= 0.0 && p.afterpulse_probability <= 1.0);
  TOFSIM_CHECK(!p.afterpulse_delays_s.empty());
  for (double d : p.afterpulse_delays_s) TOFSIM_CHECK(d > 0.0);
  TOFSIM_CHECK(p.afterpulse_weights.empty() ||
               p.afterpulse_weights.size() == p.afterpulse_delays_s.size());
  TOFSIM_CHECK(p.crosstalk_probability >= 0.0 && p.crosstalk_probability <= 1.0);
  TOFSIM_CHECK(p.crosstalk_delay_s >= 0.0);
  // A delayed arrival into a gate, gate ramps or per-pixel skew: the exact
  // array driver only (config errors with `engine: fast`); the gated frames'
  // other gate positions: not modelled (checkCrosstalkGate).
  TOFSIM_CHECK(p.engine != SpadEngine::Fast || !detail::crosstalkNeedsEvents(p));
  TOFSIM_CHECK(p.crosstalk_probability == 0.0 || p.gated_frames == 0);
  if (p.irf.present()) {
    TOFSIM_CHECK(p.irf.sample_width_s > 0.0);
    TOFSIM_CHECK(p.pulse_fwhm_s == 0.0 && p.jitter_fwhm_s == 0.0 && p.jitter_tail_fraction == 0.0);
  }
  TOFSIM_CHECK(p.pde_spread >= 0.0 && p.dark_count_log_sigma >= 0.0);
  TOFSIM_CHECK(p.hot_pixel_fraction >= 0.0 && p.hot_pixel_fraction <= 1.0);
  TOFSIM_CHECK(p.dead_pixel_fraction >= 0.0 && p.dead_pixel_fraction <= 1.0);
  TOFSIM_CHECK(p.hot_pixel_rate_per_s >= 0.0);
  TOFSIM_CHECK(p.return_threshold_sigma > 0.0);
}

// Per-cycle flux of one pixel from its render bins (signal in photo-electrons),
// with the pixel's own PDE and dark count rate, before the gate. With a
// DNL table the light is first spread over the nominal bins (where the
// kernel is defined), then moved into the true unequal bins by overlap.
void fluxFromSignal(const std::vector<double>& signal, const TimeAxis& render, const SpadParams& p,
                    const SpadPixel& pixel, const detail::TdcBins& bins, const BinKernel& kernel,
                    std::vector<double>& resampled, std::vector<double>& flux) {
  const TimeAxis& axis = bins.axis;
  resampleEnergy(signal, render, axis, resampled);
  flux.assign(resampled.size(), 0.0);
  convolveConserving(resampled.data(), axis.bins, 1, kernel, flux.data());
  const double pde = pixel.pde, dcr_per_s = pixel.dcr_per_s;
  if (bins.edges.empty()) {
    const double background =
        pde * p.ambient_rate_per_s * axis.bin_width_s + dcr_per_s * axis.bin_width_s;
    for (double& f : flux) f = pde * std::max(0.0, f) + background;
    return;
  }
  resampled.swap(flux);
  resampleEnergyToEdges(resampled, axis, bins.edges, flux);
  for (int32_t i = 0; i < axis.bins; ++i) {
    const double w = bins.width(i);
    flux[i] = pde * std::max(0.0, flux[i]) + pde * p.ambient_rate_per_s * w + dcr_per_s * w;
  }
}

// A disarmed detector sees nothing, so the first-photon and dead-time laws
// run on the gated flux alone; the pixel's gate is moved by its skew.
void gateFlux(const SpadParams& p, const detail::SpadGate& gate, const SpadPixel& pixel,
              const detail::TdcBins& bins, std::vector<double>& flux) {
  if (p.gate_width_s > 0.0) detail::applyGate(gate.shifted(pixel.gate_skew_s), bins, flux);
}

// The event engine's laws of the model's detector (free-running: every
// detection recorded).
detail::DetectorLaws detectorLaws(const SpadParams& p, const TimeAxis& axis, int32_t deadBins) {
  detail::DetectorLaws laws;
  laws.deadBins = deadBins;
  laws.stops = p.mode == SpadMode::Synchronous ? p.tdc_stops : 0;
  detail::AfterpulseLaw& ap = laws.afterpulses;
  ap.count = p.afterpulse_count == SpadAfterpulseCount::Poisson
                 ? detail::AfterpulseLaw::Count::Poisson
                 : detail::AfterpulseLaw::Count::Bernoulli;
  ap.mean = p.afterpulse_probability;
  ap.delays_bins.clear();
  for (double d : p.afterpulse_delays_s) ap.delays_bins.push_back(d / axis.bin_width_s);
  ap.weights = p.afterpulse_weights;
  if (ap.weights.empty()) ap.weights.assign(ap.delays_bins.size(), 1.0);
  ap.reset = p.afterpulse_traps == SpadAfterpulseTraps::Reset;
  return laws;
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
  std::vector<double> signal, resampled;
  pixelSignal(volume, params.common, y, x, signal);
  const std::size_t px = static_cast<std::size_t>(y) * volume.width() + x;
  const SpadPixel pixel = spadPixel(params, px);
  const detail::TdcBins bins = detail::tdcBins(params, axis);
  fluxFromSignal(signal, volume.axis(), params, pixel, bins, spadKernel(params, axis), resampled,
                 flux);
  gateFlux(params, detail::spadGate(params), pixel, bins, flux);
}

double irfTimeZero_s(const SpadIrf& irf) {
  TOFSIM_CHECK(irf.present());
  const auto timeOf = [&](std::size_t k) {
    return irf.first_time_s + static_cast<double>(k) * irf.sample_width_s;
  };
  switch (irf.t0) {
    case SpadIrf::TimeZero::Peak:
      return timeOf(static_cast<std::size_t>(
          std::max_element(irf.values.begin(), irf.values.end()) - irf.values.begin()));
    case SpadIrf::TimeZero::Centroid: {
      double sum = 0.0, moment = 0.0;
      for (std::size_t k = 0; k < irf.values.size(); ++k) {
        sum += irf.values[k];
        moment += irf.values[k] * timeOf(k);
      }
      return moment / sum;
    }
    case SpadIrf::TimeZero::Time:
      return irf.t0_s;
  }
  return irf.t0_s;
}

namespace {

/// The SPAD fed pixel by pixel: per-pixel images, the plotted pixels'
/// histograms, and the counts either held or streamed to an ArrayWriter.
class SpadStream final : public SensorStream {
 public:
  SpadStream(const SpadParams& p, const VolumeShape& shape, const StreamOptions& options)
      : p_(p),
        shape_(shape),
        options_(options),
        axis_(resolveBins(p.bins, shape.axis)),
        bins_(detail::tdcBins(p, axis_)),
        gate_(detail::spadGate(p)),
        kernel_(spadKernel(p, axis_)),
        deadBins_(static_cast<int32_t>(std::lround(p.dead_time_s / axis_.bin_width_s))),
        laws_(detectorLaws(p, axis_, deadBins_)),
        plotted_(plotPixels(p.plot_pixels, shape.height, shape.width)),
        histograms_(plotted_.size()),
        maps_(spadPixelMaps(p, shape.height, shape.width)),
        frames_(p, shape, options),
        estimator_(kernel_, axis_, p.return_threshold_sigma) {
    checkParams(p);
    if (detail::exactCrosstalk(p)) {
      exact_ =
          std::make_unique<detail::SpadExactCrosstalk>(p, laws_, bins_, shape.width, shape.height);
    } else if (p.crosstalk_probability > 0.0) {
      // A batch of an image row (at least 256 pixels) between look-aheads.
      crosstalk_ = std::make_unique<detail::SpadCrosstalk>(
          p, axis_.bins, axis_.bin_width_s, deadBins_, shape.width, shape.height,
          std::max<std::size_t>(256, static_cast<std::size_t>(shape.width)));
    }
    checkChannelSelection(p.common.channel, shape.channels);
    const std::size_t HW = shape.pixelCount();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    depthPeak_.assign(HW, nan);
    depthCoates_.assign(HW, nan);
    intensity_.assign(HW, 0.0f);
    depthMatched_.assign(HW, nan);
    confidence_.assign(HW, 0.0f);
    returns_.assign(HW, 0.0f);
    for (auto& d : returnDepth_) d.assign(HW, nan);
    for (auto& v : returnIntensity_) v.assign(HW, 0.0f);
    counts_.name = "spad_counts";
    counts_.kind = SensorOutput::Kind::Array;
    counts_.shape = {shape.height, shape.width, axis_.bins};
    counts_.axes = {"y", "x", "t"};
    counts_.time = axis_;
    counts_.unit = "counts";
    counts_.description = "SPAD detections per TDC bin over " + std::to_string(p.cycles) +
                          " laser cycles (" +
                          (p.mode == SpadMode::Synchronous ? "synchronous" : "free-running") + ")";
    if (options.arrays) {
      writer_ = options.arrays->open(counts_.name, counts_.shape);
      counts_.streamed = true;
    } else {
      counts_.data.resize(HW * axis_.bins);
    }
  }

  void consume(const PixelSpan& span) override {
    TOFSIM_CHECK(span.firstPixel == next_ && next_ + span.pixelCount <= shape_.pixelCount());
    if (exact_) {
      consumeExact(span);
      next_ += span.pixelCount;
      return;
    }
    if (crosstalk_) {
      consumeWithCrosstalk(span);
      next_ += span.pixelCount;
      return;
    }
    const auto K = static_cast<std::size_t>(axis_.bins);
    float* counts = countsOf(span.firstPixel, span.pixelCount);
    detail::parallelPixels(span.pixelCount, options_.threads, [&](std::size_t b, std::size_t e) {
      Scratch scratch;
      for (std::size_t i = b; i < e; ++i) {
        pixel(span.volume + i * shape_.pixelFloats(), span.firstPixel + i, counts + i * K, scratch);
      }
    });
    emit(span.firstPixel, span.pixelCount, counts);
    next_ += span.pixelCount;
  }

  std::vector<SensorOutput> finish(const Image*) override {
    TOFSIM_CHECK(next_ == shape_.pixelCount());
    TOFSIM_CHECK(!crosstalk_ || received_ == next_);
    if (writer_) writer_->close();
    const int32_t H = shape_.height, W = shape_.width;
    std::vector<SensorOutput> outputs;
    outputs.push_back(std::move(counts_));
    const SensorOutput::PointCloud totals{"spad_intensity", "spad_confidence"};
    outputs.push_back(depthImage("spad_depth_peak", std::move(depthPeak_),
                                 "SPAD depth from the histogram peak (c t / 2)", totals));
    outputs.push_back(depthImage("spad_depth_coates", std::move(depthCoates_),
                                 "SPAD depth from the peak of the Coates-corrected histogram",
                                 totals));
    outputs.push_back(depthImage("spad_depth_matched", std::move(depthMatched_),
                                 "SPAD depth by the log-matched filter with the instrument "
                                 "response",
                                 totals));
    outputs.push_back(image("spad_intensity", H, W, std::move(intensity_), "counts",
                            "SPAD total counts per pixel"));
    outputs.push_back(image("spad_confidence", H, W, std::move(confidence_), "-",
                            "SPAD detection confidence (background alone gives a smaller "
                            "matched-filter maximum with this probability)"));
    for (std::size_t i = 1; i < 6; ++i) {
      SensorOutput png = outputs[i];
      png.kind = SensorOutput::Kind::ColorMappedImage;
      png.colormap = p_.colormap;
      png.point_cloud.reset();
      outputs.push_back(std::move(png));
    }
    static constexpr const char* kReturnNames[3] = {"first", "strongest", "last"};
    for (std::size_t r = 0; r < 3; ++r) {
      const std::string which = kReturnNames[r];
      outputs.push_back(depthImage("spad_depth_" + which, std::move(returnDepth_[r]),
                                   "SPAD depth of the " + which + " return (NaN: none)",
                                   {"spad_intensity_" + which, "spad_confidence"}));
      outputs.push_back(image("spad_intensity_" + which, H, W, std::move(returnIntensity_[r]),
                              "counts", "SPAD signal counts of the " + which + " return"));
    }
    outputs.push_back(image("spad_returns", H, W, std::move(returns_), "-",
                            "SPAD returns above return_threshold per pixel"));
    outputs.push_back(histogramPlot(plotted_, histograms_, axis_));
    frames_.finish(outputs);
    if (spadHasPixelMaps(p_)) {
      const std::vector<std::pair<std::string, double>> counts = {
          {"hot_pixels", static_cast<double>(maps_.hot)},
          {"dead_pixels", static_cast<double>(maps_.dead)}};
      outputs.push_back(image("spad_pde_map", H, W, {maps_.pde.begin(), maps_.pde.end()}, "-",
                              "SPAD photon detection efficiency per pixel (fixed pattern)"));
      outputs.back().attributes = counts;
      outputs.push_back(image("spad_dcr_map", H, W,
                              {maps_.dcr_per_s.begin(), maps_.dcr_per_s.end()}, "counts / s",
                              "SPAD dark count rate per pixel (fixed pattern; hot pixels at "
                              "hot_pixel_rate, dead pixels 0)"));
      outputs.back().attributes = counts;
    }
    if (p_.gate_skew_sigma_s > 0.0) {
      outputs.push_back(image("spad_gate_skew_map", H, W,
                              {maps_.gate_skew_s.begin(), maps_.gate_skew_s.end()}, "s",
                              "SPAD gate skew per pixel: the whole gate moved by this time "
                              "(fixed pattern)"));
    }
    return outputs;
  }

 private:
  struct Scratch {
    std::vector<double> signal, resampled, flux, fastFlux, ungated, h, lossless, lambda;
    detail::FirstPhotonScratch firstPhoton;
    SpadEstimator::Scratch estimates;
  };

  SensorOutput depthImage(const std::string& name, std::vector<float> data,
                          const std::string& description, SensorOutput::PointCloud cloud) const {
    SensorOutput o = image(name, shape_.height, shape_.width, std::move(data), "m", description);
    o.point_cloud = std::move(cloud);
    return o;
  }

  // Where the fast draws are not exact: the first-photon law needs one stop,
  // no afterpulse and a detector live again at the next pulse; the
  // free-running binomials (exact marginals) no afterpulse. `flux` is the
  // one the fast draws would use (with `engine: fast`, afterpulses in it).
  // `engine: fast` takes afterpulses to first order when free-running only:
  // a synchronous avalanche's releases follow the stop it made, and extra flux
  // on the first-photon law cannot know that (SpadFastAfterpulseTest).
  bool firstOrderAfterpulses() const {
    return p_.engine == SpadEngine::Fast && p_.mode == SpadMode::FreeRunning;
  }

  bool needsEngine(const std::vector<double>& flux) const {
    if (p_.engine == SpadEngine::Exact) return true;
    if (laws_.afterpulses.on() && !firstOrderAfterpulses()) return true;
    return p_.mode == SpadMode::Synchronous &&
           (p_.tdc_stops != 1 || !detail::deadTimeEndsInItsCycle(flux, deadBins_));
  }

  // Where the counts of pixels first .. first + n - 1 go before emit().
  float* countsOf(std::size_t first, std::size_t n) {
    frames_.beginSpan(first, n);
    const auto K = static_cast<std::size_t>(axis_.bins);
    if (!writer_) return counts_.data.data() + first * K;
    chunk_.resize(n * K);
    return chunk_.data();
  }

  // The plotted histograms among pixels first .. first + n - 1, and the
  // counts to the writer.
  void emit(std::size_t first, std::size_t n, const float* counts) {
    const auto K = static_cast<std::size_t>(axis_.bins);
    for (std::size_t k = 0; k < plotted_.size(); ++k) {
      const std::size_t px =
          static_cast<std::size_t>(plotted_[k][1]) * shape_.width + plotted_[k][0];
      if (px < first || px >= first + n) continue;
      const float* h = counts + (px - first) * K;
      histograms_[k].assign(h, h + K);
    }
    if (writer_) writer_->append(chunk_.data(), n * K);
    frames_.endSpan();
  }

  // Crosstalk (SpadCrosstalk.h): each batch of the span's pixels is sent
  // (own flux, then the profile the neighbours receive), then every pixel
  // whose neighbours have all been sent is drawn, its neighbours' crosstalk
  // added to its flux; the last span draws the rest.
  void consumeWithCrosstalk(const PixelSpan& span) {
    const auto K = static_cast<std::size_t>(axis_.bins);
    for (std::size_t done = 0; done < span.pixelCount;) {
      const std::size_t first = span.firstPixel + done;
      const std::size_t n = std::min(crosstalk_->batch(), span.pixelCount - done);
      detail::parallelPixels(n, options_.threads, [&](std::size_t b, std::size_t e) {
        Scratch scratch;
        for (std::size_t i = b; i < e; ++i) {
          pixelFlux(span.volume + (done + i) * shape_.pixelFloats(), first + i,
                    crosstalk_->flux(first + i), scratch);
          crosstalk_->send(first + i);
        }
      });
      done += n;
      const std::size_t end = crosstalk_->receivable(first + n);
      const std::size_t from = received_, count = end - from;
      if (count == 0) continue;
      float* counts = countsOf(from, count);
      detail::parallelPixels(count, options_.threads, [&](std::size_t b, std::size_t e) {
        Scratch scratch;
        for (std::size_t i = b; i < e; ++i) {
          crosstalk_->receive(from + i, scratch.flux);
          drawPixel(from + i, counts + i * K, scratch);
        }
      });
      emit(from, count, counts);
      received_ = end;
    }
  }

  // Exact crosstalk (SpadExactCrosstalk.h): every pixel's flux is held; with
  // the last one the array is drawn at once (one coupled region, one
  // thread), then each pixel's estimates in blocks as usual.
  void consumeExact(const PixelSpan& span) {
    detail::parallelPixels(span.pixelCount, options_.threads, [&](std::size_t b, std::size_t e) {
      Scratch scratch;
      for (std::size_t i = b; i < e; ++i) {
        const std::size_t px = span.firstPixel + i;
        pixelFlux(span.volume + i * shape_.pixelFloats(), px, exact_->flux(px), scratch);
        exact_->acceptance(px, pixelOf(px));
      }
    });
    if (span.firstPixel + span.pixelCount < shape_.pixelCount()) return;
    exact_->run(options_.seed, kSpadStreamTag);
    const auto K = static_cast<std::size_t>(axis_.bins);
    const std::size_t chunk = 4096;
    for (std::size_t from = 0; from < shape_.pixelCount(); from += chunk) {
      const std::size_t count = std::min(chunk, shape_.pixelCount() - from);
      float* counts = countsOf(from, count);
      detail::parallelPixels(count, options_.threads, [&](std::size_t b, std::size_t e) {
        Scratch scratch;
        for (std::size_t i = b; i < e; ++i) drawPixel(from + i, counts + i * K, scratch);
      });
      emit(from, count, counts);
    }
  }

  void pixel(const float* values, std::size_t px, float* out, Scratch& s) const {
    pixelFlux(values, px, s.flux, s);
    drawPixel(px, out, s);
  }

  void pixelFlux(const float* values, std::size_t px, std::vector<double>& flux, Scratch& s) const {
    pixelSignal(values, shape_.axis.bins, shape_.channels, p_.common, s.signal);
    const SpadPixel pixel = pixelOf(px);
    fluxFromSignal(s.signal, shape_.axis, p_, pixel, bins_, kernel_, s.resampled, flux);
    // The gated frames sweep their own gates over the ungated flux (no
    // crosstalk with them: checkParams), drawn with the pixel in drawPixel.
    if (frames_.active()) s.ungated = flux;
    gateFlux(p_, gate_, pixel, bins_, flux);
  }

  SpadPixel pixelOf(std::size_t px) const {
    return {maps_.pde[px], maps_.dcr_per_s[px], maps_.kind[px], maps_.gate_skew_s[px]};
  }

  // The pixel's histogram from its flux s.flux, and its estimates; its gated
  // frames from s.ungated.
  void drawPixel(std::size_t px, float* out, Scratch& s) const {
    const int32_t K = axis_.bins;
    frames_.pixel(px, s.ungated, maps_.gate_skew_s[px], s.lambda);
    Rng rng(options_.seed, pixelStream(kSpadStreamTag, px));
    const auto N = static_cast<uint64_t>(p_.cycles);
    const bool firstOrder = firstOrderAfterpulses() && laws_.afterpulses.on();
    const std::vector<double>& fast =
        firstOrder
            ? (s.fastFlux = detail::firstOrderAfterpulseFlux(s.flux, deadBins_, laws_.afterpulses))
            : s.flux;
    if (exact_) {
      s.h = exact_->histogram(px);  // drawn with its neighbours (consumeExact)
    } else if (needsEngine(fast)) {
      // Multi-stop TDCs, dead time past the cycle's end and afterpulses
      // correlate bins and cycles: the exact event engine draws the pixel.
      s.h.assign(static_cast<std::size_t>(K), 0.0);
      detail::spadEvents(s.flux, N, laws_, rng, s.h);
    } else if (p_.mode == SpadMode::Synchronous) {
      detail::firstPhotonHistogram(fast, N, rng, s.firstPhoton, s.h);
    } else {
      const std::vector<double> m = freeRunningProbabilities(fast, deadBins_);
      s.h.resize(static_cast<std::size_t>(K));
      for (int32_t i = 0; i < K; ++i) s.h[i] = static_cast<double>(rng.binomial(N, m[i]));
    }
    if (p_.counter_bits > 0) {  // the histogram memory saturates
      for (double& c : s.h) c = detail::clipCount(c, p_.counter_bits);
    }
    double total = 0.0;
    for (int32_t i = 0; i < K; ++i) {
      out[i] = static_cast<float>(s.h[i]);
      total += s.h[i];
    }
    intensity_[px] = static_cast<float>(total);
    depthPeak_[px] = static_cast<float>(peakDepth_m(s.h, axis_));
    depthCoates_[px] = static_cast<float>(coatesPeakDepth_m(s.h, p_.cycles, axis_));
    // The estimators read the detections without pile-up: N times Coates'
    // flux in synchronous mode, the counts when free-running.
    if (p_.mode == SpadMode::Synchronous) {
      s.lossless = coatesEstimate(s.h, p_.cycles);
      for (double& v : s.lossless) v *= static_cast<double>(p_.cycles);
    } else {
      s.lossless = s.h;
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
  }

  const SpadParams p_;
  const VolumeShape shape_;
  const StreamOptions options_;
  const TimeAxis axis_;
  const detail::TdcBins bins_;
  const detail::SpadGate gate_;
  const BinKernel kernel_;
  const int32_t deadBins_;
  const detail::DetectorLaws laws_;
  const std::vector<std::array<int32_t, 2>> plotted_;
  std::vector<std::vector<float>> histograms_;
  const SpadPixelMaps maps_;
  detail::SpadGatedFrames frames_;
  const SpadEstimator estimator_;
  SensorOutput counts_;
  std::unique_ptr<ArrayWriter> writer_;
  std::vector<float> chunk_;
  std::unique_ptr<detail::SpadCrosstalk> crosstalk_;   ///< null: no crosstalk
  std::unique_ptr<detail::SpadExactCrosstalk> exact_;  ///< null: none, or first order
  std::size_t received_ = 0;                           ///< pixels drawn, with crosstalk
  // Written by pixel() from several threads, each pixel by one only.
  mutable std::vector<float> depthPeak_, depthCoates_, intensity_, depthMatched_, confidence_,
      returns_;
  mutable std::array<std::vector<float>, 3> returnDepth_,
      returnIntensity_;  // first, strongest, last
  std::size_t next_ = 0;
};

}  // namespace

std::unique_ptr<SensorStream> openSpad(const SpadParams& params, const VolumeShape& shape,
                                       const StreamOptions& options) {
  return std::make_unique<SpadStream>(params, shape, options);
}

std::vector<SensorOutput> runSpad(const TransientVolume& volume, const SpadParams& p,
                                  uint64_t seed) {
  StreamOptions options;
  options.seed = seed;
  const std::unique_ptr<SensorStream> stream = openSpad(p, shapeOf(volume), options);
  stream->consume(wholeVolume(volume));
  return stream->finish(nullptr);
}

}  // namespace tofsim::sensors
