#include "OutputStreams.h"

#include <algorithm>

#include "tofsim/capture/Imager.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/pipeline/FiniteSegments.h"
#include "tofsim/pipeline/OutputFileNames.h"

namespace tofsim::pipeline {

namespace {

// The video's and the frames' bin-major copy of the volume, in the staging
// folder (on the outputs' disk, not a RAM-backed /tmp); gone before the
// folder is committed.
constexpr const char* kBinMajorSpillName = ".transient_bin_major.tmp";

// The bounce components the consumers read: bounce<k>.npy's and the sensors'
// bounces 1..N (N = 1 reads the indirect light).
std::vector<int32_t> bouncesRead(const config::OutputConfig& out, int32_t sensorBounces) {
  std::vector<int32_t> bounces = out.bounces;
  for (int32_t k = 1; sensorBounces >= 2 && k <= sensorBounces; ++k) {
    if (std::find(bounces.begin(), bounces.end(), k) == bounces.end()) bounces.push_back(k);
  }
  return bounces;
}

}  // namespace

// The sensors see what the render saves (the total volume, plus the direct
// component and the depth when the output writes them), so `tofsim sense`
// on the saved folder reproduces their outputs byte for byte. They are fed
// each segment as it is written, so that no one holds the whole volume. The
// video and the frames (time-major: every pixel of one bin) get it through a
// bin-major temporary file. The light by bounce order (cwtof
// multipath_by_order) is given the sensors whether or not the components are
// saved; `tofsim sense` needs the files (direct.npy, bounce<k>.npy) to redo it.
OutputStreams::OutputStreams(const config::RunConfig& config, const capture::RenderJob& job,
                             const std::filesystem::path& dir,
                             const std::vector<OutputProduct>& products, bool psfOnTransient,
                             const std::filesystem::path& sharedVolume,
                             const Progress& progress) {
  const config::OutputConfig& out = config.output;
  const int32_t width = capture::imageWidth(job.imager), height = capture::imageHeight(job.imager);
  const sensors::VolumeShape shape{width, height, capture::kChannels, job.settings.time};
  bounces_ = sensorBounces(config);
  // The lens's PSF on every bin, or on the CW-ToF raws and the steady image
  // when nothing written needs the blurred transient (PsfPath.h).
  const PsfPath psf = choosePsfPath(config, psfOnTransient);
  if (psf == PsfPath::Raws) {
    progress.message(
        "camera.psf: on the CW-ToF raws and the steady image (no output needs the blurred "
        "transient)");
  }
  if (!config.sensors.empty()) {
    sensorStreams_.emplace(config, shape, out.direct, bounces_, dir,
                           capture::cameraOf(job.imager), psf);
  }
  if (out.frames || out.video || out.frame_pngs) spill_.emplace(dir / kBinMajorSpillName, shape);
  // output.format: hdf5: the volumes and the other arrays in one file.
  if (out.format == config::OutputFormat::Hdf5) capture_.emplace(dir / files::kCapture, config.cpu_threads);
  for (const OutputProduct& p : products) {
    if (p.writer != Writer::Volume) continue;
    if (capture_) {
      consumers_.sinks.push_back(
          &capture_->volume(p.dataset, p.component, width, height, job.settings.time.bins));
      continue;
    }
    volumeFiles_.push_back(std::make_unique<VolumeFileSink>(dir / p.files.at(0), p.component,
                                                            width, height, job.settings.time));
    consumers_.sinks.push_back(volumeFiles_.back().get());
  }
  // What the sensors see (no PSF on the transient here: SharedRender.h),
  // for the batch runs that take this render.
  if (!sharedVolume.empty()) {
    std::filesystem::create_directories(sharedVolume);
    volumeFiles_.push_back(std::make_unique<VolumeFileSink>(
        sharedVolume / files::kTransient, kTotal, width, height, job.settings.time));
    consumers_.sinks.push_back(volumeFiles_.back().get());
  }
  if (sensorStreams_ || spill_) {
    spans_.emplace(
        [this](const sensors::PixelSpan& s) {
          if (sensorStreams_) sensorStreams_->consume(s);
          if (spill_) spill_->append(s);
        },
        bounces_.value_or(0));
    consumers_.sinks.push_back(&*spans_);
  }
  // The light before the PSF, for the CW-ToF sensors' cwtof_psf_error.
  if (sensorStreams_ && psf == PsfPath::Transient) {
    sharpSpans_.emplace([this](const sensors::PixelSpan& s) { sensorStreams_->consumeBeforePsf(s); },
                        0);
    consumers_.beforePsf.push_back(&*sharpSpans_);
  }
  consumers_.psfOnRaws = psf == PsfPath::Raws;
  consumers_.bounces = bouncesRead(out, bounces_.value_or(0));
}

void OutputStreams::renderDone() {
  if (sensorStreams_) sensorStreams_->checkWindows();
  for (const std::unique_ptr<VolumeFileSink>& file : volumeFiles_) file->commit();
}

const imaging::BinFrames& OutputStreams::binFrames() {
  if (!frames_) frames_.emplace(spill_->frames());
  return *frames_;
}

}  // namespace tofsim::pipeline
