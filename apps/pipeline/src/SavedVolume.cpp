#include "tofsim/pipeline/SavedVolume.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tofsim/io/DepthExr.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Hdf5Capture.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/OutputFileNames.h"
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

bool fileExists(const std::filesystem::path& file) {
  std::error_code ec;
  return std::filesystem::exists(file, ec);
}

std::filesystem::path capturePath(const std::filesystem::path& directory) {
  return directory / files::kCapture;
}

// A render's negative values are round-off, far below this share of their
// pixel's light, its values summed: the footprint integrals are differences
// of nearly equal sums (cornell_box, 32 x 32 x 640: at most 2.2e-15 on the
// GL backend, llvmpipe; 16 x 16 x 256 on the CPU backend: 2.4e-14).
constexpr float kNegativeRoundOff = 1e-5f;

/// Throws an InputError naming `file` and the first of `count` values (a run
/// of whole pixels from `firstPixel` of an (H, W, T, C) volume) that is no
/// radiance: NaN, infinite, or negative past round-off. A render writes none
/// (a NaN becomes 0, transient.json's stats.rejected_non_finite_values); read
/// back, one would make every sensor count and comparison NaN or 0 without
/// a word.
void checkRadiance(const std::filesystem::path& file, const io::NpyShape& shape,
                   std::size_t firstPixel, const float* values, std::size_t count) {
  const std::size_t perPixel = shape[2] * shape[3];
  for (std::size_t start = 0; start < count; start += perPixel) {
    const float* pixel = values + start;
    bool finite = true;  // one branch-free pass over the pixel, at memory speed
    float lo = 0.0f, light = 0.0f;
    for (std::size_t i = 0; i < perPixel; ++i) {
      finite &= std::isfinite(pixel[i]);
      lo = std::min(lo, pixel[i]);
      light += pixel[i] > 0.0f ? pixel[i] : 0.0f;  // NaN adds nothing: `finite` has it
    }
    const float floor = -kNegativeRoundOff * light;
    if (finite && lo >= floor) continue;
    for (std::size_t i = 0; i < perPixel; ++i) {
      const float v = pixel[i];
      if (std::isfinite(v) && v >= floor) continue;
      const std::size_t at = firstPixel + start / perPixel;
      char text[64];
      std::snprintf(text, sizeof text, "%g", static_cast<double>(v));
      fail(file, std::string("value ") + text + " at (y, x, bin, channel) = (" +
                     std::to_string(at / shape[1]) + ", " + std::to_string(at % shape[1]) + ", " +
                     std::to_string(i / shape[3]) + ", " + std::to_string(i % shape[3]) + ") is " +
                     (std::isfinite(v) ? "negative" : "not finite") +
                     ": a saved volume holds radiance, finite and >= 0");
    }
  }
}

}  // namespace

namespace detail {

/// One saved volume read a run of pixels at a time, in order.
class ComponentReader {
 public:
  virtual ~ComponentReader() = default;
  /// For messages: the .npy, or capture.h5:/<dataset>.
  virtual std::filesystem::path name() const = 0;
  virtual const io::NpyShape& shape() const = 0;
  /// The values of `pixels` pixels from `firstPixel` on; an InputError at
  /// the first that is no radiance (checked as each run is read, so a volume
  /// read out of core is not read twice).
  void read(std::size_t firstPixel, std::size_t pixels, float* out) {
    readValues(firstPixel, pixels, out);
    const io::NpyShape& s = shape();  // (H, W, T, C), checked before any read
    checkRadiance(name(), s, firstPixel, out, pixels * s[2] * s[3]);
  }

 private:
  virtual void readValues(std::size_t firstPixel, std::size_t pixels, float* out) = 0;
};

}  // namespace detail

namespace {

class NpyComponent : public detail::ComponentReader {
 public:
  explicit NpyComponent(const std::filesystem::path& file) : file_(file), reader_(file) {}
  std::filesystem::path name() const override { return file_; }
  const io::NpyShape& shape() const override { return reader_.shape(); }
  void readValues(std::size_t, std::size_t pixels, float* out) override {
    const io::NpyShape& s = reader_.shape();
    reader_.read(out, pixels * (io::elementCount(s) / (s[0] * s[1])));
  }

 private:
  std::filesystem::path file_;
  io::NpyStreamReader reader_;
};

class H5Component : public detail::ComponentReader {
 public:
  H5Component(std::shared_ptr<const io::H5CaptureReader> file, std::string dataset)
      : file_(std::move(file)), dataset_(std::move(dataset)), shape_(file_->shape(dataset_)) {}
  std::filesystem::path name() const override { return file_->path().string() + ":/" + dataset_; }
  const io::NpyShape& shape() const override { return shape_; }
  void readValues(std::size_t firstPixel, std::size_t pixels, float* out) override {
    file_->readPixels(dataset_, firstPixel, pixels, out);
  }

 private:
  std::shared_ptr<const io::H5CaptureReader> file_;
  std::string dataset_;
  io::NpyShape shape_;
};

// The folder's saved volumes: its capture.h5 when it has one, else its .npy files.
class SavedFolder {
 public:
  explicit SavedFolder(const std::filesystem::path& directory) : directory_(directory) {
    if (fileExists(capturePath(directory))) {
      capture_ = std::make_shared<const io::H5CaptureReader>(capturePath(directory));
    }
  }
  bool has(const std::string& component) const {
    return capture_ ? capture_->has(component) : fileExists(directory_ / (component + ".npy"));
  }
  std::filesystem::path name(const std::string& component) const {
    return capture_ ? std::filesystem::path(capture_->path().string() + ":/" + component)
                    : directory_ / (component + ".npy");
  }
  /// InputError naming it when it is not there.
  std::unique_ptr<detail::ComponentReader> open(const std::string& component) const {
    if (!has(component)) {
      throw InputError(FileLoc{name(component).string()}, "", "not found");
    }
    if (capture_) return std::make_unique<H5Component>(capture_, component);
    return std::make_unique<NpyComponent>(directory_ / (component + ".npy"));
  }

