#include "CaptureFile.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {

// The attributes of a dataset described by the JSON `text`: the text itself
// and the keys a reader looks for first.
std::vector<io::H5Attribute> attributesOf(const std::string& text) {
  std::vector<io::H5Attribute> a{{"json", text}};
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object()) return a;
  const auto strings = [&](const char* key, const char* name) {
    if (!j.contains(key) || !j.at(key).is_array()) return;
    std::vector<std::string> list;
    for (const nlohmann::json& s : j.at(key)) {
      if (s.is_string()) list.push_back(s.get<std::string>());
    }
    a.push_back({name, list});
  };
  for (const char* key : {"value_unit", "unit"}) {
    if (j.contains(key) && j.at(key).is_string()) {
      a.push_back({"units", j.at(key).get<std::string>()});
      break;
    }
  }
  strings("axes", "axes");
  strings("channels", "channels");
  if (j.contains("time") && j.at("time").is_object()) {
    const nlohmann::json& t = j.at("time");
    for (const char* key : {"start_s", "bin_width_s"}) {
      if (t.contains(key) && t.at(key).is_number()) a.push_back({key, t.at(key).get<double>()});
    }
    if (t.contains("bins") && t.at("bins").is_number_integer()) {
      a.push_back({"bins", t.at("bins").get<int64_t>()});
    }
  }
  return a;
}

std::string imageJson(const nlohmann::json& axes, const char* unit, const char* doc) {
  return nlohmann::json{{"axes", axes}, {"unit", unit}, {"doc", doc}}.dump(2);
}

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool endsWith(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The coordinates 0 .. n - 1.
std::vector<double> indices(std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<double>(i);
  return v;
}

std::vector<io::H5Attribute> scaleAttributes(const char* units, const char* longName) {
  return {{"units", std::string(units)}, {"long_name", std::string(longName)}};
}

}  // namespace

bool CaptureFile::pixelScales(std::size_t height, std::size_t width) {
  if (height_ == 0) {
    height_ = height;
    width_ = width;
    writer_.writeScale("y", indices(height), scaleAttributes("pixel", "image row, 0 at the top"));
    writer_.writeScale("x", indices(width),
                       scaleAttributes("pixel", "image column, 0 at the left"));
    std::vector<io::H5Attribute> c = scaleAttributes("1", "colour channel");
    c.push_back({"names", std::vector<std::string>{"R", "G", "B"}});
    writer_.writeScale("c", indices(capture::kChannels), c);
  }
  return height == height_ && width == width_;
}

void CaptureFile::attachScales(const std::string& dataset, std::size_t height, std::size_t width,
                               const std::vector<std::string>& more) {
  if (!pixelScales(height, width)) return;
  writer_.attachScale(dataset, 0, "y");
  writer_.attachScale(dataset, 1, "x");
  for (std::size_t a = 0; a < more.size(); ++a) {
    if (!more[a].empty()) writer_.attachScale(dataset, static_cast<unsigned>(2 + a), more[a]);
  }
}

class CaptureFile::VolumeSink : public capture::SegmentSink {
 public:
  VolumeSink(std::string dataset, std::string_view component, io::H5FloatStream& stream,
             std::size_t pixelFloats)
      : dataset_(std::move(dataset)),
        component_(component),
        stream_(stream),
        pixelFloats_(pixelFloats) {}
  std::size_t height = 0, width = 0;
  void consume(const capture::Segment& segment) override {
    stream_.append(segment.component(component_), segment.pixelCount * pixelFloats_);
  }
  const std::string& dataset() const { return dataset_; }

 private:
  std::string dataset_;
  std::string_view component_;
  io::H5FloatStream& stream_;
  std::size_t pixelFloats_;
};

CaptureFile::CaptureFile(const std::filesystem::path& file, int threads) : writer_(file, threads) {}

CaptureFile::~CaptureFile() = default;

capture::SegmentSink& CaptureFile::volume(const std::string& dataset, std::string_view component,
                                          int32_t width, int32_t height, int32_t bins) {
  const io::NpyShape shape{static_cast<std::size_t>(height), static_cast<std::size_t>(width),
                           static_cast<std::size_t>(bins), capture::kChannels};
  io::H5FloatStream& stream = writer_.stream(dataset, shape);
  volumes_.push_back(std::make_unique<VolumeSink>(dataset, component, stream, shape[2] * shape[3]));
  volumes_.back()->height = shape[0];
  volumes_.back()->width = shape[1];
  return *volumes_.back();
}

void CaptureFile::describeVolumes(const std::string& metadataJson) {
  // The t scale: each bin's leading edge, start_s + i bin_width_s.
  const nlohmann::json meta = nlohmann::json::parse(metadataJson, nullptr, false);
  if (timeJson_.empty() && meta.is_object() && meta.contains("time")) {
    const nlohmann::json& t = meta.at("time");
    const double start = t.value("start_s", 0.0), width = t.value("bin_width_s", 0.0);
    std::vector<double> edges(t.value("bins", std::size_t{0}));
    for (std::size_t i = 0; i < edges.size(); ++i)
      edges[i] = start + static_cast<double>(i) * width;
    writer_.writeScale("t", edges,
                       scaleAttributes("s",
                                       "arrival time at the bin's leading edge, from the "
                                       "light's impulse (transient.json: time)"));
    timeJson_ = t.dump();
  }
  for (const std::unique_ptr<VolumeSink>& v : volumes_) {
    std::vector<io::H5Attribute> a = attributesOf(metadataJson);
    a.push_back({"component", v->dataset()});
    writer_.setAttributes(v->dataset(), a);
    attachScales(v->dataset(), v->height, v->width, {timeJson_.empty() ? "" : "t", "c"});
  }
}

