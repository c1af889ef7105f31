// Loads a run config: the YAML, the --set overrides, each section read by
// its parser (RunSections.cpp, CameraConfigParser.cpp, ...), then the checks
// across sections (RunChecks.cpp, SensorListChecks.cpp) and the unknown keys.
#include <string>

#include "CameraConfigParser.h"
#include "ConfigNode.h"
#include "LidarSection.h"
#include "MaterialSection.h"
#include "MediumSection.h"
#include "NlosConfigParser.h"
#include "RayFile.h"
#include "RunChecks.h"
#include "RunConfigYaml.h"
#include "RunSections.h"
#include "SensorListChecks.h"
#include "SequenceConfigParser.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/config/SensorConfig.h"

namespace tofsim::config {

namespace {

// "sensors.0.bins" -> "sensors[0].bins", the form ConfigNode paths take.
std::string nodePath(const std::string& keyPath) {
  std::string out;
  std::size_t begin = 0;
  while (begin <= keyPath.size()) {
    const std::size_t dot = keyPath.find('.', begin);
    const std::string part = keyPath.substr(begin, dot == std::string::npos ? dot : dot - begin);
    const bool index = !part.empty() && part.find_first_not_of("0123456789") == std::string::npos;
    out += index ? "[" + part + "]" : (out.empty() ? "" : ".") + part;
    if (dot == std::string::npos) break;
    begin = dot + 1;
  }
  return out;
}

void parseScene(const ConfigNode& root, RunConfig& config) {
  const std::string sceneText = root.requireString("scene");
  config.scene_file = config.config_file.parent_path() / sceneText;
  // The error_code overload: a name the OS rejects (too long, ...) is bad
  // input, not a std::filesystem_error escaping (found by fuzz_config).
  std::error_code ec;
  if (!std::filesystem::exists(config.scene_file, ec)) {
    root.failKey("scene", "scene file not found: " + config.scene_file.string());
  }
}

// A camera and a light, or an nlos scan or a lidar in their place.
void parseView(const ConfigNode& root, RunConfig& config) {
  if (root.has("lidar")) {
    parseLidarView(root, config);
    checkLidarRun(root, *config.lidar);
    return;
  }
  const auto nlos = root.optionalChild("nlos");
  if (!nlos && root.has("rays")) {
    if (root.has("camera")) root.failKey("camera", "a capture has one imager: `camera` or `rays`, not both");
    config.rays = parseRays(root.child("rays"));
    config.camera.camera.width = config.rays->imager.width;
    config.camera.camera.height = config.rays->imager.height;
    parseLight(root.child("light"), config.light);
    if (config.light.attach_to_camera) {
      root.child("light").failKey("attach_to_camera", "rays have no camera to attach the light to");
    }
    return;
  }
  if (!nlos) {
    parseCamera(root.child("camera"), config.camera);
    parseLight(root.child("light"), config.light);
    return;
  }
  config.nlos = parseNlos(*nlos);
  for (const char* key : {"camera", "light", "rays"}) {
    if (root.has(key)) {
      root.failKey(key,
                   "an nlos capture looks at the relay wall from nlos.sensor_origin and is "
                   "lit by nlos.laser_*: remove `" +
                       std::string(key) + "`");
    }
  }
  config.light.light.type = capture::Light::Type::Lambertian;
  config.light.light.intensity_W_per_sr = config.nlos->laser_power_W;
}

void parseSensorList(const ConfigNode& list, RunConfig& config) {
  // parseSensors reports unknown keys inside each sensor itself; the keys it
  // read are shared with the root, so its check neither repeats nor misses
  // them.
  config.sensors = parseSensors(list);
  checkSensorNames(list, config.sensors);
  // An nlos capture's sensor image: a row per sensor x (and laser point), a
  // column per sensor y (apps/pipeline NlosSensors.h).
  capture::Camera image = config.camera.camera;
  if (config.nlos) {
    const NlosConfig& n = *config.nlos;
    const int32_t lasers = n.scan == NlosScan::Exhaustive ? n.laser_grid[0] * n.laser_grid[1] : 1;
    image.width = n.sensor_grid[1];
    image.height = n.sensor_grid[0] * lasers;
  }
  checkSensorsFitImage(list, config.sensors, image);
  checkBounceOrders(list, config);
  checkSpadGates(list, config);
  checkSensorChannels(list, config);
  checkSensorKernels(list, config.sensors, config.render.time);
}

}  // namespace

Override parseOverride(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError("--set expects key.path=value (got '" + text + "')");
  }
  return Override{text.substr(0, eq), text.substr(eq + 1)};
}

RunConfig loadRunConfig(const std::filesystem::path& file, const std::vector<Override>& overrides) {
  return loadRunConfigYaml(loadYamlFile(file.string()), file, overrides);
}

RunConfig loadRunConfigYaml(YAML::Node yaml, const std::filesystem::path& file,
                            const std::vector<Override>& overrides) {
  if (!yaml.IsMap())
    throw InputError(FileLoc{file.string(), 1, 1}, "", "the config must be a mapping");
  for (const Override& o : overrides) applyOverride(yaml, o.keyPath, o.value);
  const ConfigNode root(yaml, file.string());
  for (const Override& o : overrides) {
    root.addOverrideSource(nodePath(o.keyPath), "--set " + o.keyPath + "=" + o.value);
  }

  RunConfig config;
  config.config_file = file;
  parseScene(root, config);
  parseView(root, config);
  if (const auto sequence = root.optionalChild("sequence")) {
    if (config.nlos)
      sequence->fail("a sequence of nlos captures is not supported (remove `nlos` or `sequence`)");
    if (config.rays)
      sequence->fail("a sequence of ray-list captures is not supported (remove `rays` or `sequence`)");
    config.sequence = parseSequence(*sequence);
  }
  if (const auto time = root.optionalChild("time")) {
    parseTime(*time, config.render.time);
  } else {
    root.failKey("time", "required key is missing (start, bin_width, bins)");
  }
  if (const auto render = root.optionalChild("render")) parseRender(*render, config);
  parseMedium(root, config);
  config.materials_at = FileLoc{file.string()};
  if (const auto materials = root.optionalChild("materials")) parseMaterials(*materials, config);
  checkVplCount(root, config);
  checkBackendCapabilities(root, config);
  if (const auto output = root.optionalChild("output")) parseOutput(*output, config, config.output);
  if (config.sequence) checkSequenceVideo(root.child("sequence"), config);
  if (config.nlos) checkNlosRun(root);
  if (const auto list = root.optionalChild("sensors")) parseSensorList(*list, config);
  root.reportUnusedKeys();
  return config;
}

}  // namespace tofsim::config
