#pragma once
// A sensor model fed the volume as it streams out of the renderer: runs of
// consecutive pixels in row order (the (H, W, T, C) layout of transient.npy),
// so that no one needs the whole volume in memory. Each model keeps only what
// it must: per-pixel results, the image rows a streak camera records, the
// histograms a SPAD plots. The in-memory entry points (runSensor, runSpad,
// ...) feed the whole volume as one span, so both paths are one code path and
// give the same bytes; every pixel draws from its own random stream
// (Random.h), so how the image is cut into spans changes nothing.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/optics/PsfKernel.h"
#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::sensors {

/// What a stream needs to know of the volume before any value arrives.
struct VolumeShape {
  int32_t width = 0;
  int32_t height = 0;
  int32_t channels = 0;
  TimeAxis axis;

  std::size_t pixelCount() const { return static_cast<std::size_t>(width) * height; }
  std::size_t pixelFloats() const { return static_cast<std::size_t>(axis.bins) * channels; }
};

VolumeShape shapeOf(const TransientVolume& volume);

/// Pixels firstPixel .. firstPixel + pixelCount - 1 (index y * width + x),
/// each VolumeShape::pixelFloats() floats.
struct PixelSpan {
  std::size_t firstPixel = 0;
  std::size_t pixelCount = 0;
  const float* volume = nullptr;      ///< the total volume
  const float* directOnly = nullptr;  ///< its direct component, or nullptr
  /// Bounces 1..N (StreamOptions::bounces = N), the light of exactly k
  /// indirect bounces; empty when the spans do not carry them.
  std::vector<const float*> bounces;
};

/// The whole volume (and its direct component and bounces, when given) as one span.
PixelSpan wholeVolume(const TransientVolume& volume, const TransientVolume* directOnly = nullptr,
                      const std::vector<const TransientVolume*>* bounces = nullptr);

/// Receives an Array output in C order as it is made; it is never held whole.
class ArrayWriter {
 public:
  virtual ~ArrayWriter() = default;
  virtual void append(const float* values, std::size_t count) = 0;
  /// Every value has been appended.
  virtual void close() = 0;
};

/// Where a stream may send its Array outputs as large as a volume channel
/// (spad_counts). Such an output then comes back from finish() with
/// `streamed` set and no data.
class ArrayStreams {
 public:
  virtual ~ArrayStreams() = default;
  virtual std::unique_ptr<ArrayWriter> open(const std::string& name,
                                            const std::vector<int64_t>& shape) = 0;
};

struct StreamOptions {
  uint64_t seed = 0;
  /// Spans carry directOnly (CW-ToF's error against the direct-only depth).
  bool directOnly = false;
  /// N: spans carry the direct component and bounces 1..N (CW-ToF's
  /// multipath error by bounce order; N = 0: direct only). Unset: they do not.
  std::optional<int32_t> bounces;
  /// nullptr: every output is held in memory and returned with its data.
  ArrayStreams* arrays = nullptr;
  /// Threads a span's pixels are spread over; 0: every core. The bytes do
  /// not depend on it.
  int threads = 0;
  /// The lens's PSF (camera.psf) for the sensor to apply itself: the spans
  /// carry the light before it, and a CW-ToF sensor convolves its
  /// noise-free signal charges (optics::applyPsf on its F N raw planes,
  /// ambient excluded), the same by linearity as the PSF on every bin.
  /// CW-ToF only, and exact only without a fixed-pattern delay (an
  /// InputError else). Not owned; nullptr: the spans carry the light as
  /// the sensor sees it.
  const optics::PsfKernel* psfOnRaws = nullptr;
  /// consumeBeforePsf() is given the light before the lens's PSF, the
  /// spans of consume() carrying it after (CW-ToF's cwtof_psf_error).
  bool beforePsf = false;
  /// A moving scene's sensors that integrate over time (CW-ToF's raws over
  /// integration_time): the samples per exposure, at the middles of equal
  /// parts of it (sampleTimes_s).
  int32_t exposureSamples = 1;
};

/// The sample times of an exposure [start, start + exposure) in a moving
/// scene: the middles of S equal parts of it, appended to `times`.
void appendExposureSamples(double start_s, double exposure_s, int32_t S,
                           std::vector<double>& times);

/// One pass of a moving scene's frame (SensorStream::beginPass): the light
/// at one time, standing for the samples listed.
struct SensorPass {
  /// Indices into SensorStream::sampleTimes_s(); empty: none of them.
  std::vector<std::size_t> samples;
  /// The frame's own time: its light gives what is compared with the
  /// ground truth (multipath errors, the instrument window's loss).
  bool reference = false;
};

class SensorStream {
 public:
  virtual ~SensorStream() = default;
  /// Spans come in order and cover the image exactly once.
  virtual void consume(const PixelSpan& span) = 0;
  /// With StreamOptions::beforePsf: the same pixels' light before the
  /// lens's PSF (its volume; directOnly and bounces unset), in order and
  /// covering the image once, before, after or between the spans of
  /// consume(). Sensors that did not ask ignore it.
  virtual void consumeBeforePsf(const PixelSpan& /*span*/) {}
  /// When the light is sampled within a frame of a moving scene, s after
  /// the frame's time: CW-ToF samples each raw over its own exposure
  /// (capture order, integration_time, readout_gap); the others take the
  /// frame's light at once, {0}.
  virtual std::vector<double> sampleTimes_s() const { return {0.0}; }
  /// A moving scene: the spans until the next beginPass (each pass covering
  /// the image once, in order) are the light at the time of `pass`'s
  /// samples. Without any call (a static scene) the spans are the light of
  /// every sample at once. Sensors whose samples are {0} see only the
  /// reference pass.
  virtual void beginPass(const SensorPass& /*pass*/) {}
  /// After the last span: the outputs (sensors/README.md, "Outputs"). The
  /// ground-truth depth (H, W, 1) in metres, known only once the render is
  /// done, feeds the CW-ToF multipath errors; nullptr when there is none.
  virtual std::vector<SensorOutput> finish(const Image* groundTruthDepth_m) = 0;
};

}  // namespace tofsim::sensors