 private:
  std::filesystem::path directory_;
  std::shared_ptr<const io::H5CaptureReader> capture_;
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

// Throws unless the .npy's shape is (H, W, bins, C) with the JSON's bins and
// channels; returns the channel names (the JSON's, or C0, C1, ...).
std::vector<std::string> checkedChannels(const std::filesystem::path& file, const io::NpyShape& s,
                                         const VolumeLayout& layout,
                                         const std::filesystem::path& jsonFile) {
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
  return channels;
}

TransientVolume readVolume(const SavedFolder& folder, const std::string& component,
                           const VolumeLayout& layout, const std::filesystem::path& jsonFile) {
  const std::unique_ptr<detail::ComponentReader> reader = folder.open(component);
  const io::NpyShape s = reader->shape();
  std::vector<std::string> channels = checkedChannels(reader->name(), s, layout, jsonFile);
  TransientVolume volume(static_cast<int32_t>(s[1]), static_cast<int32_t>(s[0]), layout.axis,
                         std::move(channels));
  reader->read(0, s[0] * s[1], volume.values().data());
  return volume;
}

// depth.exr when present, one channel of W x H.
std::optional<Image> readDepth(const std::filesystem::path& directory, int32_t W, int32_t H) {
  const std::filesystem::path depthFile = directory / files::kDepthExr;
  std::error_code ec;
  if (!std::filesystem::exists(depthFile, ec)) return std::nullopt;
  Image depth = io::readDepthExr(depthFile);
  if (depth.channels != 1 || depth.width != W || depth.height != H) {
    fail(depthFile, "expected one channel of " + std::to_string(W) + "x" + std::to_string(H) +
                        " (got " + std::to_string(depth.channels) + " of " +
                        std::to_string(depth.width) + "x" + std::to_string(depth.height) + ")");
  }
  return depth;
}

}  // namespace

bool hasSavedComponent(const std::filesystem::path& directory, const std::string& component) {
  return SavedFolder(directory).has(component);
}

std::string savedComponentName(const std::filesystem::path& directory,
                               const std::string& component) {
  return SavedFolder(directory).name(component).string();
}

SavedVolume loadSavedVolume(const std::filesystem::path& directory) {
  const std::filesystem::path json = directory / files::kMetadata;
  const VolumeLayout layout = readLayout(json);
  const SavedFolder folder(directory);
  SavedVolume saved{readVolume(folder, "transient", layout, json), {}, {}};
  const int32_t W = saved.volume.width(), H = saved.volume.height();
  if (folder.has("direct")) {
    saved.directOnly = readVolume(folder, "direct", layout, json);
    if (saved.directOnly->width() != W || saved.directOnly->height() != H ||
        saved.directOnly->channels() != saved.volume.channels()) {
      fail(folder.name("direct"), "shape differs from the transient");
    }
  }
  saved.depth_m = readDepth(directory, W, H);
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

SavedVolumeStream::SavedVolumeStream(const std::filesystem::path& directory,
                                     const std::vector<std::string>& components) {
  const std::filesystem::path json = directory / files::kMetadata;
  const VolumeLayout layout = readLayout(json);
  const SavedFolder folder(directory);
  const auto open = [&](const std::string& component) {
    std::unique_ptr<detail::ComponentReader> reader = folder.open(component);
    const std::vector<std::string> channels =
        checkedChannels(reader->name(), reader->shape(), layout, json);
    return std::make_pair(std::move(reader), channels.size());
  };
  auto [volume, channels] = open("transient");
  const io::NpyShape s = volume->shape();
  shape_.height = static_cast<int32_t>(s[0]);
  shape_.width = static_cast<int32_t>(s[1]);
  shape_.channels = static_cast<int32_t>(channels);
  shape_.axis = layout.axis;
  files_.push_back({"transient", std::move(volume), {}});
  for (const std::string& name : components) {
    if (!folder.has(name)) continue;
    auto component = open(name).first;
    if (component->shape() != s) fail(component->name(), "shape differs from the transient");
    files_.push_back({name, std::move(component), {}});
  }
  depth_m_ = readDepth(directory, shape_.width, shape_.height);
}

SavedVolumeStream::~SavedVolumeStream() = default;

bool SavedVolumeStream::has(const std::string& component) const {
  for (const File& f : files_) {
    if (f.name == component) return true;
  }
  return false;
}

std::size_t SavedVolumeStream::read(std::size_t maxPixels) {
  TOFSIM_CHECK(maxPixels >= 1);
  const std::size_t pixels = std::min(maxPixels, shape_.pixelCount() - next_);
  firstPixel_ = next_;
  for (File& f : files_) {
    f.values.resize(pixels * shape_.pixelFloats());
    f.reader->read(next_, pixels, f.values.data());
  }
  next_ += pixels;
  return pixels;
}

const float* SavedVolumeStream::values(const std::string& component) const {
  for (const File& f : files_) {
    if (f.name == component) return f.values.data();
  }
  return nullptr;
}

std::optional<TransientVolume> loadSavedComponent(const std::filesystem::path& directory,
                                                  const std::string& name) {
  const SavedFolder folder(directory);
  if (!folder.has(name)) return std::nullopt;
  const std::filesystem::path json = directory / files::kMetadata;
  return readVolume(folder, name, readLayout(json), json);
}

}  // namespace tofsim::pipeline
