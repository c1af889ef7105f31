#include "tofsim/sensors/Streak.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

#include "tofsim/sensors/Random.h"
#include "tofsim/sensors/TimeKernel.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr uint32_t kStreakStreamTag = 0x5354;  // "ST"
}

std::string streakRowName(int32_t row) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "streak_row%03d", static_cast<int>(row));
  return buf;
}

namespace {

/// The streak camera fed pixel by pixel: each recorded row is gathered as its
/// pixels arrive (its spatial blur needs the whole row) and turned into its
/// streak image once complete; the other rows are never held. Scanning rows
/// in a moving scene (row_time): each pass takes only the rows recorded at
/// its time.
class StreakStream final : public SensorStream {
 public:
  StreakStream(const StreakParams& p, const VolumeShape& shape, const StreamOptions& options)
      : p_(p),
        shape_(shape),
        seed_(options.seed),
        axis_(resolveBins(p.bins, shape.axis)),
        timeKernel_(gaussianKernel(fwhmToSigma(p.time_fwhm_s), axis_.bin_width_s)),
        spaceKernel_(gaussianKernel(fwhmToSigma(p.spatial_fwhm_px), 1.0)) {
    TOFSIM_CHECK(p.time_fwhm_s >= 0.0 && p.spatial_fwhm_px >= 0.0 && p.read_noise_e >= 0.0);
    TOFSIM_CHECK(p.gain_adu_per_e > 0.0 && p.saturation_adu > 0.0);
    checkChannelSelection(p.common.channel, shape.channels);
    rows_ = p.rows;
    if (rows_.empty()) {
      for (int32_t y = 0; y < shape.height; ++y) rows_.push_back(y);
    }
    for (int32_t y : rows_) {
      if (y < 0 || y >= shape.height) {
        throw InputError("streak row " + std::to_string(y) + " is outside the image (height " +
                         std::to_string(shape.height) + ")");
      }
      if (images_.count(y)) continue;  // recorded once even when listed twice
      images_[y];
      rowTimes_.push_back(static_cast<double>(order_.size()) * p.row_time_s);
      order_.push_back(y);
    }
    if (p.row_time_s == 0.0) rowTimes_ = {0.0};
  }

  /// Recorded row i (in `rows` order) at i row_time; no row time: {0}.
  std::vector<double> sampleTimes_s() const override { return rowTimes_; }

  /// The rows scanned at this pass's time (all of them without a row time).
  void beginPass(const SensorPass& pass) override {
    TOFSIM_CHECK(next_ == 0 || next_ == shape_.pixelCount());
    next_ = 0;
    if (p_.row_time_s == 0.0) return;
    inPass_.clear();
    for (std::size_t i : pass.samples) inPass_.insert(order_.at(i));
    scanning_ = true;
  }

  void consume(const PixelSpan& span) override {
    TOFSIM_CHECK(span.firstPixel == next_ && next_ + span.pixelCount <= shape_.pixelCount());
    const int32_t W = shape_.width, T = axis_.bins;
    for (std::size_t i = 0; i < span.pixelCount; ++i) {
      const std::size_t px = span.firstPixel + i;
      const auto y = static_cast<int32_t>(px / W), x = static_cast<int32_t>(px % W);
      if (!images_.count(y) || (scanning_ && !inPass_.count(y))) continue;
      if (x == 0) row_.assign(static_cast<std::size_t>(T) * W, 0.0);
      pixelSignal(span.volume + i * shape_.pixelFloats(), shape_.axis.bins, shape_.channels,
                  p_.common, signal_);
      resampleEnergy(signal_, shape_.axis, axis_, resampled_);
      for (int32_t t = 0; t < T; ++t) row_[static_cast<std::size_t>(t) * W + x] = resampled_[t];
      if (x == W - 1) images_[y] = streakImage(y);
    }
    next_ += span.pixelCount;
  }

