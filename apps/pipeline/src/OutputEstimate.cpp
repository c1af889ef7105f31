#include "tofsim/pipeline/OutputEstimate.h"

#include <sys/statvfs.h>

#include <algorithm>
#include <cstdio>

#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {

constexpr std::uintmax_t kChannels = 3;
constexpr std::uintmax_t kNpyHeaderBytes = 128;
// An 8-bit RGB picture as a bound for its PNG, an eighth of that per MP4 frame.
constexpr std::uintmax_t kMp4Ratio = 8;

}  // namespace

std::uintmax_t OutputEstimate::totalBytes() const {
  std::uintmax_t total = 0;
  for (const OutputItem& item : items) total += item.bytes;
  return total;
}

OutputEstimate estimateOutputs(const config::RunConfig& config) {
  const capture::Camera& camera = config.camera.camera;
  const TimeAxis& axis = config.render.time;
  const std::uintmax_t w = static_cast<std::uintmax_t>(camera.width);
  const std::uintmax_t h = static_cast<std::uintmax_t>(camera.height);
  const std::uintmax_t bins = static_cast<std::uintmax_t>(axis.bins);
  const std::uintmax_t volume = kNpyHeaderBytes + w * h * bins * kChannels * 4;
  const std::string volumeKeys = "camera.resolution x time.bins";
  const config::OutputConfig& out = config.output;
  OutputEstimate e;
  if (out.transient) e.items.push_back({"transient.npy", volume, volumeKeys});
  if (out.direct) e.items.push_back({"direct.npy", volume, volumeKeys + ", output.components"});
  if (out.indirect) e.items.push_back({"indirect.npy", volume, volumeKeys + ", output.components"});
  for (const int32_t k : out.bounces) {
    e.items.push_back(
        {"bounce" + std::to_string(k) + ".npy", volume, volumeKeys + ", output.components"});
  }
  if (out.frames) e.items.push_back({"frames/*.exr", volume, volumeKeys + ", output.frames"});
  if (out.frames || out.video || out.frame_pngs) {
    // Disk the run needs while it goes, gone when it ends (BinMajorSpill.h).
    e.temporaryBytes = volume - kNpyHeaderBytes;
  }
  const std::uintmax_t picture = w * h * kChannels;
  const std::uintmax_t videoFrames = (bins + out.video_stride - 1) / out.video_stride;
  if (out.frame_pngs) {
    e.items.push_back(
        {"frames/*.png", videoFrames * picture, volumeKeys + " / output.video_stride"});
  }
  if (out.video) {
    e.items.push_back({"transient.mp4", videoFrames * picture / kMp4Ratio + 4096,
                       volumeKeys + " / output.video_stride"});
  }
  if (out.steady)
    e.items.push_back(
        {"steady.exr/.png", w * h * (kChannels * 4 + kChannels), "camera.resolution"});
  if (out.depth)
    e.items.push_back({"depth.exr/.npy/.png", w * h * (4 + 4 + kChannels), "camera.resolution"});
  for (const sensors::SensorSpec& spec : config.sensors) {
    e.items.push_back({"sensors/" + spec.name,
                       sensors::sensorOutputBytes(spec.params, camera.width, camera.height, axis),
                       "camera.resolution x the sensor's bins"});
  }
  return e;
}

std::string formatBytes(std::uintmax_t bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 6) {
    value /= 1024.0;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", value, units[unit]);
  return text;
}

void checkOutputsFit(const OutputEstimate& estimate, const config::RunConfig& config,
                     const std::filesystem::path& directory) {
  const std::uintmax_t total = estimate.totalBytes();
  std::vector<OutputItem> largest = estimate.items;
  std::sort(largest.begin(), largest.end(),
            [](const OutputItem& a, const OutputItem& b) { return a.bytes > b.bytes; });
  std::string detail;
  for (std::size_t i = 0; i < largest.size() && i < 3; ++i) {
    detail += (i ? ", " : "") + largest[i].what + " " + formatBytes(largest[i].bytes) + " (" +
              largest[i].drivenBy + ")";
  }
  const std::string need = "the outputs need about " + formatBytes(total) + ": " + detail;
  if (total > config.output.max_bytes) {
    throw InputError(FileLoc{config.config_file.string()}, "output.max_bytes",
                     need + "; that is over output.max_bytes (" +
                         formatBytes(config.output.max_bytes) +
                         "): lower time.bins or camera.resolution, turn outputs off, or raise "
                         "output.max_bytes");
  }
  struct statvfs fs {};
  if (::statvfs(directory.c_str(), &fs) != 0) return;  // unknown: the writes will tell
  const std::uintmax_t available = static_cast<std::uintmax_t>(fs.f_bavail) * fs.f_frsize;
  if (total + estimate.temporaryBytes > available) {
    const std::string temporary =
        estimate.temporaryBytes == 0
            ? ""
            : ", and " + formatBytes(estimate.temporaryBytes) +
                  " more while the run goes (the video's and frames' bin-major copy of the "
                  "volume, output.video / frames / frame_pngs)";
    throw InputError(FileLoc{directory.string()}, "",
                     need + temporary + "; the file system has " + formatBytes(available) +
                         " free (the earlier results stay until the new set is complete)");
  }
}

}  // namespace tofsim::pipeline
