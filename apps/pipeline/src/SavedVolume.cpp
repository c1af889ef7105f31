#include "tofsim/pipeline/SavedVolume.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& message) {
  throw InputError(FileLoc{file.string()}, "", message);
}

struct VolumeLayout {
  TimeAxis axis;
  std::vector<std::string> channels;
};

// The sensors need the time axis, which only the JSON records (the .npy holds
// numbers and a shape).
VolumeLayout readLayout(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) fail(file, "cannot open (it is written by `tofsim render` with output.transient)");
  VolumeLayout layout;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    const nlohmann::json& time = j.at("time");
    layout.axis.start_s = time.at("start_s").get<double>();
    layout.axis.bin_width_s = time.at("bin_width_s").get<double>();
    layout.axis.bins = time.at("bins").get<int32_t>();
    if (j.contains("channels")) layout.channels = j.at("channels").get<std::vector<std::string>>();
  } catch (const nlohmann::json::exception& e) {
    fail(file, std::string("not a tofsim transient.json: ") + e.what());
  }
  if (!(layout.axis.bin_width_s > 0.0) || layout.axis.bins < 1) {
    fail(file, "time.bin_width_s must be > 0 and time.bins >= 1");
  }
  return layout;
}

std::string shapeText(const io::NpyShape& shape) {
  std::string text = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) text += (i ? ", " : "") + std::to_string(shape[i]);
  return text + ")";
}

TransientVolume readVolume(const std::filesystem::path& file, const VolumeLayout& layout,
                           const std::filesystem::path& jsonFile) {
  if (!std::filesystem::exists(file)) fail(file, "not found");
  io::NpyArray array = io::readNpy(file);
  const io::NpyShape& s = array.shape;
  if (s.size() != 4 || s[2] != static_cast<std::size_t>(layout.axis.bins) ||
      (!layout.channels.empty() && s[3] != layout.channels.size())) {
    fail(file, "shape " + shapeText(s) + " does not match " + jsonFile.filename().string() +
                   " (expected (H, W, " + std::to_string(layout.axis.bins) + ", " +
                   (layout.channels.empty() ? "C" : std::to_string(layout.channels.size())) + "))");
  }
  std::vector<std::string> channels = layout.channels;
  for (std::size_t c = channels.size(); c < s[3]; ++c) channels.push_back("C" + std::to_string(c));
  TransientVolume volume(static_cast<int32_t>(s[1]), static_cast<int32_t>(s[0]), layout.axis,
                         channels);
  volume.values() = std::move(array.data);
  return volume;
}

}  // namespace

SavedVolume loadSavedVolume(const std::filesystem::path& directory) {
  const std::filesystem::path json = directory / "transient.json";
  const VolumeLayout layout = readLayout(json);
  SavedVolume saved{readVolume(directory / "transient.npy", layout, json), {}, {}};
  const int32_t W = saved.volume.width(), H = saved.volume.height();
  if (std::filesystem::exists(directory / "direct.npy")) {
    saved.directOnly = readVolume(directory / "direct.npy", layout, json);
    if (saved.directOnly->width() != W || saved.directOnly->height() != H ||
        saved.directOnly->channels() != saved.volume.channels()) {
      fail(directory / "direct.npy", "shape differs from transient.npy");
    }
  }
  const std::filesystem::path depthFile = directory / "depth.exr";
  if (std::filesystem::exists(depthFile)) {
    saved.depth_m = io::readExr(depthFile);
    if (saved.depth_m->channels != 1 || saved.depth_m->width != W || saved.depth_m->height != H) {
      fail(depthFile, "expected one channel of " + std::to_string(W) + "x" + std::to_string(H) +
                          " (got " + std::to_string(saved.depth_m->channels) + " of " +
                          std::to_string(saved.depth_m->width) + "x" +
                          std::to_string(saved.depth_m->height) + ")");
    }
  }
  return saved;
}

}  // namespace tofsim::pipeline
