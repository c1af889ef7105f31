#pragma once
// Private to the pipeline: what a render's segments stream into while it
// runs (RenderRun.cpp's writeOutputs): the volume files or capture.h5, the
// sensors, and the bin-major spill the video and the frames read. Made
// before the render, so that a sensor that does not fit or a file that
// cannot be created fails before any light is computed.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "BinMajorSpill.h"
#include "CaptureFile.h"
#include "tofsim/capture/RenderJob.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/OutputProducts.h"
#include "tofsim/pipeline/PixelSpanSink.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/PsfPath.h"
#include "tofsim/pipeline/RenderCapture.h"
#include "tofsim/pipeline/SensorStreams.h"
#include "tofsim/pipeline/VolumeFileSink.h"

namespace tofsim::pipeline {

class OutputStreams {
 public:
  /// Into the staging folder `dir`, for the products' Writer::Volume files;
  /// `psfOnTransient`: RunOptions::psfOnTransient; `sharedVolume`: where the
  /// total volume is saved too (RunOptions::sharedVolume; empty: nowhere).
  OutputStreams(const config::RunConfig& config, const capture::RenderJob& job,
                const std::filesystem::path& dir, const std::vector<OutputProduct>& products,
                bool psfOnTransient, const std::filesystem::path& sharedVolume,
                const Progress& progress);
  OutputStreams(const OutputStreams&) = delete;
  OutputStreams& operator=(const OutputStreams&) = delete;

  /// Who takes the render's segments.
  const CaptureConsumers& consumers() const { return consumers_; }
  /// The sensors' bounce orders (sensorBounces).
  std::optional<int32_t> bounces() const { return bounces_; }
  /// The sensors, or null without any.
  SensorStreams* sensors() { return sensorStreams_ ? &*sensorStreams_ : nullptr; }
  /// capture.h5 (output.format: hdf5), or null.
  CaptureFile* capture() { return capture_ ? &*capture_ : nullptr; }
  /// After the last segment: the sensors' time windows checked, the volume
  /// files completed.
  void renderDone();
  /// The volume bin by bin, read from the spill on first need.
  const imaging::BinFrames& binFrames();

 private:
  std::optional<int32_t> bounces_;
  std::optional<SensorStreams> sensorStreams_;
  std::optional<BinMajorSpill> spill_;
  std::optional<imaging::BinFrames> frames_;
  std::optional<CaptureFile> capture_;
  std::vector<std::unique_ptr<VolumeFileSink>> volumeFiles_;
  std::optional<PixelSpanSink> spans_;
  std::optional<PixelSpanSink> sharpSpans_;
  CaptureConsumers consumers_;
};

}  // namespace tofsim::pipeline
