#include "tofsim/pipeline/OutputProducts.h"

#include <cstdio>

#include "tofsim/capture/SegmentSink.h"
#include "tofsim/pipeline/FiniteSegments.h"

namespace tofsim::pipeline {

namespace files {

std::string bounce(int32_t k) { return std::string(capture::bounceComponent(k)) + ".npy"; }

namespace {
std::string frame(int32_t bin, const char* extension) {
  char name[64];
  std::snprintf(name, sizeof name, "frames/frame_%05d.%s", bin, extension);
  return name;
}
}  // namespace

std::string frameExr(int32_t bin) { return frame(bin, "exr"); }
std::string framePng(int32_t bin) { return frame(bin, "png"); }

}  // namespace files

namespace {

constexpr std::uintmax_t kChannels = 3;
constexpr std::uintmax_t kNpyHeaderBytes = 128;
// An 8-bit RGB picture as a bound for its PNG, an eighth of that per MP4 frame.
constexpr std::uintmax_t kMp4Ratio = 8;

std::string text(std::string_view name) { return std::string(name); }

}  // namespace

std::uintmax_t volumeBytes(const config::RunConfig& config) {
  const capture::Camera& camera = config.camera.camera;
  return static_cast<std::uintmax_t>(camera.width) * static_cast<std::uintmax_t>(camera.height) *
         static_cast<std::uintmax_t>(config.render.time.bins) * kChannels * 4;
}

std::vector<OutputProduct> renderProducts(const config::RunConfig& config) {
  const capture::Camera& camera = config.camera.camera;
  const TimeAxis& axis = config.render.time;
  const std::uintmax_t w = static_cast<std::uintmax_t>(camera.width);
  const std::uintmax_t h = static_cast<std::uintmax_t>(camera.height);
  const std::uintmax_t bins = static_cast<std::uintmax_t>(axis.bins);
  const std::uintmax_t volume = kNpyHeaderBytes + volumeBytes(config);
  const std::string volumeKeys = "camera.resolution x time.bins";
  const std::string componentKeys = volumeKeys + ", output.components";
  const config::OutputConfig& out = config.output;
  std::vector<OutputProduct> p;
  // With output.format: hdf5 a volume is a dataset of capture.h5 (its size
  // line still the .npy's: an upper bound of the compressed dataset).
  const bool hdf5 = out.format == config::OutputFormat::Hdf5;
  const auto addVolume = [&](std::string_view component, std::string file,
                             const std::string& keys) {
    std::string dataset = file.substr(0, file.size() - 4);
    std::vector<std::string> written;
    if (!hdf5) written.push_back(file);
    p.push_back({Writer::Volume,
                 component,
                 std::move(dataset),
                 std::move(written),
                 {{file, volume, keys}}});
  };
  if (out.transient) addVolume(kTotal, text(files::kTransient), volumeKeys);
  if (out.direct) addVolume(capture::kDirect, text(files::kDirect), componentKeys);
  if (out.indirect) addVolume(capture::kIndirect, text(files::kIndirect), componentKeys);
  for (const int32_t k : out.bounces) {
    addVolume(capture::bounceComponent(k), files::bounce(k), componentKeys);
  }
  if (out.steady) {
    p.push_back({Writer::Steady,
                 {},
                 {},
                 {text(files::kSteadyExr), text(files::kSteadyPng)},
                 {{"steady.exr/.png", w * h * (kChannels * 4 + kChannels), "camera.resolution"}}});
  }
  if (out.depth) {
    p.push_back({Writer::Depth,
                 {},
                 {},
                 {text(files::kDepthExr), text(files::kDepthNpy), text(files::kDepthPng)},
                 {{"depth.exr/.npy/.png", w * h * (4 + 4 + kChannels), "camera.resolution"}}});
  }
  if (out.frames) {
    OutputProduct frames{
        Writer::Frames, {}, {}, {}, {{"frames/*.exr", volume, volumeKeys + ", output.frames"}}};
    for (int32_t t = 0; t < axis.bins; ++t) frames.files.push_back(files::frameExr(t));
    p.push_back(std::move(frames));
  }
  if (out.video || out.frame_pngs) {
    const std::uintmax_t picture = w * h * kChannels;
    const std::uintmax_t videoFrames = (bins + out.video_stride - 1) / out.video_stride;
    const std::string videoKeys = volumeKeys + " / output.video_stride";
    OutputProduct video{Writer::Video, {}, {}, {}, {}};
    if (out.frame_pngs) video.sizes.push_back({"frames/*.png", videoFrames * picture, videoKeys});
    if (out.video) {
      video.files.push_back(text(files::kVideo));
      video.sizes.push_back(
          {text(files::kVideo), videoFrames * picture / kMp4Ratio + 4096, videoKeys});
    }
    if (out.frame_pngs) {
      for (int32_t t = 0; t < axis.bins; t += out.video_stride) {
        video.files.push_back(files::framePng(t));
      }
    }
    p.push_back(std::move(video));
  }
  // Small (no size line): it describes transient.npy.
  if (out.transient) p.push_back({Writer::Metadata, {}, {}, {text(files::kMetadata)}, {}});
  // Last: it holds the arrays above, and the sensors' that follow them.
  if (hdf5) p.push_back({Writer::Capture, {}, {}, {text(files::kCapture)}, {}});
  return p;
}

std::vector<std::pair<std::string, std::string>> metadataFiles(const config::OutputConfig& out) {
  const bool hdf5 = out.format == config::OutputFormat::Hdf5;
  return {{"transient", text(hdf5 ? files::kCapture : files::kTransient)},
          {"steady", text(files::kSteadyExr)},
          {"depth", text(files::kDepthExr)}};
}

}  // namespace tofsim::pipeline
