#include "tofsim/sensors/CwTof.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "CwTofByOrder.h"
#include "CwTofCorrelator.h"
#include "CwTofDeviceImages.h"
#include "CwTofDeviceStage.h"
#include "CwTofMotionError.h"
#include "CwTofOutputs.h"
#include "CwTofPsfError.h"
#include "tofsim/optics/PsfConvolution.h"
#include "tofsim/sensors/Random.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr uint32_t kCwTofStreamTag = 0x4357;  // "CW"

void checkParams(const CwTofParams& p, const VolumeShape& shape) {
  TOFSIM_CHECK(!p.frequencies_Hz.empty() && p.phase_steps >= 3);
  for (double f : p.frequencies_Hz) TOFSIM_CHECK(f > 0.0);
  TOFSIM_CHECK(p.ambient_e >= 0.0 && p.read_noise_e >= 0.0 && p.max_depth_m >= 0.0);
  TOFSIM_CHECK(p.modulation_contrast > 0.0 && p.modulation_contrast <= 1.0);
  checkChannelSelection(p.common.channel, shape.channels);
  for (std::size_t i = 0; i < p.frequencies_Hz.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (frequencyLabel(p.frequencies_Hz[i]) == frequencyLabel(p.frequencies_Hz[j])) {
        throw InputError("cwtof frequencies " + std::to_string(j) + " and " + std::to_string(i) +
                         " share the output name " + frequencyLabel(p.frequencies_Hz[i]));
      }
    }
  }
}

void checkGroundTruth(const Image* gt, const VolumeShape& shape) {
  if (gt && (gt->width != shape.width || gt->height != shape.height || gt->channels < 1)) {
    throw InputError("cwtof ground-truth depth is " + std::to_string(gt->width) + "x" +
                     std::to_string(gt->height) + ", the volume " + std::to_string(shape.width) +
                     "x" + std::to_string(shape.height));
  }
}

/// The model fed pixel by pixel into planes of H x W. The error against the
/// ground truth needs a depth known only after the render, so the noise-free
/// depths it compares are kept per pixel and compared in finish().
class CwTofStream final : public SensorStream {
 public:
  CwTofStream(const CwTofParams& p, const VolumeShape& shape, const StreamOptions& options)
      : p_(p),
        shape_(shape),
        seed_(options.seed),
        withDirect_(options.directOnly),
        psfOnRaws_(options.psfOnRaws),
        correlator_(p_, shape_.axis),
        device_(p_, shape.height, shape.width),
        deviceImages_(p_, shape.pixelCount()),
        H_(shape.height),
        W_(shape.width),
        F_(static_cast<int32_t>(p.frequencies_Hz.size())),
        HW_(shape.pixelCount()),
        exposureSamples_(p.integration_time_s > 0.0 ? options.exposureSamples : 1),
        rawWeights_(static_cast<std::size_t>(F_) * p.phase_steps, 1.0) {
    checkParams(p, shape);
    TOFSIM_CHECK(exposureSamples_ >= 1);
    const double k = shape.axis.depthPerSecond_m_per_s();
    unwrapRange_ = unwrapRange_m(p, k);
    depthRange_ = depthRange_m(p, k);
    wiggling_ = wigglingError_m(p, k);
    raw_.resize(static_cast<std::size_t>(F_) * p.phase_steps * HW_);
    clean_.resize(correlator_.rows * HW_);
    phase_.resize(F_ * HW_);
    amplitude_.resize(F_ * HW_);
    wrappedDepth_.resize(F_ * HW_);
    depth_.resize(HW_);
    cleanDepth_.resize(HW_);
    cleanWrapped_.resize(F_ * HW_);
    if (withDirect_) mpiDirect_.assign(HW_, std::numeric_limits<float>::quiet_NaN());
    if (p.multipath_by_order) {
      if (!options.bounces) {
        throw InputError(
            "multipath_by_order needs the render's light by bounce order (its direct component "
            "and bounce1 .. bounceN), which this run does not give the sensor");
      }
      byOrder_.emplace(correlator_, p_.common, shape_, *options.bounces, unwrapRange_);
    }
    if (psfOnRaws_) checkPsfOnRaws();
    if (psfOnRaws_ || options.beforePsf) psfError_.emplace(HW_);
  }

