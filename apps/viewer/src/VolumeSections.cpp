// The page's volume and image: a camera's transient (streamed a run of pixels
// at a time: never held whole), an NLOS capture's H or a lidar's waveforms
// (with its range and intensity images).

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "PackedArray.h"
#include "Sections.h"
#include "ViewerBudget.h"
#include "VolumeReducer.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/OutputFileNames.h"
#include "tofsim/pipeline/SavedVolume.h"
#include "tofsim/util/Error.h"

namespace tofsim::viewer {

namespace {

bool isFile(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

nlohmann::json imageEntry(const VolumeReducer& reducer, std::size_t channels,
                          const std::string& label) {
  const std::size_t block =
      planPixelBlock(reducer.height(), reducer.width(), channels, kImageValues);
  nlohmann::json image =
      packFloat16(blockMean(reducer.timeSum(), reducer.height(), reducer.width(), channels, block));
  image["label"] = label;
  image["h"] = reducedSize(reducer.height(), block);
  image["w"] = reducedSize(reducer.width(), block);
  image["channels"] = channels;
  image["pixel_block"] = block;
  return image;
}

void noteReduction(const VolumeReducer& reducer, const std::string& what, nlohmann::json& page) {
  const Reduction& r = reducer.reduction();
  if (r.pixelBlock == 1 && r.binRun == 1) return;
  page["notes"].push_back(what + " downsampled to fit the page (" +
                          std::to_string(kVolumeValues >> 20) +
                          " Mi values): pixels averaged over " + std::to_string(r.pixelBlock) +
                          " x " + std::to_string(r.pixelBlock) + " blocks, " +
                          std::to_string(r.binRun) + " bins summed into one");
}

// A lidar's image `name`.npy (rings x azimuths; the first return's where it
// holds one per return), if the folder has one.
void addLidarMap(const std::filesystem::path& folder, const std::string& name,
                 const std::string& unit, const std::string& description, nlohmann::json& page) {
  const std::filesystem::path path = folder / (name + ".npy");
  if (!isFile(path)) return;
  const io::NpyArray a = io::readNpy(path);
  if (a.shape.size() < 2 || a.shape[0] * a.shape[1] == 0) {
    throw InputError(FileLoc{path.string()}, "", "a lidar image has axes (rings, azimuths)");
  }
  const std::size_t rings = a.shape[0], azimuths = a.shape[1];
  std::vector<float> first(rings * azimuths);
  const std::size_t stride = a.data.size() / first.size();
  for (std::size_t i = 0; i < first.size(); ++i) first[i] = a.data[i * stride];
  page["lidars"].push_back(makeMap("lidar", name, unit, description, {"ring", "azimuth"}, rings,
                                   azimuths, first, kMapValues));
}

}  // namespace

const nlohmann::json& timeOf(const nlohmann::json& meta, const std::filesystem::path& file) {
  const auto time = meta.find("time");
  bool numbers = time != meta.end() && time->is_object();
  for (const char* key : {"start_s", "bin_width_s", "start_m", "bin_width_m"}) {
    numbers = numbers && time->contains(key) && (*time)[key].is_number();
  }
  if (!numbers) {
    throw InputError(FileLoc{file.string()}, "time",
                     "no time axis (numbers start_s, bin_width_s, start_m, bin_width_m)");
  }
  return *time;
}

// The volume's entry: its reduced values and the axis of its merged bins.
nlohmann::json volumeEntry(const VolumeReducer& reducer, const nlohmann::json& time,
                           std::size_t bins, const std::vector<std::string>& channels) {
  const auto run = static_cast<double>(reducer.reduction().binRun);
  nlohmann::json v = packFloat16(reducer.reduced());
  v["full"] = {reducer.height(), reducer.width(), bins};
  v["h"] = reducer.reducedHeight();
  v["w"] = reducer.reducedWidth();
  v["bins"] = reducer.reducedBins();
  v["channels"] = channels;
  v["pixel_block"] = reducer.reduction().pixelBlock;
  v["bin_run"] = reducer.reduction().binRun;
  v["start_s"] = time["start_s"];
  v["bin_width_s"] = time["bin_width_s"].get<double>() * run;
  v["start_m"] = time["start_m"];
  v["bin_width_m"] = time["bin_width_m"].get<double>() * run;
  return v;
}

namespace {

// What a volume section shows beside its reduced values.
struct VolumeSection {
  const char* kind;                   // the page's kind: "camera", "nlos", "lidar"
  std::string label;                  // the volume's name on the page
  std::vector<std::string> axes;      // its image's rows and columns
  std::string source;                 // the file it was read from
  std::vector<std::string> channels;  // one name each
  std::string imageLabel;             // the image: the volume summed over time
  std::string reduced;                // "The transient", "H", ...: in the reduction note
};

// The section's volume, its image and the note of what was merged, into the page.
void setVolume(const VolumeReducer& reducer, const nlohmann::json& meta, const nlohmann::json& time,
               std::size_t bins, const VolumeSection& section, nlohmann::json& page) {
  nlohmann::json volume = volumeEntry(reducer, time, bins, section.channels);
  volume["label"] = section.label;
  volume["unit"] = textOf(meta, "value_unit");
  volume["axes"] = section.axes;
  volume["source"] = section.source;
  page["kind"] = section.kind;
  page["volume"] = std::move(volume);
  page["image"] = imageEntry(reducer, section.channels.size(), section.imageLabel);
  noteReduction(reducer, section.reduced, page);
}

// An NLOS or lidar capture: its metadata `json` (with the time axis) and the
// array `npy` beside it; none when the folder has no `json`.
struct SavedArray {
  nlohmann::json meta;
  nlohmann::json time;
  std::filesystem::path path;  // of the array
  io::NpyArray array;
};

std::optional<SavedArray> readSavedArray(const std::filesystem::path& folder, const char* json,
                                         const char* npy) {
  const std::filesystem::path metaPath = folder / json;
  if (!isFile(metaPath)) return std::nullopt;
  SavedArray saved;
  saved.meta = readJsonFile(metaPath);
  saved.time = timeOf(saved.meta, metaPath);
  saved.path = folder / npy;
  saved.array = io::readNpy(saved.path);
  return saved;
}

}  // namespace

bool addCameraVolume(const std::filesystem::path& folder, nlohmann::json& page) {
  const std::filesystem::path metaPath = folder / pipeline::files::kMetadata;
  if (!isFile(metaPath)) return false;
  pipeline::SavedVolumeStream stream(folder, {});  // checks transient.json against the volume
  const nlohmann::json meta = readJsonFile(metaPath);
  const nlohmann::json& time = timeOf(meta, metaPath);
  const sensors::VolumeShape& shape = stream.shape();
  const auto height = static_cast<std::size_t>(shape.height);
  const auto width = static_cast<std::size_t>(shape.width);
  const auto bins = static_cast<std::size_t>(shape.axis.bins);
  const auto channels = static_cast<std::size_t>(shape.channels);
  VolumeReducer reducer(height, width, bins, channels, kVolumeValues);
  while (const std::size_t run = stream.read(std::max<std::size_t>(width, 1))) {
    const float* values = stream.values("transient");
    for (std::size_t i = 0; i < run; ++i) {
      const std::size_t p = stream.firstPixel() + i;
      reducer.addPixel(p / width, p % width, values + i * bins * channels);
    }
  }
  std::vector<std::string> names = stringList(meta, "channels");
  names.resize(channels);
  setVolume(reducer, meta, time, bins,
            {"camera", "transient", {"y", "x"}, pipeline::savedComponentName(folder, "transient"),
             names, "steady (the transient summed over time)", "The transient"},
            page);
  return true;
}

bool addNlosVolume(const std::filesystem::path& folder, nlohmann::json& page) {
  const std::optional<SavedArray> saved = readSavedArray(folder, "H.json", "H.npy");
  if (!saved) return false;
  const io::NpyArray& h = saved->array;
  if (h.shape.size() != 3 && h.shape.size() != 5) {
    throw InputError(FileLoc{saved->path.string()}, "",
                     "H has " + std::to_string(h.shape.size()) +
                         " axes; an NLOS capture's has 3 (t, sx, sy) or 5 (t, lx, ly, sx, sy)");
  }
  const std::size_t bins = h.shape[0], sx = h.shape[h.shape.size() - 2], sy = h.shape.back();
  const std::size_t lasers = h.shape.size() == 5 ? h.shape[1] * h.shape[2] : 1;
  VolumeReducer reducer(sx, sy, bins, 1, kVolumeValues);
  std::vector<float> histogram(bins);
  for (std::size_t x = 0; x < sx; ++x) {
    for (std::size_t y = 0; y < sy; ++y) {
      std::fill(histogram.begin(), histogram.end(), 0.0f);
      for (std::size_t t = 0; t < bins; ++t) {
        for (std::size_t l = 0; l < lasers; ++l)
          histogram[t] += h.data[((t * lasers + l) * sx + x) * sy + y];
      }
      reducer.addPixel(x, y, histogram.data());
    }
  }
  setVolume(reducer, saved->meta, saved->time, bins,
            {"nlos", lasers > 1 ? "H (the laser points summed)" : "H", {"sx", "sy"}, "H.npy",
             {"H"}, "H summed over time (rows sx, columns sy)", "H"},
            page);
  return true;
}

bool addLidarVolume(const std::filesystem::path& folder, nlohmann::json& page) {
  const std::optional<SavedArray> saved = readSavedArray(folder, "lidar.json", "waveforms.npy");
  if (!saved) return false;
  const io::NpyArray& w = saved->array;
  if (w.shape.size() != 3) {
    throw InputError(FileLoc{saved->path.string()}, "",
                     "a lidar's waveforms have 3 axes (rings, azimuths, t), not " +
                         std::to_string(w.shape.size()));
  }
  const std::size_t rings = w.shape[0], azimuths = w.shape[1], bins = w.shape[2];
  VolumeReducer reducer(rings, azimuths, bins, 1, kVolumeValues);
  for (std::size_t r = 0; r < rings; ++r) {
    for (std::size_t a = 0; a < azimuths; ++a) {
      reducer.addPixel(r, a, w.data.data() + (r * azimuths + a) * bins);
    }
  }
  setVolume(reducer, saved->meta, saved->time, bins,
            {"lidar", "waveforms", {"ring", "azimuth"}, "waveforms.npy", {"waveform"},
             "the waveforms summed over time (rows rings, columns azimuths)", "The waveforms"},
            page);
  addLidarMap(folder, "range", "m", "the first return's range (0: none)", page);
  addLidarMap(folder, "intensity", textOf(saved->meta, "value_unit"),
              "the first return's intensity", page);
  addLidarMap(folder, "zone_distance", "m",
              "a multizone sensor's own per-zone distance (its on-chip estimate; 0: no light)",
              page);
  return true;
}

}  // namespace tofsim::viewer
