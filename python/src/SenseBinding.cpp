// _sense: one sensor model (streak, SPAD, CW-ToF; sensors/) on any (H, W, T, C)
// float32 transient, tofsim's or another renderer's. The sensor comes as JSON
// text in the config's sensor format and is parsed by apps/config's sensor
// parser, so its validation and defaults are the CLI's.

#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "Arrays.h"
#include "Bindings.h"
#include "SenseInputs.h"
#include "tofsim/config/SensorConfig.h"
#include "tofsim/pipeline/SensorMetadata.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/sensors/RunSensor.h"

namespace py = pybind11;

namespace tofsim::python {

namespace {

constexpr const char* kSensorFile = "<sensor>";

// parseSensorText names keys "sensors[0].<key>"; the user wrote "<key>".
sensors::SensorSpec parseSensor(const std::string& json) {
  try {
    return config::parseSensorText(json, kSensorFile);
  } catch (const InputError& e) {
    const std::string prefix = "sensors[0]";
    std::string key = e.key();
    if (key.compare(0, prefix.size(), prefix) == 0) key.erase(0, prefix.size());
    if (!key.empty() && key[0] == '.') key.erase(0, 1);
    throw InputError(FileLoc{kSensorFile}, key, inputErrorMessage(e));
  }
}

// A cwtof sensor with multipath_by_order takes the light by bounce order and
// the ground truth; naming the missing arguments here says more than the
// sensor's own error, which speaks of the CLI's files.
void checkByOrderInputs(const sensors::SensorSpec& spec, bool bounces, bool direct, bool depth) {
  const auto* cwtof = std::get_if<sensors::CwTofParams>(&spec.params);
  if (!cwtof || !cwtof->multipath_by_order || (bounces && direct && depth)) return;
  std::string missing;
  for (const auto& [given, name] :
       {std::pair{bounces, "bounces"}, std::pair{direct, "direct"}, std::pair{depth, "depth"}}) {
    if (!given) missing += std::string(missing.empty() ? "" : ", ") + name;
  }
  throw InputError(FileLoc{kSensorFile}, "multipath_by_order",
                   "needs bounces= (the light of bounces 1..N, (H, W, T, C) each), direct= and "
                   "depth=; missing: " +
                       missing);
}

// The bounce volumes, each of the transient's shape.
std::vector<TransientVolume> bounceVolumes(const std::vector<FloatArray>& arrays,
                                           const FloatArray& transient, const TimeAxis& axis) {
  std::vector<TransientVolume> volumes;
  for (size_t k = 0; k < arrays.size(); ++k) {
    const std::string what = "bounces[" + std::to_string(k) + "]";
    const FloatArray& a = arrays[k];
    bool same = a.ndim() == transient.ndim();
    for (py::ssize_t d = 0; same && d < a.ndim(); ++d) same = a.shape(d) == transient.shape(d);
    if (!same) throw py::value_error(what + " must have the transient's shape (H, W, T, C)");
    volumes.push_back(volumeFromArray(a, axis, what.c_str()));
  }
  return volumes;
}

py::tuple sense(const FloatArray& transient, double start_s, double binWidth_s,
                const std::string& sensorJson, uint64_t seed,
                const std::optional<FloatArray>& direct, const std::optional<FloatArray>& depth,
                const std::optional<std::vector<FloatArray>>& bounces) {
  const sensors::SensorSpec spec = parseSensor(sensorJson);
  checkByOrderInputs(spec, bounces.has_value(), direct.has_value(), depth.has_value());
  if (bounces && !direct) throw py::value_error("bounces need direct (the direct component) too");
  const TimeAxis axis{start_s, binWidth_s,
                      transient.ndim() == 4 ? static_cast<int32_t>(transient.shape(2)) : 0};
  const TransientVolume volume = volumeFromArray(transient, axis, "transient");
  std::optional<TransientVolume> directVolume;
  if (direct) directVolume = volumeFromArray(*direct, axis, "direct");
  std::optional<Image> depthImage;
  if (depth) {
    if (depth->ndim() != 2 || depth->shape(0) != volume.height() ||
        depth->shape(1) != volume.width()) {
      throw py::value_error("depth must have shape (H, W) of the transient");
    }
    depthImage = Image(volume.width(), volume.height(), 1);
    std::copy_n(depth->data(), depthImage->data.size(), depthImage->data.data());
  }
  std::vector<TransientVolume> bounceVolumesHeld;
  std::vector<const TransientVolume*> bouncePointers;
  if (bounces) {
    bounceVolumesHeld = bounceVolumes(*bounces, transient, axis);
    for (const TransientVolume& b : bounceVolumesHeld) bouncePointers.push_back(&b);
  }
  sensors::SensorInputs inputs;
  inputs.volume = &volume;
  inputs.directOnly = directVolume ? &*directVolume : nullptr;
  inputs.groundTruthDepth_m = depthImage ? &*depthImage : nullptr;
  inputs.bounces = bounces ? &bouncePointers : nullptr;
  inputs.seed = seed;
  return senseInputs(spec, inputs);
}

}  // namespace

// (outputs: name -> array, metadata: name -> JSON text, warnings). The
// metadata is the CLI's sensors/<name>/<output>.json without its `files`. A
// colour-mapped image repeats the Image of the same name (it is how the CLI
// draws it), so it adds no array; a plot with no data of its own (SPAD
// histograms) adds its plotted numbers.
py::tuple senseInputs(const sensors::SensorSpec& spec, const sensors::SensorInputs& inputs) {
  std::vector<sensors::SensorOutput> outputs;
  pipeline::SensorRunInfo run{&spec, inputs.volume->axis(), inputs.seed, {}};
  {
    py::gil_scoped_release released;
    run.warnings = sensors::sensorWarnings(spec, inputs);
    outputs = sensors::runSensor(spec, inputs);
  }
  py::dict metadata;
  for (const pipeline::NamedMetadata& m : pipeline::sensorMetadata(run, outputs, false)) {
    metadata[py::str(m.name)] = m.json;
  }
  py::dict arrays;
  for (sensors::SensorOutput& o : outputs) {
    if (o.kind == sensors::SensorOutput::Kind::ColorMappedImage && arrays.contains(o.name)) {
      continue;
    }
    const std::vector<py::ssize_t> shape(o.shape.begin(), o.shape.end());
    arrays[py::str(o.name)] = ownedArray(std::move(o.data), shape);
  }
  return py::make_tuple(arrays, metadata, run.warnings);
}

void bindSense(py::module_& m) {
  m.def("_sense", &sense, py::arg("transient"), py::arg("start_s"), py::arg("bin_width_s"),
        py::arg("sensor_json"), py::arg("seed"), py::arg("direct"), py::arg("depth"),
        py::arg("bounces"));
}

}  // namespace tofsim::python