  void consume(const PixelSpan& span) override {
    TOFSIM_CHECK(span.firstPixel == next_ && next_ + span.pixelCount <= HW_);
    TOFSIM_CHECK(!withDirect_ || span.directOnly != nullptr);
    for (std::size_t i = 0; i < span.pixelCount; ++i) {
      const std::size_t offset = i * shape_.pixelFloats();
      pixel(span.volume + offset, withDirect_ ? span.directOnly + offset : nullptr,
            span.firstPixel + i);
      if (byOrder_ && reference_) byOrder_->pixel(span, offset, span.firstPixel + i);
    }
    next_ += span.pixelCount;
  }

  /// Raw j = (f, n) of the capture order's position i integrates over
  /// [s_j, s_j + integration_time), s_j = i (integration_time + readout_gap):
  /// sample m of it at s_j + (m + 1/2) integration_time / S. Index j S + m.
  std::vector<double> sampleTimes_s() const override {
    const std::vector<double> starts = cwtofRawStartTimes_s(p_);
    const int32_t S = exposureSamples_;
    std::vector<double> times;
    times.reserve(starts.size() * S);
    for (double start : starts) appendExposureSamples(start, p_.integration_time_s, S, times);
    return times;
  }

  /// The raws' charges are sums over the passes, each weighted by the share
  /// of the raw's samples the pass stands for.
  void beginPass(const SensorPass& pass) override {
    TOFSIM_CHECK(passes_ == 0 || next_ == HW_);
    next_ = 0;
    if (passes_++ == 0) {
      referenceSeen_ = false;
      const std::vector<double> times = sampleTimes_s();
      if (std::any_of(times.begin(), times.end(), [](double t) { return t != 0.0; })) {
        motion_.emplace(HW_);  // raws at different times: cwtof_motion_error
      }
    }
    reference_ = pass.reference;
    std::fill(rawWeights_.begin(), rawWeights_.end(), 0.0);
    for (std::size_t i : pass.samples) {
      TOFSIM_CHECK(i < rawWeights_.size() * exposureSamples_);
      rawWeights_[i / exposureSamples_] += 1.0 / exposureSamples_;
    }
    if (reference_) referenceSeen_ = true;
  }

  /// The light before the lens's PSF: each pixel's noise-free depth, as
  /// multipath() finds the depth of the light with it.
  void consumeBeforePsf(const PixelSpan& span) override {
    if (!psfError_) return;
    TOFSIM_CHECK(span.firstPixel == nextSharp_ && nextSharp_ + span.pixelCount <= HW_);
    for (std::size_t i = 0; i < span.pixelCount; ++i) {
      pixelSignal(span.volume + i * shape_.pixelFloats(), shape_.axis.bins, shape_.channels,
                  p_.common, signal_);
      correlator_.raw(signal_, p_.ambient_e, ideal_);
      const double depth = correlator_.depth(ideal_, phases_, amps_, unwrapRange_);
      psfError_->sharp(span.firstPixel + i, depth, amps_[0] > 0.0);
    }
    nextSharp_ += span.pixelCount;
  }

  std::vector<SensorOutput> finish(const Image* groundTruthDepth_m) override;

 private:
  void addByOrder(std::vector<SensorOutput>& outs, const Image* gt) const;

  /// consume(): the pixel's noise-free charges (every tap, its fixed-pattern
  /// delay inside the correlation) kept for finish(), and its multipath errors.
  /// With the PSF on the raws the charges kept are the signal's alone (the
  /// ambient is added at the pixel, after the lens) and the depths found
  /// here are the sharp light's.
  void pixel(const float* values, const float* direct, std::size_t px) {
    pixelSignal(values, shape_.axis.bins, shape_.channels, p_.common, signal_);
    const double delay = device_.delay_s(px);
    correlator_.taps(signal_, psfOnRaws_ ? 0.0 : p_.ambient_e, delay, ideal_);
    // A static scene is one pass of weight 1: 0 + 1 x is x, the bytes of a
    // single capture.
    const std::size_t FN = rawWeights_.size();
    for (std::size_t j = 0; j < ideal_.size(); ++j) {
      const double w = rawWeights_[j % FN];
      if (w != 0.0) clean_[j * HW_ + px] += w * ideal_[j];
    }
    // What is compared with the ground truth is the light at the frame's time.
    if (!reference_) return;
    // The still light through the device (its delay; the PSF comes later).
    if (motion_ && !psfOnRaws_) {
      const double still = correlator_.depth(ideal_, phases_, amps_, unwrapRange_);
      motion_->still(px, still, amps_[0] > 0.0);
    }
    // The multipath errors are the scene's: without the device's delay.
    if (delay != 0.0 || psfOnRaws_) correlator_.raw(signal_, p_.ambient_e, ideal_);
    const bool lit = multipath(direct, px);
    if (!psfError_) return;
    if (psfOnRaws_) {
      psfError_->sharp(px, cleanDepth_[px], lit);
    } else {
      psfError_->blurred(px, lit);
    }
  }

