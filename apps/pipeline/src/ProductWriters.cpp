#include "ProductWriters.h"

#include "SequenceVideo.h"  // videoOptions

#include "tofsim/capture/VolumeCollector.h"  // defaultChannelNames
#include "tofsim/imaging/Video.h"
#include "tofsim/io/DepthExr.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/Metadata.h"
#include "tofsim/pipeline/OutputFileNames.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

namespace {

void writeFrames(const std::filesystem::path& directory, const imaging::BinFrames& frames) {
  std::filesystem::create_directories(directory / "frames");
  std::vector<std::string> channels = capture::defaultChannelNames(frames.channels);
  for (int32_t t = 0; t < frames.axis.bins; ++t) {
    throwIfInterrupted();
    Image frame(frames.width, frames.height, frames.channels);
    frames.readBin(t, frame.data.data());
    io::writeExr(directory / files::frameExr(t), frame, channels);
  }
}

// transient.mp4 and/or frames/frame_NNNNN.png (the same pictures).
void writeVideo(const std::filesystem::path& dir, const config::OutputConfig& out,
                const imaging::BinFrames& frames, const Progress& progress) {
  const imaging::VideoOptions options = videoOptions(out);
  progress.message(
      "video: " + std::to_string(imaging::videoFrameCount(frames.axis.bins, out.video_stride)) +
      " frame(s)");
  imaging::writeTransientVideo(out.video ? dir / files::kVideo : std::filesystem::path(), frames,
                               options, out.frame_pngs ? dir / "frames" : std::filesystem::path());
}

void writeSteady(const std::filesystem::path& dir, const Image& steady, PlotRanges& ranges) {
  io::writeExr(dir / files::kSteadyExr, steady, {"R", "G", "B"});
  imaging::writeToneMappedPng(dir / files::kSteadyPng, steady, imaging::ToneMap::Global,
                              ranges.take("steady"));
}

void writeDepth(const std::filesystem::path& dir, const Image& depth_m, PlotRanges& ranges) {
  io::writeDepthExr(dir / files::kDepthExr, depth_m);  // channels Y and Z
  io::writeNpy(dir / files::kDepthNpy, {std::size_t(depth_m.height), std::size_t(depth_m.width)},
               depth_m.data.data());
  imaging::ColorScale scale;  // over the surfaces: 0 (no surface) is not a depth
  scale.nonPositiveIsNoData = true;
  scale.noDataLabel = "no surface";
  scale.range = ranges.take("depth");
  imaging::writeColormappedPng(dir / files::kDepthPng, depth_m, "depth [m]", scale);
}

}  // namespace

void writeProduct(const OutputProduct& p, const config::RunConfig& config,
                  const capture::RenderJob& job, const std::filesystem::path& dir,
                  const Image& steady, const RunSummary& summary, OutputStreams& streams,
                  PlotRanges& ranges, const Progress& progress) {
  CaptureFile* capture = streams.capture();
  switch (p.writer) {
    case Writer::Volume:
    case Writer::Capture:  // committed after the sensors (writeOutputs)
      break;
    case Writer::Steady:
      writeSteady(dir, steady, ranges);
      if (capture) capture->addSteady(steady);
      break;
    case Writer::Depth:
      writeDepth(dir, summary.result.depth_m, ranges);
      if (capture) capture->addDepth(summary.result.depth_m);
      break;
    case Writer::Frames:
      writeFrames(dir, streams.binFrames());
      break;
    case Writer::Video:
      writeVideo(dir, config.output, streams.binFrames(), progress);
      break;
    case Writer::Metadata: {
      const std::string json =
          transientMetadataJson(config, job, summary.result, summary.backend, summary.device);
      writeFileAtomically(dir / files::kMetadata, json);
      if (capture) capture->describeVolumes(json);
      break;
    }
  }
}

}  // namespace tofsim::pipeline
