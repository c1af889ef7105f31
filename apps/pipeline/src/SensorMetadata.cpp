#include "tofsim/pipeline/SensorMetadata.h"

#include <nlohmann/json.hpp>

#include "SensorParametersJson.h"
#include "tofsim/pipeline/Version.h"
#include "tofsim/sensors/RunSensor.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {
using json = nlohmann::ordered_json;
using sensors::SensorOutput;

const char* kindName(SensorOutput::Kind kind) {
  switch (kind) {
    case SensorOutput::Kind::Array:
      return "array";
    case SensorOutput::Kind::Image:
      return "image";
    case SensorOutput::Kind::ColorMappedImage:
      return "color_mapped_image";
    case SensorOutput::Kind::HistogramPlot:
      return "histogram_plot";
  }
  return "array";
}

bool isPicture(const SensorOutput& o) {
  return o.kind == SensorOutput::Kind::ColorMappedImage ||
         o.kind == SensorOutput::Kind::HistogramPlot;
}

std::string axisDoc(const std::string& axis) {
  if (axis == "y") return "image row, 0 = top";
  if (axis == "x") return "image column, 0 = left";
  if (axis == "t") return "time bin of `time` (see time.bin_doc)";
  if (axis == "frequency") return "index into sensor.parameters.frequencies_Hz";
  if (axis == "phase_step")
    return "phase step k, reference phase 2 pi k / sensor.parameters.phase_steps";
  if (axis == "capture_index")
    return "raw i as the device takes it: sensor.parameters.capture.order[i] is its [frequency, "
           "phase_step]";
  if (axis == "tap") return "tap: 0 = A (reference phase theta), 1 = B (theta + pi)";
  if (axis == "pixel") return "index into `labels` (the pixel each series shows)";
  if (axis == "order") return "bounce order k: the light of direct + indirect bounces 1..k";
  if (axis == "sweep")
    return "sweep point j: a single return at (j + 0.5) / attributes.sweep_points of the "
           "frequency's unambiguous range";
  if (axis == "gate")
    return "gate position k: the gate moved by k sensor.parameters.gate_step_s from gate_start_s";
  if (axis == "return") return "echo index of an APD pixel, in time order (NaN: no echo)";
  TOFSIM_CHECK_MSG(false, "undocumented sensor output axis " + axis);
  return "";
}

json sensorJson(const SensorRunInfo& run) {
  json j = {{"name", run.spec->name},
            {"type", sensors::sensorTypeName(run.spec->params)},
            {"seed", run.seed},
            {"parameters", sensorParametersJson(run.spec->params, run.render)},
            {"render_time", timeAxisJson(run.render)},
            {"warnings", run.warnings}};
  if (!run.sampleTimes_s.empty()) {
    j["sample_times_s"] = run.sampleTimes_s;
    j["sample_times_doc"] =
        "a frame of a capture sequence: the times after the frame's time, s, the sensor took the "
        "scene's light at (SensorStream::sampleTimes_s: CW-ToF each raw's exposure samples in "
        "[f][n] order, S per raw; SPAD its exposure's; a scanning streak camera each recorded "
        "row's)";
  }
  return j;
}

// The numbers' description: from the data output, or the picture when the
// name has no data (a histogram plot).
json describe(const SensorOutput& o) {
  TOFSIM_CHECK_MSG(o.axes.size() == o.shape.size(), o.name + ": one axis name per dimension");
  json j;
  j["kind"] = kindName(o.kind);
  j["dtype"] = "float32";
  j["shape"] = o.shape;
  j["axes"] = o.axes;
  json docs = json::object();
  for (const std::string& a : o.axes) docs[a] = axisDoc(a);
  j["axes_doc"] = docs;
  j["order"] = "C (row-major): the last axis varies fastest";
  j["unit"] = o.unit;
  j["description"] = o.description;
  j["signed"] = o.signed_values;
  j["nan_doc"] = "NaN where the value is undefined (no detection, no ground truth)";
  if (o.time) j["time"] = timeAxisJson(*o.time);
  json attributes = json::object();
  for (const auto& [key, value] : o.attributes) attributes[key] = value;
  j["attributes"] = attributes;
  if (o.kind == SensorOutput::Kind::Image) {
    j["exr_channels"] = o.shape.size() == 2 ? json{"Y"} : json{};
    j["exr_doc"] = "EXR rows are the first axis, columns the second";
  }
  if (!o.labels.empty()) j["labels"] = o.labels;
  return j;
}

json pictureJson(const SensorOutput& o, const std::map<std::string, PictureRange>& ranges) {
  json j = {{"kind", kindName(o.kind)}};
  if (!o.colormap.empty()) j["colormap"] = o.colormap;
  const auto it = ranges.find(o.name);
  if (it != ranges.end()) {
    const PictureRange& r = it->second;
    j["range"] = {{"lo", r.lo},
                  {"hi", r.hi},
                  {"unit", o.unit},
                  {"source", r.automatic ? "automatic" : r.bySensor ? "sensor" : "output.plot_ranges"},
                  {"clipped_low", r.clippedLow},
                  {"clipped_high", r.clippedHigh}};
    if (r.automatic) {
      j["range"]["lo_percentile"] = r.loPercentile;
      j["range"]["hi_percentile"] = r.hiPercentile;
    }
  }
  return j;
}
}  // namespace

std::string sensorFileName(const SensorOutput& o) {
  switch (o.kind) {
    case SensorOutput::Kind::Array:
      return o.name + ".npy";
    case SensorOutput::Kind::Image:
      return o.name + ".exr";
    case SensorOutput::Kind::ColorMappedImage:
    case SensorOutput::Kind::HistogramPlot:
      return o.name + ".png";
  }
  return o.name;
}

std::string sensorArrayFileName(const SensorOutput& o) { return o.name + ".npy"; }

std::vector<NamedMetadata> sensorMetadata(const SensorRunInfo& run,
                                          const std::vector<SensorOutput>& outputs, bool files,
                                          const std::map<std::string, PictureRange>& ranges) {
  TOFSIM_CHECK(run.spec != nullptr);
  std::vector<std::string> order;
  std::vector<json> docs;
  for (const SensorOutput& o : outputs) {
    std::size_t i = 0;
    while (i < order.size() && order[i] != o.name) ++i;
    if (i == order.size()) {
      // The first output of a name describes the numbers: the data output
      // (an Image precedes its ColorMappedImage), or a plot that has none.
      order.push_back(o.name);
      json doc = {{"format", "tofsim sensor output"},
                  {"tofsim_version", kVersion},
                  {"name", o.name},
                  {"sensor", sensorJson(run)}};
      doc.update(describe(o));
      docs.push_back(std::move(doc));
    }
    json& doc = docs[i];
    if (isPicture(o)) doc["picture"] = pictureJson(o, ranges);
    if (files) doc["files"][isPicture(o) ? "picture" : "data"] = sensorFileName(o);
    if (files && o.kind == SensorOutput::Kind::Image) doc["files"]["npy"] = sensorArrayFileName(o);
    if (files && run.camera && o.kind == SensorOutput::Kind::Image && o.point_cloud) {
      doc["files"]["point_cloud"] = o.name + ".ply";
    }
  }
  std::vector<NamedMetadata> result;
  for (std::size_t i = 0; i < order.size(); ++i)
    result.push_back({order[i], docs[i].dump(2) + "\n"});
  return result;
}

}  // namespace tofsim::pipeline