  /// The PSF on the raws is the PSF on every bin only where each pixel's
  /// charges are a linear map of its light common to all pixels; the
  /// pipeline puts it on the transient otherwise (PsfPath.h).
  void checkPsfOnRaws() const {
    if (!device_.pattern().delay_s.empty()) {
      throw InputError(
          "cwtof: the lens's PSF on the raw images is exact only without a fixed-pattern delay "
          "(delay_sigma, delay_map); apply it to the transient");
    }
    if (withDirect_ || byOrder_) {
      throw InputError(
          "cwtof: the lens's PSF on the raw images blurs the total light only; the direct-only "
          "and by-order references need it on the transient");
    }
  }

  /// The lens's PSF on the noise-free signal charges (each of the rows
  /// planes of H x W on its own, the image zero outside, as on each bin of a
  /// transient), the ambient added after it (it is defined at the pixel),
  /// and the noise-free depths found again from the blurred charges.
  void lensOnRaws() {
    optics::applyPsf(*psfOnRaws_, clean_.data(), static_cast<int32_t>(correlator_.rows), H_, W_);
    const double ambient = 0.5 * p_.ambient_e;  // Correlator::correlate's share per raw
    for (double& q : clean_) q += ambient;
    const std::size_t FN = static_cast<std::size_t>(F_) * p_.phase_steps;
    ideal_.resize(FN);
    for (std::size_t px = 0; px < HW_; ++px) {
      for (std::size_t j = 0; j < FN; ++j) ideal_[j] = clean_[j * HW_ + px];  // tap A's raws
      const bool lit = multipath(nullptr, px);
      psfError_->blurred(px, lit);
      if (motion_) motion_->still(px, cleanDepth_[px], lit);  // the blurred still light
    }
  }

  /// finish(): the device stage of every pixel, from its kept noise-free
  /// charges, with the noise of its own stream (as it always was).
  void device() {
    // The lens's PSF (StreamOptions::psfOnRaws) acts here, on the noise-free
    // charge planes clean_ (correlator_.rows planes of H x W, e-; plane j =
    // tap j / (F N), frequency and step of j % (F N)), before any noise. Each
    // pixel's fixed-pattern delay would already be inside its charges (it
    // acts in the correlation, consume()), so light blurred onto a pixel here
    // would keep the delay of the pixel it came from: hence no delay pattern
    // with it (checkPsfOnRaws); the PSF on the transient is the exact order.
    if (psfOnRaws_) lensOnRaws();
    for (std::size_t px = 0; px < HW_; ++px) {
      noisy_.resize(correlator_.rows);
      for (std::size_t j = 0; j < noisy_.size(); ++j) noisy_[j] = clean_[j * HW_ + px];
      if (motion_) {  // the raws as taken, before the noise
        const double taken = correlator_.depth(noisy_, phases_, amps_, unwrapRange_);
        motion_->taken(px, taken, amps_[0] > 0.0, depthRange_);
      }
      Rng rng(seed_, pixelStream(kCwTofStreamTag, px));
      const bool saturated = device_.pixel(noisy_, px, rng, deviceImages_.taps());
      for (std::size_t j = 0; j < noisy_.size(); ++j) raw_[j * HW_ + px] = float(noisy_[j]);
      depth_[px] = static_cast<float>(correlator_.depth(noisy_, phases_, amps_, unwrapRange_));
      for (int32_t f = 0; f < F_; ++f) {
        phase_[f * HW_ + px] = static_cast<float>(phases_[f]);
        amplitude_[f * HW_ + px] = static_cast<float>(amps_[f]);
        wrappedDepth_[f * HW_ + px] = static_cast<float>(correlator_.wrappedDepth(f, phases_[f]));
      }
      deviceImages_.pixel(px, noisy_, saturated, correlator_, unwrapRange_);
    }
    std::vector<double>().swap(clean_);
  }

