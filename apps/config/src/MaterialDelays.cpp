#include "tofsim/config/MaterialDelays.h"

#include <yaml-cpp/yaml.h>

#include <map>
#include <string>

#include "ConfigNode.h"
#include "MaterialSection.h"

namespace tofsim::config {

namespace {

constexpr const char* kKey = "scattering_delay";

// The flattened extras below `kKey` as the YAML they came from: "a.b" a
// member of a mapping, "a.0" .. "a.n-1" the elements of a list (the glTF
// JSON's arrays: reemission's rows).
struct Tree {
  std::string value;
  std::map<std::string, Tree> children;
};

YAML::Node toYaml(const Tree& t) {
  if (t.children.empty()) return YAML::Node(t.value);
  bool list = true;
  for (std::size_t i = 0; i < t.children.size() && list; ++i) {
    list = t.children.count(std::to_string(i)) > 0;
  }
  YAML::Node n(list ? YAML::NodeType::Sequence : YAML::NodeType::Map);
  if (list) {
    for (std::size_t i = 0; i < t.children.size(); ++i)
      n.push_back(toYaml(t.children.at(std::to_string(i))));
  } else {
    for (const auto& [key, child] : t.children) n[key] = toYaml(child);
  }
  return n;
}

YAML::Node extrasYaml(const std::map<std::string, std::string>& extras) {
  Tree root;
  const std::string prefix = std::string(kKey) + ".";
  for (const auto& [path, value] : extras) {
    if (path != kKey && path.rfind(prefix, 0) != 0) continue;
    Tree* at = &root;
    std::size_t begin = 0;
    while (true) {
      const std::size_t dot = path.find('.', begin);
      at = &at->children[path.substr(begin, dot - begin)];
      if (dot == std::string::npos) break;
      begin = dot + 1;
    }
    at->value = value;
  }
  return toYaml(root);
}

std::optional<physics::ResponseKernel> extrasDelay(const scene::Material& m, std::size_t index,
                                                   const MaterialExtras& extras,
                                                   const RunConfig& config) {
  if (index >= extras.size()) return std::nullopt;
  const YAML::Node yaml = extrasYaml(extras[index]);
  if (!yaml.IsMap()) return std::nullopt;  // no scattering_delay in the extras
  const ConfigNode root(yaml, config.scene_file.string(),
                        "materials[" + std::to_string(index) + "] '" + m.name + "'.extras");
  ScatteringDelayConfig d = parseScatteringDelay(root, config.render.time);
  root.reportUnusedKeys();
  return std::move(d.kernel);
}

std::string materialNames(const scene::Scene& scene) {
  std::string names;
  for (const scene::Material& m : scene.materials) names += (names.empty() ? "" : ", ") + m.name;
  return names.empty() ? "none" : names;
}

}  // namespace

std::vector<std::optional<physics::ResponseKernel>> materialDelays(const RunConfig& config,
                                                                   const scene::Scene& scene,
                                                                   const MaterialExtras& extras) {
  for (const MaterialConfig& entry : config.materials) {
    bool found = false;
    for (const scene::Material& m : scene.materials) found = found || m.name == entry.name;
    if (!found) {
      throw InputError(entry.at, "materials." + entry.name,
                       "the scene " + config.scene_file.filename().string() +
                           " has no material of this name (its materials: " + materialNames(scene) +
                           ")");
    }
  }
  std::vector<std::optional<physics::ResponseKernel>> delays;
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const scene::Material& m = scene.materials[i];
    const MaterialConfig* entry = nullptr;
    for (const MaterialConfig& e : config.materials) {
      if (e.name == m.name) entry = &e;
    }
    delays.push_back(entry ? entry->scattering_delay.kernel : extrasDelay(m, i, extras, config));
  }
  return delays;
}

void applyMaterialDelays(const RunConfig& config, scene::Scene& scene,
                         const MaterialExtras& extras) {
  const auto delays = materialDelays(config, scene, extras);
  for (std::size_t i = 0; i < delays.size(); ++i) scene.materials[i].scatteringDelay = delays[i];
}

}  // namespace tofsim::config
