// The run keys declared in tables (apps/config/src RunFields.h, TimeFields.h,
// LightFields.h, OutputFields.h, CameraFields.h): the documented default of each, written
// into a config, gives the effective config of leaving it out (the doc rows,
// the loader and the writer read one declaration), and a value out of a
// table's range is a located error naming the key.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>

#include "support/TempDir.h"
#include "tofsim/config/ConfigKeys.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

namespace tofsim::config {
namespace {

class RunKeyTablesTest : public test::TempDirTest {
 protected:
  /// The effective config of a run whose sections hold `sections` (section
  /// name -> its YAML lines, each indented by two).
  std::string effective(const std::map<std::string, std::string>& sections) {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    std::ofstream out(dir_ / "c.yaml");
    out << "scene: scene.gltf\ncamera: {}\n";
    for (const char* name : {"light", "time", "render", "output"}) {
      const auto it = sections.find(name);
      out << name << (it == sections.end() ? ": {}\n" : ":\n" + it->second);
    }
    out.close();
    return effectiveConfigYaml(loadRunConfig(dir_ / "c.yaml"));
  }
  std::string errorOf(const std::map<std::string, std::string>& sections) {
    try {
      effective(sections);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(RunKeyTablesTest, DocumentedDefaultsReadBackAsTheDefaults) {
  const std::string defaults = effective({});
  int checked = 0;
  for (const ConfigKey& key : runConfigKeys()) {
    const std::string path = key.path, type = key.type;
    const std::size_t dot = path.find('.');
    if (dot == std::string::npos || type == "mapping") continue;
    const std::string section = path.substr(0, dot), name = path.substr(dot + 1);
    if (section != "light" && section != "time" && section != "render" && section != "output") {
      continue;
    }
    if (name.find('.') != std::string::npos) continue;  // render.indirect.*: RunConfigFieldsTest
    SCOPED_TRACE(path + ": " + key.defaultValue);
    EXPECT_EQ(effective({{section, "  " + name + ": " + key.defaultValue + "\n"}}), defaults)
        << "the documented default of `" << path << "` is not the one the loader takes";
    ++checked;
  }
  EXPECT_EQ(checked, 8 + 5 + 11 + 15);  // light, time, render, output
}

TEST_F(RunKeyTablesTest, OutOfRangeValuesAreLocatedErrors) {
  struct Case {
    const char* section;
    const char* line;
    const char* key;
    const char* message;
  };
  for (const Case& c : {
           Case{"time", "  bins: 0\n", "time.bins", "must be in [1, 1048576] (got 0)"},
           Case{"time", "  bin_width: -3 ps\n", "time.bin_width", "must be > 0"},
           Case{"time", "  index_of_refraction: 0.5\n", "time.index_of_refraction", ">= 1"},
           Case{"render", "  memory_budget: 1 KiB\n", "render.memory_budget",
                "must be between 1 MiB and 1 PiB"},
           Case{"render", "  seed: -1\n", "render.seed", "must be in [0, "},
           Case{"render", "  backend: vulkan\n", "render.backend", "must be auto, gl or cpu"},
           Case{"light", "  cone_angle: 200 deg\n", "light.cone_angle", "(0, 180]"},
           Case{"light", "  cone_falloff: 40 deg\n", "light.cone_falloff", "[0, cone_angle]"},
           Case{"light", "  intensity: [1, -1, 1]\n", "light.intensity", "must be >= 0"},
           Case{"light", "  direction: [0, 0, 0]\n", "light.direction", "must not be zero"},
           Case{"output", "  video_window: 0\n", "output.video_window", "must be in [1, 1048576]"},
           Case{"output", "  max_bytes: 0\n", "output.max_bytes", "must be between 1 B and 1 EiB"},
       }) {
    const std::string what = errorOf({{c.section, c.line}});
    SCOPED_TRACE(c.line);
    ASSERT_FALSE(what.empty()) << "accepted";
    // The section's only key is on the line after its name (scene, camera,
    // then light, time, render, output: one line each when empty).
    const std::map<std::string, int> lineOf = {
        {"light", 4}, {"time", 5}, {"render", 6}, {"output", 7}};
    const int line = lineOf.at(c.section);
    EXPECT_NE(what.find("c.yaml:" + std::to_string(line) + ":"), std::string::npos) << what;
    EXPECT_NE(what.find(c.key), std::string::npos) << what;
    EXPECT_NE(what.find(c.message), std::string::npos) << what;
  }
}

// camera's table (CameraFields.h): the documented default of each camera key
// that stands alone gives the effective config of leaving it out
// (focus_distance and aperture_samples need an aperture; lens and psf are
// sections of their own).
TEST_F(RunKeyTablesTest, CameraDocumentedDefaultsReadBackAsTheDefaults) {
  const auto withCamera = [&](const std::string& line) {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    std::ofstream(dir_ / "c.yaml") << "scene: scene.gltf\ncamera:\n  " << (line.empty() ? "{}" : line)
                                   << "\nlight: {}\ntime: {}\n";
    return effectiveConfigYaml(loadRunConfig(dir_ / "c.yaml"));
  };
  const std::string defaults = withCamera("");
  int checked = 0;
  for (const ConfigKey& key : runConfigKeys()) {
    const std::string path = key.path, type = key.type;
    if (path.rfind("camera.", 0) != 0 || type == "mapping") continue;
    const std::string name = path.substr(7);
    if (name.find('.') != std::string::npos) continue;
    if (name == "focus_distance" || name == "aperture_samples") continue;
    SCOPED_TRACE(path + ": " + key.defaultValue);
    EXPECT_EQ(withCamera(name + ": " + key.defaultValue), defaults)
        << "the documented default of `" << path << "` is not the one the loader takes";
    ++checked;
  }
  EXPECT_EQ(checked, 8);
}

}  // namespace
}  // namespace tofsim::config
