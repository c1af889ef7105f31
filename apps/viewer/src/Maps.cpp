// The page's maps: the ground-truth depth and every sensor map under
// sensors/<name>/ (each <output>.json says its kind, shape, axes and unit;
// its numbers are <output>.npy).

#include <algorithm>
#include <string>
#include <vector>

#include "Downsample.h"
#include "PackedArray.h"
#include "Sections.h"
#include "ViewerBudget.h"
#include "VolumeReducer.h"
#include "tofsim/io/FileBytes.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/OutputFileNames.h"
#include "tofsim/util/Error.h"

namespace tofsim::viewer {

namespace {

// A slice of an array shown as one map.
struct MapSource {
  std::string group, name, unit, description;
  std::vector<std::string> axes;
  std::size_t height = 0, width = 0;
  std::vector<float> values;
};

// A sensor array of axes (y, x, t) with its time axis: read once every
// output is listed, so the arrays share their budget.
struct HistogramSource {
  std::string sensor, name, unit;
  std::filesystem::path json, npy;
};

// Outputs of more slices than this show their first ones (a note says so).
constexpr std::size_t kMaxSlices = 8;

std::vector<std::filesystem::path> sortedEntries(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> entries;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    entries.push_back(entry.path());
  }
  std::sort(entries.begin(), entries.end());
  return entries;
}

// The maps of one sensor output: an image (y, x) or (y, x, c), or an array
// whose last two axes are y and x (one map per leading index). Anything else
// (histograms, raw sweeps) is listed in the notes, not drawn.
void addOutputMaps(const std::filesystem::path& json, const std::string& sensor,
                   std::vector<MapSource>& maps, std::vector<HistogramSource>& histograms,
                   nlohmann::json& page) {
  const nlohmann::json meta = readJsonFile(json);
  const std::string kind = textOf(meta, "kind");
  const std::string name = json.stem().string();
  std::filesystem::path npy = json;
  npy.replace_extension(".npy");
  std::error_code ec;
  if ((kind != "image" && kind != "array") || !std::filesystem::is_regular_file(npy, ec)) return;
  const std::vector<std::string> axes = stringList(meta, "axes");
  const bool yxLast = axes.size() >= 2 && axes[axes.size() - 2] == "y" && axes.back() == "x";
  const bool imageChannels = kind == "image" && axes.size() == 3;
  if (kind == "array" && axes == std::vector<std::string>{"y", "x", "t"} && meta.contains("time")) {
    histograms.push_back({sensor, name, textOf(meta, "unit"), json, npy});
    return;
  }
  if (!(kind == "image" && axes.size() == 2) && !yxLast && !imageChannels) {
    page["notes"].push_back("sensors/" + sensor + "/" + name + ".npy (" + kind + ", axes " +
                            nlohmann::json(axes).dump() + ") is not drawn: not a y-x map");
    return;
  }
  const io::NpyArray array = io::readNpy(npy);
  if (array.shape.size() != axes.size() || array.shape.size() < 2) {
    throw InputError(FileLoc{npy.string()}, "",
                     "shape " + nlohmann::json(array.shape).dump() + " does not match the " +
                         std::to_string(axes.size()) + " axes of " + json.filename().string());
  }
  // Slices: the leading index of a y-x array, or the channel of an image.
  const std::size_t height = array.shape[imageChannels ? 0 : array.shape.size() - 2];
  const std::size_t width = array.shape[imageChannels ? 1 : array.shape.size() - 1];
  if (height * width == 0) {
    page["notes"].push_back("sensors/" + sensor + "/" + name + ".npy is empty: not drawn");
    return;
  }
  const std::size_t slices = array.data.size() / (height * width);
  const std::size_t shown = std::min(slices, kMaxSlices);
  if (shown < slices) {
    page["notes"].push_back("sensors/" + sensor + "/" + name + ".npy: the first " +
                            std::to_string(shown) + " of its " + std::to_string(slices) +
                            " maps are drawn");
  }
  for (std::size_t s = 0; s < shown; ++s) {
    MapSource map{sensor,
                  name,
                  textOf(meta, "unit"),
                  textOf(meta, "description"),
                  {axes[axes.size() - 2], axes.back()},
                  height,
                  width,
                  std::vector<float>(height * width)};
    if (imageChannels) map.axes = {axes[0], axes[1]};
    for (std::size_t i = 0; i < height * width; ++i) {
      map.values[i] =
          imageChannels ? array.data[i * slices + s] : array.data[s * height * width + i];
    }
    if (slices > 1) map.name += "[" + std::to_string(s) + "]";
    maps.push_back(std::move(map));
  }
}

// Each (y, x, t) array as a volume of one channel, the arrays sharing
// kHistogramsValues.
void addHistograms(const std::vector<HistogramSource>& sources, nlohmann::json& page) {
  page["histograms"] = nlohmann::json::array();
  for (const HistogramSource& source : sources) {
    const nlohmann::json meta = readJsonFile(source.json);
    const nlohmann::json& time = timeOf(meta, source.json);
    const io::NpyArray array = io::readNpy(source.npy);
    if (array.shape.size() != 3) {
      throw InputError(FileLoc{source.npy.string()}, "",
                       "shape " + nlohmann::json(array.shape).dump() + " is not the (y, x, t) of " +
                           source.json.filename().string());
    }
    const std::size_t height = array.shape[0], width = array.shape[1], bins = array.shape[2];
    VolumeReducer reducer(height, width, bins, 1, kHistogramsValues / sources.size());
    for (std::size_t p = 0; p < height * width; ++p) {
      reducer.addPixel(p / width, p % width, array.data.data() + p * bins);
    }
    nlohmann::json entry = volumeEntry(reducer, time, bins, {source.name});
    entry["label"] = source.sensor + "/" + source.name;
    entry["unit"] = source.unit;
    const Reduction& r = reducer.reduction();
    if (r.pixelBlock > 1 || r.binRun > 1) {
      page["notes"].push_back(entry["label"].get<std::string>() + ": pixels averaged over " +
                              std::to_string(r.pixelBlock) + " x " + std::to_string(r.pixelBlock) +
                              " blocks, " + std::to_string(r.binRun) +
                              " bins summed into one, to fit the page");
    }
    page["histograms"].push_back(std::move(entry));
  }
}

}  // namespace

