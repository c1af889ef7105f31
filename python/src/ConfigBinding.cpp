// tofsim.Config: a run config validated by apps/config exactly as the CLI
// validates it (loadRunConfig / loadRunConfigText), read-only from Python.

#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "Bindings.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

namespace py = pybind11;

namespace tofsim::python {

namespace {
using OverridePairs = std::vector<std::pair<std::string, std::string>>;

std::vector<config::Override> toOverrides(const OverridePairs& pairs) {
  std::vector<config::Override> out;
  for (const auto& [key, value] : pairs) out.push_back(config::Override{key, value});
  return out;
}

std::shared_ptr<config::RunConfig> loadFile(const std::string& path,
                                            const OverridePairs& overrides) {
  return std::make_shared<config::RunConfig>(config::loadRunConfig(path, toOverrides(overrides)));
}

// keepLines false: the text was generated (a dict as JSON), so its lines and
// columns mean nothing to the user; the key path says where.
std::shared_ptr<config::RunConfig> loadText(const std::string& text, const std::string& file,
                                            const OverridePairs& overrides, bool keepLines) {
  try {
    return std::make_shared<config::RunConfig>(
        config::loadRunConfigText(text, file, toOverrides(overrides)));
  } catch (const InputError& e) {
    if (keepLines || e.location().file != file) throw;
    throw InputError(FileLoc{file}, e.key(), inputErrorMessage(e));
  }
}

py::dict timeOf(const config::RunConfig& c) {
  py::dict d;
  d["start_s"] = c.render.time.start_s;
  d["bin_width_s"] = c.render.time.bin_width_s;
  d["bins"] = c.render.time.bins;
  return d;
}
}  // namespace

void bindConfig(py::module_& m) {
  py::class_<config::RunConfig, std::shared_ptr<config::RunConfig>>(
      m, "Config", "A validated run config (tofsim.load_config); read-only.", py::dynamic_attr())
      .def_property_readonly("config_file",
                             [](const config::RunConfig& c) { return c.config_file.string(); })
      .def_property_readonly("scene_file",
                             [](const config::RunConfig& c) { return c.scene_file.string(); })
      .def_property_readonly(
          "resolution",
          [](const config::RunConfig& c) {
            return std::make_pair(c.camera.camera.width, c.camera.camera.height);
          },
          "(width, height) in pixels")
      .def_property_readonly("renderer",
                             [](const config::RunConfig& c) {
                               return c.renderer == config::RendererKind::Reference ? "reference"
                                                                                    : "ir";
                             })
      .def_property_readonly("seed", [](const config::RunConfig& c) { return c.render.seed; })
      .def_property_readonly("time_axis", &timeOf, "render axis: start_s, bin_width_s, bins")
      .def_property_readonly("sensors",
                             [](const config::RunConfig& c) {
                               std::vector<std::string> names;
                               for (const auto& s : c.sensors) names.push_back(s.name);
                               return names;
                             })
      .def_property_readonly(
          "is_nlos", [](const config::RunConfig& c) { return c.nlos.has_value(); },
          "whether the config is a non-line-of-sight capture (`nlos:`)")
      .def_property_readonly(
          "frame_times_s",
          [](const config::RunConfig& c) -> std::optional<std::vector<double>> {
            if (!c.sequence) return std::nullopt;
            return c.sequence->times_s;
          },
          "a capture sequence's frame times, s of scene time; None without `sequence:`")
      .def_property_readonly("output_directory",
                             [](const config::RunConfig& c) { return c.output.directory.string(); })
      .def("effective_yaml", &config::effectiveConfigYaml,
           "Every key with its value, defaults filled in (config.effective.yaml)");
  m.def("_load_config_file", &loadFile, py::arg("path"), py::arg("overrides"));
  m.def("_load_config_text", &loadText, py::arg("text"), py::arg("file"), py::arg("overrides"),
        py::arg("keep_lines"));
}

}  // namespace tofsim::python