void CaptureFile::addSteady(const Image& steady) {
  writer_.write("steady",
                {static_cast<std::size_t>(steady.height), static_cast<std::size_t>(steady.width),
                 static_cast<std::size_t>(steady.channels)},
                steady.data.data());
  writer_.setAttributes(
      "steady", attributesOf(imageJson({"y", "x", "c"}, "W m^-2 sr^-1",
                                       "the transient summed over its time bins (steady.exr)")));
  attachScales("steady", steady.height, steady.width, {steady.channels == 3 ? "c" : ""});
}

void CaptureFile::addDepth(const Image& depth_m) {
  writer_.write("depth",
                {static_cast<std::size_t>(depth_m.height), static_cast<std::size_t>(depth_m.width)},
                depth_m.data.data());
  writer_.setAttributes(
      "depth", attributesOf(imageJson({"y", "x"}, "m",
                                      "camera-to-surface distance, 0 where a pixel sees no "
                                      "surface (depth.exr, depth.npy)")));
  attachScales("depth", depth_m.height, depth_m.width, {});
}

void CaptureFile::addSensorFiles(const std::filesystem::path& directory,
                                 const std::vector<std::string>& files) {
  for (const std::string& file : files) {
    const bool npy = endsWith(file, ".npy"), exr = endsWith(file, ".exr");
    if (!npy && !exr) continue;
    const std::string dataset = file.substr(0, file.size() - 4);  // sensors/<sensor>/<output>
    // An Image's numbers come twice (.exr and its .npy twin): one dataset.
    if (exr && std::find(files.begin(), files.end(), dataset + ".npy") != files.end()) continue;
    const std::filesystem::path path = directory / file;
    io::NpyShape shape;
    if (exr) {
      const Image image = io::readExr(path);
      shape = {static_cast<std::size_t>(image.height), static_cast<std::size_t>(image.width)};
      if (image.channels > 1) shape.push_back(static_cast<std::size_t>(image.channels));
      writer_.write(dataset, shape, image.data.data());
    } else {
      io::NpyStreamReader reader(path);
      shape = reader.shape();
      if (shape.size() < 3 || io::elementCount(shape) == 0) {
        std::vector<float> values(reader.remaining());
        reader.read(values.data(), values.size());
        writer_.write(dataset, shape, values.data());
      } else {  // perhaps a volume itself (a SPAD's histograms): a row at a time
        io::H5FloatStream& stream = writer_.stream(dataset, shape);
        std::vector<float> row(io::elementCount(shape) / shape[0]);
        while (reader.remaining() > 0) {
          reader.read(row.data(), row.size());
          stream.append(row.data(), row.size());
        }
      }
    }
    const std::filesystem::path json = directory / (dataset + ".json");
    std::error_code ec;
    if (std::filesystem::exists(json, ec)) {
      const std::string text = readText(json);
      writer_.setAttributes(dataset, attributesOf(text));
      attachSensorScales(dataset, shape, text);
    }
  }
}

// A sensor array's axes named y, x, t or c get the scale of that name where
// they have its length; t only where it is the render's own time axis (a
// sensor's instrument window of other bins keeps its axis unscaled).
void CaptureFile::attachSensorScales(const std::string& dataset, const io::NpyShape& shape,
                                     const std::string& jsonText) {
  const nlohmann::json j = nlohmann::json::parse(jsonText, nullptr, false);
  if (!j.is_object() || !j.contains("axes") || !j.at("axes").is_array() || height_ == 0) return;
  const nlohmann::json& axes = j.at("axes");
  if (axes.size() != shape.size()) return;
  bool sameTime = !timeJson_.empty() && j.contains("time") && j.at("time").is_object();
  if (sameTime) {
    const nlohmann::json render = nlohmann::json::parse(timeJson_), own = j.at("time");
    for (const char* key : {"start_s", "bin_width_s", "bins"}) {
      sameTime =
          sameTime && own.contains(key) && render.contains(key) && own.at(key) == render.at(key);
    }
  }
  for (std::size_t a = 0; a < axes.size(); ++a) {
    const bool scaled = (axes[a] == "y" && shape[a] == height_) ||
                        (axes[a] == "x" && shape[a] == width_) || (axes[a] == "t" && sameTime) ||
                        (axes[a] == "c" && shape[a] == capture::kChannels);
    if (scaled) writer_.attachScale(dataset, static_cast<unsigned>(a), axes[a].get<std::string>());
  }
}

void CaptureFile::commit() { writer_.commit(); }

}  // namespace tofsim::pipeline