nlohmann::json readJsonFile(const std::filesystem::path& path) {
  const std::string text = io::readFileNoFollow(path, std::size_t{64} << 20);
  nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  if (json.is_discarded() || !json.is_object()) {
    throw InputError(FileLoc{path.string()}, "", "not a JSON object (a tofsim output's metadata)");
  }
  return json;
}

std::string textOf(const nlohmann::json& meta, const char* key) {
  const auto it = meta.find(key);
  return it != meta.end() && it->is_string() ? it->get<std::string>() : std::string();
}

std::vector<std::string> stringList(const nlohmann::json& meta, const char* key) {
  const auto it = meta.find(key);
  if (it == meta.end() || !it->is_array()) return {};
  std::vector<std::string> out;
  for (const auto& v : *it) out.push_back(v.is_string() ? v.get<std::string>() : v.dump());
  return out;
}

nlohmann::json makeMap(const std::string& group, const std::string& name, const std::string& unit,
                       const std::string& description, const std::vector<std::string>& axes,
                       std::size_t height, std::size_t width, const std::vector<float>& values,
                       std::size_t budget) {
  const std::size_t block = planPixelBlock(height, width, 1, budget);
  nlohmann::json map = packUint16(blockMean(values, height, width, 1, block));
  map["group"] = group;
  map["name"] = name;
  map["unit"] = unit;
  map["description"] = description;
  map["axes"] = axes;
  map["h"] = reducedSize(height, block);
  map["w"] = reducedSize(width, block);
  map["pixel_block"] = block;
  return map;
}

void addMaps(const std::filesystem::path& folder, nlohmann::json& page) {
  std::vector<MapSource> maps;
  std::vector<HistogramSource> histograms;
  std::error_code ec;
  const std::filesystem::path depth = folder / pipeline::files::kDepthNpy;
  if (std::filesystem::is_regular_file(depth, ec)) {
    io::NpyArray d = io::readNpy(depth);
    if (d.shape.size() == 2) {
      maps.push_back({"render",
                      "depth",
                      "m",
                      "ground-truth distance, camera to surface (0: none)",
                      {"y", "x"},
                      d.shape[0],
                      d.shape[1],
                      std::move(d.data)});
    }
  }
  const std::filesystem::path sensors = folder / "sensors";
  if (std::filesystem::is_directory(sensors, ec)) {
    for (const auto& sensor : sortedEntries(sensors)) {
      if (!std::filesystem::is_directory(sensor, ec)) continue;
      for (const auto& file : sortedEntries(sensor)) {
        if (file.extension() == ".json") {
          addOutputMaps(file, sensor.filename().string(), maps, histograms, page);
        }
      }
    }
  }
  // Counts bounded too: each map and histogram adds its labels to the page.
  if (maps.size() > kMaxMaps) {
    page["notes"].push_back(std::to_string(maps.size()) + " maps: the first " +
                            std::to_string(kMaxMaps) + " are drawn");
    maps.resize(kMaxMaps);
  }
  if (histograms.size() > kMaxHistograms) {
    page["notes"].push_back(std::to_string(histograms.size()) + " (y, x, t) arrays: the first " +
                            std::to_string(kMaxHistograms) + " are plotted");
    histograms.resize(kMaxHistograms);
  }
  // Every map gets an equal share of the maps' budget, at most kMapValues.
  const std::size_t share =
      maps.empty() ? kMapValues : std::min(kMapValues, kMapsValues / maps.size());
  page["maps"] = nlohmann::json::array();
  for (const MapSource& m : maps) {
    nlohmann::json map =
        makeMap(m.group, m.name, m.unit, m.description, m.axes, m.height, m.width, m.values, share);
    if (map["pixel_block"].get<std::size_t>() > 1) {
      page["notes"].push_back(m.group + "/" + m.name + ": pixels averaged over " +
                              map["pixel_block"].dump() + " x " + map["pixel_block"].dump() +
                              " blocks to fit the page");
    }
    page["maps"].push_back(std::move(map));
  }
  addHistograms(histograms, page);
}

}  // namespace tofsim::viewer
