#pragma once
// The configured sensors (config.sensors) fed the volume span by span as it
// streams out of the renderer, or from a saved volume in one span: what a run
// with sensors holds is the current segment and the sensors' own state
// (sensors/SensorStream.h), never the whole volume. Arrays as large as a
// volume channel (spad_counts) are written to their .npy as they are made.
// Outputs go to OUTDIR/sensors/<sensor name>/.
//
// Randomness: every sensor is seeded with config.render.seed and every pixel
// draws from its own stream, so the bytes do not depend on how the volume is
// cut into segments: a render's sensors and `tofsim sense` on its saved
// volume write the same files.

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/PsfPath.h"
#include "tofsim/sensors/SensorStream.h"
#include "tofsim/sensors/WindowLoss.h"

namespace tofsim::pipeline {

/// How many indirect bounces the render's light is split into for the
/// sensors (sensors::StreamOptions::bounces): unset when no sensor asks
/// (cwtof multipath_by_order); else the IR renderer's render.indirect.bounces
/// (0 with indirect light off) or the reference's bounces - 1 (at most 1,
/// checked by the config: its indirect light is then bounce 1).
std::optional<int32_t> sensorBounces(const config::RunConfig& config);

class SensorStreams {
 public:
  /// Opens every configured sensor for a volume of `shape`; spans carry the
  /// direct component when `withDirect`, and the direct component and
  /// bounces 1..N when `bounces` = N. A sensor that does not fit the volume
  /// (a row outside the image, ...) throws an InputError naming the config
  /// file and the sensor, before any value arrives.
  /// With `camera` (the pinhole the pixels looked through), depth images
  /// are also written as point clouds (PointCloudPly.h).
  /// `psf`: where the render applies camera.psf. Transient: the CW-ToF
  /// sensors also take the light before it (consumeBeforePsf) for their
  /// cwtof_psf_error; Raws: they apply it themselves on their raws
  /// (StreamOptions::psfOnRaws) and the spans carry the light before it.
  SensorStreams(const config::RunConfig& config, const sensors::VolumeShape& shape, bool withDirect,
                std::optional<int32_t> bounces, const std::filesystem::path& outputDirectory,
                const capture::Camera* camera = nullptr, PsfPath psf = PsfPath::None);
  ~SensorStreams();
  SensorStreams(const SensorStreams&) = delete;
  SensorStreams& operator=(const SensorStreams&) = delete;

  /// A moving scene's frame: the times (s after the frame's) at which some
  /// sensor samples the light (SensorStream::sampleTimes_s), 0 first (the
  /// frame's own time) and the others increasing.
  std::vector<double> passOffsets_s() const;
  /// The spans until the next call are the light at the frame's time +
  /// offset_s, one of passOffsets_s(): each sensor takes the pass as the
  /// samples it has at that time, sensors with none ignore it (offset 0,
  /// the reference, goes to every sensor). Never called for a static scene.
  void beginPass(double offset_s);

  /// Spans in order, covering the image once (once per pass).
  void consume(const sensors::PixelSpan& span);
  /// With PsfPath::Transient: the light before the lens's PSF, in order,
  /// covering the image once (SensorStream::consumeBeforePsf).
  void consumeBeforePsf(const sensors::PixelSpan& span);
  /// Warns (throws under --strict) for each sensor whose instrument window
  /// drops a noticeable part of the light it was given. After the last span.
  void checkWindows() const;
  /// Prints the sensors' warnings, writes their outputs and the metadata of
  /// each (SensorWriter.h: the warnings included, pictures in the ranges of
  /// output.plot_ranges), warns of plot_ranges keys under "sensors/" that no
  /// picture took, and returns the files written, relative to the output
  /// directory ("sensors/spad/spad_counts.npy").
  std::vector<std::string> finish(const Image* groundTruthDepth_m, const Progress& progress);

 private:
  struct Entry;
  const config::RunConfig& config_;
  sensors::VolumeShape shape_;
  std::filesystem::path outputDirectory_;
  const capture::Camera* camera_;
  std::vector<std::unique_ptr<Entry>> entries_;
};

}  // namespace tofsim::pipeline
