// The SPAD model as a stream (SensorStream.h): spans of pixels in, each
// pixel's flux (SpadFlux.h), its histogram (SpadHistogramDraw.h) and its
// images (SpadImages.h); the counts held or streamed to an ArrayWriter, the
// plotted pixels' histograms kept; crosstalk's look-ahead across spans
// (SpadCrosstalk.h) drives the same per-pixel steps in two passes; exact
// crosstalk (SpadExactCrosstalk.h) holds the whole array's flux and draws it
// at once with the last span. In a moving scene with an exposure time the
// passes' light is averaged first (ExposureAverage.h) and drawn in finish().
#include "tofsim/sensors/Spad.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "ExposureAverage.h"
#include "ParallelPixels.h"
#include "PeakDepth.h"
#include "SpadCrosstalk.h"
#include "SpadExactCrosstalk.h"
#include "SpadFlux.h"
#include "SpadGatedFrames.h"
#include "SpadHistogramDraw.h"
#include "SpadImages.h"
#include "SpadParamsCheck.h"
#include "tofsim/sensors/SpadPixelMaps.h"
#include "tofsim/sensors/TimeKernel.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {

// No exposure time: {0}, the frame's time alone.
std::vector<double> exposureTimes_s(double exposure_s, int32_t S) {
  if (exposure_s <= 0.0) return {0.0};
  std::vector<double> times;
  appendExposureSamples(0.0, exposure_s, S, times);
  return times;
}

class SpadStream final : public SensorStream {
 public:
  SpadStream(const SpadParams& p, const VolumeShape& shape, const StreamOptions& options)
      : p_(p),
        shape_(shape),
        options_(options),
        axis_(resolveBins(p.bins, shape.axis)),
        bins_(detail::tdcBins(p, axis_)),
        gate_(detail::spadGate(p)),
        kernel_(detail::spadKernel(p, axis_)),
        draw_(p, axis_),
        plotted_(plotPixels(p.plot_pixels, shape.height, shape.width)),
        histograms_(plotted_.size()),
        maps_(spadPixelMaps(p, shape.height, shape.width)),
        frames_(p, shape, options),
        images_(p, axis_, kernel_, draw_.deadBins(), shape.height, shape.width),
        sampleTimes_(exposureTimes_s(p.exposure_time_s, options.exposureSamples)) {
    detail::checkSpadParams(p);
    if (detail::exactCrosstalk(p)) {
      // p_, not p: the driver keeps a reference, and the caller's params
      // need not outlive the stream.
      exact_ = std::make_unique<detail::SpadExactCrosstalk>(p_, draw_.laws(), bins_, shape.width,
                                                            shape.height);
    } else if (p.crosstalk_probability > 0.0) {
      // A batch of an image row (at least 256 pixels) between look-aheads.
      crosstalk_ = std::make_unique<detail::SpadCrosstalk>(
          p, axis_.bins, axis_.bin_width_s, draw_.deadBins(), shape.width, shape.height,
          std::max<std::size_t>(256, static_cast<std::size_t>(shape.width)));
    }
    checkChannelSelection(p.common.channel, shape.channels);
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
      counts_.data.resize(shape.pixelCount() * axis_.bins);
    }
  }

  /// The exposure's samples (exposure_time, StreamOptions::exposureSamples).
  std::vector<double> sampleTimes_s() const override { return sampleTimes_; }

  /// A moving scene: with an exposure time the passes are averaged and
  /// drawn in finish(); without, the one pass at the frame's time is drawn
  /// as it comes (the static path).
  void beginPass(const SensorPass& pass) override {
    if (sampleTimes_.size() == 1 && sampleTimes_[0] == 0.0) return;
    if (!average_) average_.emplace(shape_, sampleTimes_.size());
    average_->beginPass(pass.samples.size());
  }

  void consume(const PixelSpan& span) override {
    if (average_) {
      average_->add(span);
      return;
    }
    draw(span);
  }

  std::vector<SensorOutput> finish(const Image*) override {
    if (average_) {
      draw(average_->mean());
      average_.reset();
    }
    TOFSIM_CHECK(next_ == shape_.pixelCount());
    TOFSIM_CHECK(!crosstalk_ || received_ == next_);
    if (writer_) writer_->close();
    std::vector<SensorOutput> outputs;
    outputs.push_back(std::move(counts_));
    images_.finish(outputs);
    outputs.push_back(histogramPlot(plotted_, histograms_, axis_));
    frames_.finish(outputs);
    detail::appendSpadMapImages(p_, maps_, shape_.height, shape_.width, outputs);
    return outputs;
  }

 private:
  struct Scratch {
    std::vector<double> signal, resampled, flux, ungated, h, lambda;
    detail::SpadHistogramDraw::Scratch draw;
    detail::SpadImages::Scratch images;
  };

  // The span's pixels' histograms, in order and covering the image once.
  void draw(const PixelSpan& span) {
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
    exact_->run(options_.seed, detail::kSpadStreamTag);
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
    detail::fluxFromSignal(s.signal, shape_.axis, p_, pixel, bins_, kernel_, s.resampled, flux);
    // The gated frames sweep their own gates over the ungated flux (no
    // crosstalk with them: checkSpadParams), drawn with the pixel in drawPixel.
    if (frames_.active()) s.ungated = flux;
    detail::gateFlux(p_, gate_, pixel, bins_, flux);
  }

  SpadPixel pixelOf(std::size_t px) const {
    return {maps_.pde[px], maps_.dcr_per_s[px], maps_.kind[px], maps_.gate_skew_s[px]};
  }

  // The pixel's histogram from its flux s.flux into `out`, and its images;
  // its gated frames from s.ungated.
  void drawPixel(std::size_t px, float* out, Scratch& s) const {
    frames_.pixel(px, s.ungated, maps_.gate_skew_s[px], s.lambda);
    if (exact_) {
      s.h = exact_->histogram(px);  // drawn with its neighbours (consumeExact)
      draw_.saturate(s.h);
    } else {
      draw_.draw(px, options_.seed, s.flux, s.draw, s.h);
    }
    for (std::size_t i = 0; i < s.h.size(); ++i) out[i] = static_cast<float>(s.h[i]);
    images_.pixel(px, s.h, s.images);
  }

  const SpadParams p_;
  const VolumeShape shape_;
  const StreamOptions options_;
  const TimeAxis axis_;
  const detail::TdcBins bins_;
  const detail::SpadGate gate_;
  const BinKernel kernel_;
  const detail::SpadHistogramDraw draw_;
  const std::vector<std::array<int32_t, 2>> plotted_;
  std::vector<std::vector<float>> histograms_;
  const SpadPixelMaps maps_;
  detail::SpadGatedFrames frames_;
  detail::SpadImages images_;
  SensorOutput counts_;
  std::unique_ptr<ArrayWriter> writer_;
  std::vector<float> chunk_;
  std::unique_ptr<detail::SpadCrosstalk> crosstalk_;   ///< null: no crosstalk
  std::unique_ptr<detail::SpadExactCrosstalk> exact_;  ///< null: none, or first order
  std::size_t received_ = 0;                           ///< pixels drawn, with crosstalk
  std::size_t next_ = 0;
  const std::vector<double> sampleTimes_;
  std::optional<detail::ExposureAverage> average_;  ///< a moving exposure's passes
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