  std::vector<SensorOutput> finish(const Image*) override {
    TOFSIM_CHECK(next_ == shape_.pixelCount());
    std::vector<SensorOutput> outputs;
    for (int32_t y : rows_) {
      const SensorOutput& image = images_.at(y);
      TOFSIM_CHECK(!image.data.empty());  // every row's pass came
      SensorOutput png = image;
      png.kind = SensorOutput::Kind::ColorMappedImage;
      png.colormap = p_.colormap;
      outputs.push_back(image);
      outputs.push_back(std::move(png));
    }
    return outputs;
  }

 private:
  // Blurs the gathered row (T, W) in time then x, then adds the noise.
  SensorOutput streakImage(int32_t y) {
    const int32_t W = shape_.width, T = axis_.bins;
    std::vector<double>& a = row_;
    blurred_.assign(a.size(), 0.0);
    for (int32_t x = 0; x < W; ++x) convolveConserving(&a[x], T, W, timeKernel_, &blurred_[x]);
    for (int32_t t = 0; t < T; ++t) {
      const std::size_t row = static_cast<std::size_t>(t) * W;
      convolveConserving(&blurred_[row], W, 1, spaceKernel_, &a[row]);
    }
    SensorOutput image;
    image.name = streakRowName(y);
    image.kind = SensorOutput::Kind::Image;
    image.shape = {T, W};
    image.axes = {"t", "x"};
    image.time = axis_;
    image.attributes = {{"row", y}};
    if (p_.row_time_s > 0.0) {
      const auto i =
          static_cast<std::size_t>(std::find(order_.begin(), order_.end(), y) - order_.begin());
      image.attributes.emplace_back("scan_time_s", rowTimes_[i]);  // after the frame's time
    }
    image.unit = "ADU";
    char axisText[96];  // %g: "5.00346 ns, step 10 ps", not std::to_string's six decimals
    std::snprintf(axisText, sizeof axisText, "%g ns, step %g ps", axis_.start_s * 1e9,
                  axis_.bin_width_s * 1e12);
    image.description = "streak image of row " + std::to_string(y) + " (rows: time from " +
                        axisText + "; columns: x)";
    image.data.resize(a.size());
    for (int32_t x = 0; x < W; ++x) {
      Rng rng(seed_, pixelStream(kStreakStreamTag, static_cast<uint64_t>(y) * W + x));
      for (int32_t t = 0; t < T; ++t) {
        const std::size_t i = static_cast<std::size_t>(t) * W + x;
        double e = p_.shot_noise ? static_cast<double>(rng.poisson(std::max(0.0, a[i]))) : a[i];
        if (p_.read_noise_e > 0.0) e += rng.normal(0.0, p_.read_noise_e);
        image.data[i] =
            static_cast<float>(std::clamp(e * p_.gain_adu_per_e, 0.0, p_.saturation_adu));
      }
    }
    return image;
  }

  const StreakParams p_;
  const VolumeShape shape_;
  const uint64_t seed_;
  const TimeAxis axis_;
  const BinKernel timeKernel_, spaceKernel_;
  std::vector<int32_t> rows_;
  std::map<int32_t, SensorOutput> images_;  // recorded row -> its image once complete
  std::vector<int32_t> order_;              // the recorded rows, each once, in `rows` order
  std::vector<double> rowTimes_;            // sampleTimes_s
  std::set<int32_t> inPass_;                // scanning: the rows of the current pass
  bool scanning_ = false;
  std::vector<double> row_, blurred_, signal_, resampled_;
  std::size_t next_ = 0;
};

}  // namespace

std::unique_ptr<SensorStream> openStreak(const StreakParams& params, const VolumeShape& shape,
                                         const StreamOptions& options) {
  return std::make_unique<StreakStream>(params, shape, options);
}

std::vector<SensorOutput> runStreak(const TransientVolume& volume, const StreakParams& p,
                                    uint64_t seed) {
  StreamOptions options;
  options.seed = seed;
  const std::unique_ptr<SensorStream> stream = openStreak(p, shapeOf(volume), options);
  stream->consume(wholeVolume(volume));
  return stream->finish(nullptr);
}

}  // namespace tofsim::sensors