  /// The noise-free depths the multipath errors compare, and the error
  /// against the direct-only depth, folded into the depth's range so that a
  /// phase wrap is not counted. True when the light ideal_ has an amplitude.
  bool multipath(const float* direct, std::size_t px) {
    const double clean = correlator_.depth(ideal_, phases_, amps_, unwrapRange_);
    const bool lit = amps_[0] > 0.0;
    cleanDepth_[px] = clean;
    for (int32_t f = 0; f < F_; ++f) {
      cleanWrapped_[f * HW_ + px] = correlator_.wrappedDepth(f, phases_[f]);
    }
    if (direct) {
      pixelSignal(direct, shape_.axis.bins, shape_.channels, p_.common, signal_);
      correlator_.raw(signal_, 0.0, ideal_);
      const double directDepth = correlator_.depth(ideal_, phases_, amps_, unwrapRange_);
      if (amps_[0] > 0.0) {
        mpiDirect_[px] = static_cast<float>(wrapSigned(clean - directDepth, depthRange_));
      }
    }
    return lit;
  }

  /// The errors of the kept noise-free depths against the ground truth.
  void groundTruthErrors(const Image& gt) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const double k = shape_.axis.depthPerSecond_m_per_s();
    mpiGt_.assign(HW_, nan);
    mpiGtPerFrequency_.assign(F_ * HW_, nan);
    wigglingMap_.assign(HW_, nan);
    std::vector<double> raw, phases, amplitudes;
    for (int32_t y = 0; y < H_; ++y) {
      for (int32_t x = 0; x < W_; ++x) {
        const std::size_t px = static_cast<std::size_t>(y) * W_ + x;
        const float truth = gt.at(y, x, 0);
        if (!(std::isfinite(truth) && truth > 0.0f)) continue;
        mpiGt_[px] = static_cast<float>(wrapSigned(cleanDepth_[px] - truth, depthRange_));
        const double single =
            correlator_.singleReturnDepth(truth / k, raw, phases, amplitudes, unwrapRange_);
        wigglingMap_[px] = static_cast<float>(wrapSigned(single - truth, depthRange_));
        for (int32_t f = 0; f < F_; ++f) {
          const double e = cleanWrapped_[f * HW_ + px] - truth;
          mpiGtPerFrequency_[f * HW_ + px] =
              static_cast<float>(wrapSigned(e, k / p_.frequencies_Hz[f]));
        }
      }
    }
  }

  std::vector<float> plane(const std::vector<float>& planes, int32_t f) const {
    return {planes.begin() + f * HW_, planes.begin() + (f + 1) * HW_};
  }

  const CwTofParams p_;
  const VolumeShape shape_;
  const uint64_t seed_;
  const bool withDirect_;
  const optics::PsfKernel* psfOnRaws_;  // not owned: the config's camera.psf
  Correlator correlator_;
  CwTofDeviceStage device_;
  CwTofDeviceImages deviceImages_;
  int32_t H_, W_, F_;
  std::size_t HW_;
  std::size_t next_ = 0, nextSharp_ = 0;
  double unwrapRange_ = 0.0, depthRange_ = 0.0;
  // (F, N, H, W) raw; (F, H, W) per frequency; (H, W) combined.
  std::vector<float> raw_, phase_, amplitude_, wrappedDepth_, mpiGtPerFrequency_;
  std::vector<float> depth_, mpiGt_, mpiDirect_;
  std::vector<float> wigglingMap_;  // (H, W): the wiggling at each pixel's true depth
  std::vector<double> clean_;       // (taps F N, H, W): noise-free charges, e-
  std::vector<double> cleanDepth_, cleanWrapped_;               // (H, W) and (F, H, W), noise-free
  std::vector<double> wiggling_;                                // (F, S), m
  std::vector<double> signal_, ideal_, noisy_, phases_, amps_;  // per-pixel scratch
  std::optional<OrderDepths> byOrder_;                          // multipath_by_order
  std::optional<CwTofPsfError> psfError_;   // with the lens's PSF: cwtof_psf_error
  std::optional<CwTofMotionError> motion_;  // raws at different times: cwtof_motion_error
  // A moving scene (beginPass): each raw's weight in the current pass, and
  // whether it is the frame's own time.
  const int32_t exposureSamples_;
  std::vector<double> rawWeights_;  // (F N)
  bool reference_ = true, referenceSeen_ = true;
  std::size_t passes_ = 0;
};

