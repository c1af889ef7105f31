#include "tofsim/pipeline/OutputEstimate.h"

#include <sys/statvfs.h>

#include <algorithm>
#include <cstdio>
#include <limits>

#include "LidarRun.h"
#include "tofsim/pipeline/NlosEstimate.h"
#include "tofsim/pipeline/OutputProducts.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

std::uintmax_t OutputEstimate::totalBytes() const {
  // Saturating: an NLOS estimate's items may be at the type's maximum.
  std::uintmax_t total = 0;
  for (const OutputItem& item : items) {
    total = item.bytes > std::numeric_limits<std::uintmax_t>::max() - total
                ? std::numeric_limits<std::uintmax_t>::max()
                : total + item.bytes;
  }
  return total;
}

namespace {

// The estimate lists the volume-sized products first, then the pictures (the
// order its message has always had, which decides it among equal sizes).
int listingRank(Writer writer) {
  switch (writer) {
    case Writer::Volume:
      return 0;
    case Writer::Frames:
      return 1;
    case Writer::Video:
      return 2;
    case Writer::Steady:
      return 3;
    case Writer::Depth:
      return 4;
    case Writer::Metadata:
    case Writer::Capture:
      return 5;
  }
  return 5;
}

}  // namespace

OutputEstimate estimateOutputs(const config::RunConfig& config) {
  std::vector<OutputProduct> products = renderProducts(config);
  std::stable_sort(products.begin(), products.end(),
                   [](const OutputProduct& a, const OutputProduct& b) {
                     return listingRank(a.writer) < listingRank(b.writer);
                   });
  const config::OutputConfig& out = config.output;
  OutputEstimate e;
  for (const OutputProduct& p : products) {
    e.items.insert(e.items.end(), p.sizes.begin(), p.sizes.end());
  }
  if (out.frames || out.video || out.frame_pngs) {
    // Disk the run needs while it goes, gone when it ends (BinMajorSpill.h):
    // the volume's floats, without a header.
    e.temporaryBytes = volumeBytes(config);
  }
  const capture::Camera& camera = config.camera.camera;
  for (const sensors::SensorSpec& spec : config.sensors) {
    const std::uintmax_t bytes =
        sensors::sensorOutputBytes(spec.params, camera.width, camera.height, config.render.time);
    e.items.push_back({"sensors/" + spec.name, bytes, "camera.resolution x the sensor's bins"});
    // output.format: hdf5 copies the arrays into capture.h5 (at most their size).
    if (out.format == config::OutputFormat::Hdf5) {
      e.items.push_back({"capture.h5 sensors/" + spec.name, bytes,
                         "camera.resolution x the sensor's bins, output.format"});
    }
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

namespace {

// "the outputs need about 27.0 GiB: transient.npy 13.5 GiB (keys), ..."
std::string needText(const OutputEstimate& estimate) {
  std::vector<OutputItem> largest = estimate.items;
  std::sort(largest.begin(), largest.end(),
            [](const OutputItem& a, const OutputItem& b) { return a.bytes > b.bytes; });
  std::string detail;
  for (std::size_t i = 0; i < largest.size() && i < 3; ++i) {
    detail += (i ? ", " : "") + largest[i].what + " " + formatBytes(largest[i].bytes) + " (" +
              largest[i].drivenBy + ")";
  }
  return "the outputs need about " + formatBytes(estimate.totalBytes()) + ": " + detail;
}

}  // namespace

void checkMaxBytes(const OutputEstimate& estimate, const config::RunConfig& config) {
  if (estimate.totalBytes() <= config.output.max_bytes) return;
  throw InputError(FileLoc{config.config_file.string()}, "output.max_bytes",
                   needText(estimate) + "; that is over output.max_bytes (" +
                       formatBytes(config.output.max_bytes) +
                       "): lower the keys named, turn outputs off, or raise output.max_bytes");
}

void checkRunSizes(const config::RunConfig& config) {
  if (config.nlos) {
    checkNlosMemory(config);
    checkMaxBytes(nlosOutputs(config), config);
  } else if (config.lidar) {
    checkMaxBytes(lidarOutputs(config), config);
  } else {
    checkMaxBytes(estimateOutputs(config), config);
  }
}

void checkOutputsFit(const OutputEstimate& estimate, const config::RunConfig& config,
                     const std::filesystem::path& directory) {
  checkMaxBytes(estimate, config);
  const std::uintmax_t total = estimate.totalBytes();
  const std::string need = needText(estimate);
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
