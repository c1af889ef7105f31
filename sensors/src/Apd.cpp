#include "tofsim/sensors/Apd.h"

#include <cmath>
#include <limits>

#include "ApdReceiver.h"
#include "ParallelPixels.h"
#include "tofsim/sensors/Random.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr uint32_t kApdStreamTag = 0x4150;  // "AP"

/// The APD fed pixel by pixel: each pixel's samples and echoes are its own
/// (its own random stream), spread over threads in fixed blocks.
class ApdStream final : public SensorStream {
 public:
  ApdStream(const ApdParams& p, const VolumeShape& shape, const StreamOptions& options)
      : p_(p), shape_(shape), options_(options), rx_(apdReceiver(p, shape.axis)) {
    TOFSIM_CHECK(p.gain >= 1.0 && p.max_returns >= 1);
    checkChannelSelection(p.common.channel, shape.channels);
    const std::size_t pixels = shape.pixelCount(), R = static_cast<std::size_t>(p.max_returns);
    if (p.output_waveforms) waveforms_.resize(pixels * static_cast<std::size_t>(rx_.axis.bins));
    range_.assign(pixels * R, std::numeric_limits<float>::quiet_NaN());
    amplitude_.assign(pixels * R, std::numeric_limits<float>::quiet_NaN());
    count_.assign(pixels, 0.0f);
  }

  void consume(const PixelSpan& span) override {
    TOFSIM_CHECK(span.firstPixel == next_ && next_ + span.pixelCount <= shape_.pixelCount());
    detail::parallelPixels(span.pixelCount, options_.threads, [&](std::size_t begin, std::size_t end) {
      std::vector<double> signal, resampled, samples;
      detail::ApdScratch scratch;
      for (std::size_t i = begin; i < end; ++i) {
        pixel(span.firstPixel + i, span.volume + i * shape_.pixelFloats(), signal, resampled,
              scratch, samples);
      }
    });
    next_ += span.pixelCount;
  }

  std::vector<SensorOutput> finish(const Image*) override {
    TOFSIM_CHECK(next_ == shape_.pixelCount());
    const int64_t H = shape_.height, W = shape_.width, R = p_.max_returns;
    std::vector<SensorOutput> out;
    const auto attributes = std::vector<std::pair<std::string, double>>{
        {"threshold_A", rx_.threshold_A},
        {"background_mean_A", rx_.backgroundMean_A},
        {"background_sigma_A", rx_.backgroundSigma_A},
        {"noise_bandwidth_Hz", rx_.noiseBandwidth_Hz},
        {"excess_noise_factor", rx_.excessNoise}};
    if (p_.output_waveforms) {
      out.push_back(array("apd_waveforms", {H, W, rx_.axis.bins}, {"y", "x", "t"},
                          std::move(waveforms_), "A",
                          "digitised APD current at the TIA's input (noisy)"));
      out.back().time = rx_.axis;
      out.back().attributes = attributes;
    }
    out.push_back(array("apd_range", {H, W, R}, {"y", "x", "return"}, range_, "m",
                        "range of each echo above the threshold, time order (NaN: none)"));
    out.back().attributes = attributes;
    out.push_back(array("apd_amplitude", {H, W, R}, {"y", "x", "return"}, amplitude_, "A",
                        "peak current of each echo (NaN: none)"));
    out.push_back(array("apd_returns", {H, W}, {"y", "x"}, count_, "echoes",
                        "echoes above the threshold per pixel (at most max_returns)"));
    std::vector<float> first(static_cast<std::size_t>(H * W));
    for (std::size_t i = 0; i < first.size(); ++i) first[i] = range_[i * R];
    SensorOutput image = array("apd_first_range", {H, W}, {"y", "x"}, std::move(first), "m",
                               "APD first return's range [m]");
    image.kind = SensorOutput::Kind::Image;
    SensorOutput picture = image;
    picture.kind = SensorOutput::Kind::ColorMappedImage;
    picture.colormap = p_.colormap;
    out.push_back(std::move(image));
    out.push_back(std::move(picture));
    return out;
  }

 private:
  static SensorOutput array(std::string name, std::vector<int64_t> shape,
                            std::vector<std::string> axes, std::vector<float> data,
                            std::string unit, std::string description) {
    SensorOutput o;
    o.name = std::move(name);
    o.shape = std::move(shape);
    o.axes = std::move(axes);
    o.data = std::move(data);
    o.unit = std::move(unit);
    o.description = std::move(description);
    return o;
  }

  void pixel(std::size_t px, const float* values, std::vector<double>& signal,
             std::vector<double>& resampled, detail::ApdScratch& scratch,
             std::vector<double>& samples) {
    pixelSignal(values, shape_.axis.bins, shape_.channels, p_.common, signal);
    resampleEnergy(signal, shape_.axis, rx_.axis, resampled);
    Rng rng(options_.seed, pixelStream(kApdStreamTag, px));
    detail::apdSamples(p_, rx_, resampled, rng, scratch, samples);
    if (p_.output_waveforms) {
      float* w = waveforms_.data() + px * static_cast<std::size_t>(rx_.axis.bins);
      for (std::size_t t = 0; t < samples.size(); ++t) w[t] = static_cast<float>(samples[t]);
    }
    apdThresholds(p_, rx_, samples, scratch.threshold);
    const std::vector<detail::ApdEcho> echoes =
        detail::apdEchoes(samples, scratch.threshold, rx_, p_.max_returns);
    const std::size_t base = px * static_cast<std::size_t>(p_.max_returns);
    for (std::size_t e = 0; e < echoes.size(); ++e) {
      range_[base + e] = static_cast<float>(echoes[e].range_m);
      amplitude_[base + e] = static_cast<float>(echoes[e].amplitude_A);
    }
    count_[px] = static_cast<float>(echoes.size());
  }

  const ApdParams p_;
  const VolumeShape shape_;
  const StreamOptions options_;
  const ApdReceiver rx_;
  std::vector<float> waveforms_, range_, amplitude_, count_;
  std::size_t next_ = 0;
};

}  // namespace

std::unique_ptr<SensorStream> openApd(const ApdParams& params, const VolumeShape& shape,
                                      const StreamOptions& options) {
  return std::make_unique<ApdStream>(params, shape, options);
}

std::vector<SensorOutput> runApd(const TransientVolume& volume, const ApdParams& params,
                                 uint64_t seed, int threads) {
  StreamOptions options;
  options.seed = seed;
  options.threads = threads;
  const std::unique_ptr<SensorStream> stream = openApd(params, shapeOf(volume), options);
  stream->consume(wholeVolume(volume));
  return stream->finish(nullptr);
}

}  // namespace tofsim::sensors