std::vector<SensorOutput> CwTofStream::finish(const Image* gt) {
  TOFSIM_CHECK(next_ == HW_);
  TOFSIM_CHECK(referenceSeen_);
  checkGroundTruth(gt, shape_);
  device();
  if (gt) groundTruthErrors(*gt);
  const int32_t H = H_, W = W_, N = p_.phase_steps;
  const std::string& cmap = p_.colormap;
  std::vector<SensorOutput> outs;
  outs.push_back(makeOutput("cwtof_raw", SensorOutput::Kind::Array, {F_, N, H, W},
                            {"frequency", "phase_step", "y", "x"}, std::move(raw_),
                            "photo-electrons",
                            "CW-ToF raw correlation images (frequency, phase step, y, x)"));
  outs.push_back(makeOutput("cwtof_phase", SensorOutput::Kind::Array, {F_, H, W},
                            {"frequency", "y", "x"}, phase_, "rad",
                            "CW-ToF wrapped phase per frequency, [0, 2 pi)"));
  // "unwrapped" only where unwrapping happened: with one frequency the depth
  // is that frequency's wrapped depth.
  const std::string depthTitle = F_ >= 2
                                     ? "CW-ToF depth (unwrapped, " + std::to_string(F_) +
                                           " frequencies, range " + metres(depthRange_) + ")"
                                     : "CW-ToF depth at " + frequencyLabel(p_.frequencies_Hz[0]) +
                                           " (wrapped, range " + metres(depthRange_) + ")";
  const ImageMeaning combined{{{"range_m", depthRange_}}, false};
  const ImageMeaning combinedError{{{"range_m", depthRange_}}, true};
  addImage(outs, "cwtof_depth", H, W, std::move(depth_), "m", depthTitle, cmap, combined);
  outs[outs.size() - 2].point_cloud = SensorOutput::PointCloud{"cwtof_amplitude", ""};
  addImage(outs, "cwtof_amplitude", H, W, plane(amplitude_, 0), "photo-electrons",
           "CW-ToF amplitude at the first frequency", cmap,
           {{{"frequency_Hz", p_.frequencies_Hz[0]}}});
  const double k = shape_.axis.depthPerSecond_m_per_s();
  for (int32_t f = 0; f < F_; ++f) {
    const std::string label = frequencyLabel(p_.frequencies_Hz[f]);
    const std::string at = " at " + label;
    const double fHz = p_.frequencies_Hz[f], range = k / fHz;
    const ImageMeaning wrapped{{{"frequency_Hz", fHz}, {"range_m", range}}, false};
    addImage(outs, "cwtof_phase_" + label, H, W, plane(phase_, f), "rad",
             "CW-ToF wrapped phase" + at + ", [0, 2 pi)", cmap, wrapped);
    addImage(outs, "cwtof_amplitude_" + label, H, W, plane(amplitude_, f), "photo-electrons",
             "CW-ToF amplitude" + at, cmap, wrapped);
    addImage(outs, "cwtof_depth_" + label, H, W, plane(wrappedDepth_, f), "m",
             "CW-ToF wrapped depth" + at + ", range " + metres(range), cmap, wrapped);
    outs[outs.size() - 2].point_cloud = SensorOutput::PointCloud{"cwtof_amplitude_" + label, ""};
    if (gt) {
      addImage(outs, "cwtof_multipath_error_" + label, H, W, plane(mpiGtPerFrequency_, f), "m",
               "CW-ToF depth error" + at + " alone (noise-free wrapped depth - ground truth)",
               cmap,
               {wrapped.attributes, true});
    }
  }
  if (gt) {
    addImage(outs, "cwtof_mpi_error", H, W, std::move(mpiGt_), "m",
             "CW-ToF depth error (noise-free depth, frequencies combined - ground truth)",
             cmap, combinedError);
    addImage(outs, "cwtof_wiggling_error_map", H, W, std::move(wigglingMap_), "m",
             "CW-ToF wiggling error at each pixel's true depth: a noise-free single return there "
             "(multipath excluded)",
             cmap, combinedError);
  }
  if (withDirect_) {
    addImage(outs, "cwtof_mpi_error_direct", H, W, std::move(mpiDirect_), "m",
             "CW-ToF multipath error alone (noise-free depth - that of the direct light)", cmap,
             combinedError);
  }
  if (psfError_) {
    addImage(outs, "cwtof_psf_error", H, W, psfError_->errors(cleanDepth_, depthRange_), "m",
             "CW-ToF depth error of the lens's stray light: noise-free depth with camera.psf - "
             "without it",
             cmap, combinedError);
  }
  if (motion_) {
    addImage(outs, "cwtof_motion_error", H, W, motion_->errors(), "m",
             "CW-ToF motion error: noise-free depth of the raws as taken, each at its own time, "
             "- that of the light at the frame's time",
             cmap, combinedError);
  }
  addByOrder(outs, gt);
  outs.push_back(wigglingErrorOutput(wiggling_, p_.frequencies_Hz));
  deviceImages_.add(outs, H, W, depthRange_, device_.pattern());
  return outs;
}

