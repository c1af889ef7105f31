// Configs and sensors given as text rather than as a file: what the Python
// module hands over for a YAML string or a dict (as JSON, which YAML reads).

#include <string>
#include <variant>

#include "ConfigNode.h"
#include "RunConfigYaml.h"
#include "SpadTableFile.h"
#include "YamlText.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/config/SensorConfig.h"

namespace tofsim::config {

namespace {
YAML::Node parseYamlText(const std::string& text, const std::string& file) {
  try {
    return parseYaml(text);
  } catch (const YAML::Exception& e) {
    throw InputError(FileLoc{file, e.mark.line + 1, e.mark.column + 1}, "", e.msg);
  }
}
}  // namespace

RunConfig loadRunConfigText(const std::string& yamlText, const std::filesystem::path& file,
                            const std::vector<Override>& overrides) {
  return loadRunConfigYaml(parseYamlText(yamlText, file.string()), file, overrides);
}

sensors::SensorSpec parseSensorText(const std::string& yamlText, const std::string& file) {
  YAML::Node list(YAML::NodeType::Sequence);
  list.push_back(parseYamlText(yamlText, file));
  YAML::Node document(YAML::NodeType::Map);
  document["sensors"] = list;
  const ConfigNode root(document, file);
  std::vector<sensors::SensorSpec> specs = parseSensors(root.child("sensors"));
  root.reportUnusedKeys();
  // No TDC axis here (the volume gives it): the DNL's sum alone.
  if (const auto* spad = std::get_if<sensors::SpadParams>(&specs.front().params)) {
    if (spad->tdc_dnl.present()) checkDnlSum(root.child("sensors").elements().front(), spad->tdc_dnl);
  }
  return std::move(specs.front());
}

}  // namespace tofsim::config
