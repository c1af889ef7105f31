#include "tofsim/pipeline/SavedVolume.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tofsim/io/DepthExr.h"
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
    // Read wide and range-checked below: get<int32_t>() of 1e20 would be an
    // out-of-range float-to-int conversion (undefined behaviour).
    const nlohmann::json& bins = time.at("bins");
    if (!bins.is_number_integer() || bins.get<int64_t>() < 1 || bins.get<int64_t>() > (1 << 24)) {
      fail(file, "time.bins must be an integer in [1, 16777216]");
    }
    layout.axis.bins = static_cast<int32_t>(bins.get<int64_t>());
    // What the times mean as depths, for the sensors (c / eta, one leg or
    // two). Absent in hand-written files: vacuum, camera leg timed.
    layout.axis.index_of_refraction = time.value("index_of_refraction", 1.0);
    layout.axis.camera_unwarp = time.value("camera_unwarp", false);
    if (j.contains("channels")) layout.channels = j.at("channels").get<std::vector<std::string>>();
  } catch (const nlohmann::json::exception& e) {
    fail(file, std::string("not a tofsim transient.json: ") + e.what());
  }
  if (!(layout.axis.bin_width_s > 0.0) || !std::isfinite(layout.axis.bin_width_s) ||
      !std::isfinite(layout.axis.start_s)) {
    fail(file, "time.start_s must be finite and time.bin_width_s finite and > 0");
  }
  if (!(layout.axis.index_of_refraction >= 1.0) ||
      !std::isfinite(layout.axis.index_of_refraction)) {
    fail(file, "time.index_of_refraction must be finite and >= 1");
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
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) fail(file, "not found");
  io::NpyArray array = io::readNpy(file);
  const io::NpyShape& s = array.shape;
  // Every axis at least 1 and H, W, C within int32 (TransientVolume's sizes).
  const auto badDimension = [](std::size_t d) { return d < 1 || d > (std::size_t{1} << 30); };
  if (s.size() != 4 || badDimension(s[0]) || badDimension(s[1]) || badDimension(s[3]) ||
      s[2] != static_cast<std::size_t>(layout.axis.bins) ||
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
  std::error_code ec;
  if (std::filesystem::exists(directory / "direct.npy", ec)) {
    saved.directOnly = readVolume(directory / "direct.npy", layout, json);
    if (saved.directOnly->width() != W || saved.directOnly->height() != H ||
        saved.directOnly->channels() != saved.volume.channels()) {
      fail(directory / "direct.npy", "shape differs from transient.npy");
    }
  }
  const std::filesystem::path depthFile = directory / "depth.exr";
  if (std::filesystem::exists(depthFile, ec)) {
    saved.depth_m = io::readDepthExr(depthFile);
    if (saved.depth_m->channels != 1 || saved.depth_m->width != W || saved.depth_m->height != H) {
      fail(depthFile, "expected one channel of " + std::to_string(W) + "x" + std::to_string(H) +
                          " (got " + std::to_string(saved.depth_m->channels) + " of " +
                          std::to_string(saved.depth_m->width) + "x" +
                          std::to_string(saved.depth_m->height) + ")");
    }
  }
  return saved;
}

int32_t savedIndirectBounces(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) fail(file, "cannot open");
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    if (!j.contains("indirect_bounces")) {
      fail(file, "records no indirect_bounces (written by an older tofsim): render again");
    }
    const nlohmann::json& n = j.at("indirect_bounces");
    if (!n.is_number_integer() || n.get<int64_t>() < 0 || n.get<int64_t>() > 64) {
      fail(file, "indirect_bounces must be an integer in [0, 64]");
    }
    return static_cast<int32_t>(n.get<int64_t>());
  } catch (const nlohmann::json::exception& e) {
    fail(file, std::string("not a tofsim transient.json: ") + e.what());
  }
}

std::optional<TransientVolume> loadSavedComponent(const std::filesystem::path& directory,
                                                  const std::string& name) {
  const std::filesystem::path file = directory / (name + ".npy");
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return std::nullopt;
  const std::filesystem::path json = directory / "transient.json";
  return readVolume(file, readLayout(json), json);
}

}  // namespace tofsim::pipeline