// (N + 1, H, W) and a picture of each order, in the combined depth's range.
void CwTofStream::addByOrder(std::vector<SensorOutput>& outs, const Image* gt) const {
  if (!byOrder_) return;
  if (!gt) {
    throw InputError(
        "multipath_by_order needs the ground-truth depth (the render's output.depth, or "
        "depth.exr beside a saved volume)");
  }
  const int32_t orders = byOrder_->orders();
  std::vector<float> errors = byOrder_->errors(*gt, depthRange_);
  const ImageMeaning meaning{{{"range_m", depthRange_}}, true};
  for (int32_t k = 0; k < orders; ++k) {
    const std::string light =
        k == 0 ? "the direct light" : "direct + bounces 1.." + std::to_string(k);
    const auto first = errors.begin() + static_cast<std::ptrdiff_t>(k * HW_);
    SensorOutput picture = makeOutput(
        "cwtof_multipath_error_order" + std::to_string(k), SensorOutput::Kind::ColorMappedImage,
        {H_, W_}, {"y", "x"}, {first, first + static_cast<std::ptrdiff_t>(HW_)}, "m",
        "CW-ToF depth error of " + light + " against the ground truth (noise-free)");
    picture.attributes = {{"range_m", depthRange_}, {"order", k}};
    picture.signed_values = true;
    picture.colormap = p_.colormap;
    outs.push_back(std::move(picture));
  }
  SensorOutput array =
      makeOutput("cwtof_multipath_error_by_order", SensorOutput::Kind::Array, {orders, H_, W_},
                 {"order", "y", "x"}, std::move(errors), "m",
                 "CW-ToF depth error of direct + bounces 1..k against the ground truth, k = 0.." +
                     std::to_string(orders - 1) + " (noise-free; order k is the first axis)");
  array.attributes = meaning.attributes;
  array.signed_values = true;
  outs.push_back(std::move(array));
}
}  // namespace

std::unique_ptr<SensorStream> openCwTof(const CwTofParams& params, const VolumeShape& shape,
                                        const StreamOptions& options) {
  return std::make_unique<CwTofStream>(params, shape, options);
}

std::vector<SensorOutput> runCwTof(const TransientVolume& volume, const CwTofParams& p,
                                   uint64_t seed, const CwTofReferences& refs) {
  const TransientVolume* direct = refs.directOnly;
  const auto sameShape = [&](const TransientVolume& v) {
    return v.width() == volume.width() && v.height() == volume.height() &&
           v.channels() == volume.channels() && v.bins() == volume.bins();
  };
  if (direct && !sameShape(*direct)) {
    throw InputError("cwtof direct-only volume does not match the volume's shape");
  }
  StreamOptions options;
  options.seed = seed;
  options.directOnly = direct != nullptr;
  if (refs.bounces) {
    if (!direct) throw InputError("cwtof bounce volumes need the direct-only volume too");
    for (const TransientVolume* b : *refs.bounces) {
      if (!sameShape(*b)) throw InputError("cwtof bounce volume does not match the volume's shape");
    }
    options.bounces = static_cast<int32_t>(refs.bounces->size());
  }
  const std::unique_ptr<SensorStream> stream = openCwTof(p, shapeOf(volume), options);
  stream->consume(wholeVolume(volume, direct, refs.bounces));
  return stream->finish(refs.groundTruthDepth_m);
}

}  // namespace tofsim::sensors
