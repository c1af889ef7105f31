#pragma once
// Streams rendered segments to disk as they arrive: transient.npy (direct +
// indirect) and, when asked, direct.npy and indirect.npy, while accumulating
// the steady image. Nothing appears under its final name until commit(); an
// exception or interruption before then leaves only removed temporaries.
//
// NaN and infinity never reach the files silently: each value that is not
// finite (in direct, indirect or their float sum) is written as 0 and counted
// (nonFiniteValues()), and the run reports the count.

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "tofsim/capture/SegmentSink.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/io/Npy.h"
#include "tofsim/sensors/SensorStream.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::pipeline {

/// Replaces NaN and +-inf by 0 in place; returns how many there were. The one
/// rule for every output path (files here, arrays in the Python module).
std::size_t zeroNonFinite(float* values, std::size_t count);

class OutputSink : public capture::SegmentSink {
 public:
  /// Each segment's values as written (total and direct, non-finite values
  /// zeroed), for the sensors (SensorStreams.h).
  using Forward = std::function<void(const sensors::PixelSpan&)>;

  /// forward: called with every segment's values once they are written (the
  /// sensors, the video's bin-major copy); the sink holds no volume.
  /// forwardBounces N >= 1: the forwarded spans carry bounces 1..N too,
  /// non-finite values zeroed as in bounce<k>.npy (bounce 1 is the
  /// indirect light when N = 1: the IR's bounce1, the reference's one bounce).
  OutputSink(const std::filesystem::path& directory, const config::OutputConfig& output,
             int32_t width, int32_t height, const TimeAxis& axis, Forward forward = {},
             int32_t forwardBounces = 0);
  void consume(const capture::Segment& segment) override;
  /// Renames the streamed files into place.
  void commit();

  /// sum over t of transient.npy, accumulated in double.
  Image steady() const;
  /// How many values were NaN or infinite and replaced by 0 so far.
  std::size_t nonFiniteValues() const { return nonFinite_; }

 private:
  /// Bounces 1..forwardBounces_ (>= 2) into forwardedBounces_, non-finite zeroed.
  void cleanForwardedBounces(const capture::Segment& segment, std::size_t floats);
  /// Bounce k with non-finite values zeroed, for bounce<k>.npy: the sensors'
  /// copy when they take it, else cleaned into bounceScratch_.
  const float* cleanBounce(const capture::Segment& segment, int32_t k, std::size_t floats);
  /// The segment as the sensors see it (after consume cleaned it).
  sensors::PixelSpan forwardedSpan(const capture::Segment& segment) const;

  int32_t width_, height_;
  TimeAxis axis_;
  std::unique_ptr<io::NpyStreamWriter> total_, directFile_, indirectFile_;
  /// bounce<k>.npy for each k of OutputConfig::bounces, in that order.
  std::vector<std::pair<int32_t, std::unique_ptr<io::NpyStreamWriter>>> bounceFiles_;
  std::vector<double> steady_;
  std::vector<float> scratch_, directScratch_, indirectScratch_, bounceScratch_;
  int32_t forwardBounces_ = 0;
  std::vector<std::vector<float>> forwardedBounces_;  ///< bounces 1..N when forwardBounces_ >= 2
  std::size_t nonFinite_ = 0;
  Forward forward_;
};

}  // namespace tofsim::pipeline
