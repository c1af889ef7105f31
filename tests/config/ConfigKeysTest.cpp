// The declared keys (ConfigKeys.h) against the documentation tables and the
// effective-config writer: a key added to one and not the other fails here.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "support/TempDir.h"
#include "tofsim/config/ConfigKeys.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/io/Npy.h"

namespace tofsim::config {
namespace {

using Row = std::vector<std::string>;  // path, type column, default, unit, doc

// Rows of every "| key | type | default | unit | meaning |" table, each key
// prefixed with what the heading above it names (nullptr: not a key table).
std::vector<Row> readmeRows(const std::string& file,
                            const std::function<const char*(const std::string&)>& prefixOf) {
  std::ifstream in(std::string(TOFSIM_SOURCE_DIR) + "/" + file);
  EXPECT_TRUE(in) << file;
  const std::regex row(R"(^\| `([^`]+)` \| (.*) \| (.*) \| (.*) \| (.*) \|$)");
  std::vector<Row> rows;
  const char* prefix = nullptr;
  std::string prefixText, line;
  while (std::getline(in, line)) {
    if (line.rfind('#', 0) == 0) {
      prefix = prefixOf(line.substr(line.find_first_not_of("# ")));
      prefixText = prefix ? prefix : "";
      continue;
    }
    std::smatch m;
    if (prefix && std::regex_match(line, m, row)) {
      rows.push_back(
          {prefixText + (prefixText.empty() ? "" : ".") + m[1].str(), m[2], m[3], m[4], m[5]});
    }
  }
  return rows;
}

std::vector<Row> declaredRows(std::span<const ConfigKey> keys) {
  std::vector<Row> rows;
  for (const ConfigKey& k : keys) {
    const std::string range = k.range;
    rows.push_back({k.path, std::string(k.type) + (range.empty() ? "" : " " + range),
                    k.defaultValue, k.unit, k.doc});
  }
  return rows;
}

void expectSameRows(const std::vector<Row>& readme, const std::vector<Row>& declared,
                    const std::string& file) {
  std::map<std::string, Row> byPath;
  for (const Row& r : declared) byPath[r[0]] = r;
  std::set<std::string> documented;
  for (const Row& r : readme) {
    documented.insert(r[0]);
    const auto it = byPath.find(r[0]);
    if (it == byPath.end()) {
      ADD_FAILURE() << file << " documents `" << r[0] << "`, which ConfigKeys.cpp does not declare";
    } else {
      EXPECT_EQ(r, it->second) << file << ": the row of `" << r[0]
                               << "` differs from ConfigKeys.cpp";
    }
  }
  for (const Row& r : declared) {
    EXPECT_TRUE(documented.count(r[0])) << "`" << r[0] << "` is declared but not in " << file;
  }
}

TEST(ConfigKeysTest, ConfigsReadmeTablesMatchTheDeclaredKeys) {
  const auto prefixOf = [](const std::string& heading) -> const char* {
    static std::string name;
    if (heading == "Top level") return "";
    const std::smatch m = [&] {
      std::smatch s;
      std::regex_match(heading, s, std::regex("^`([a-z_.]+)`$"));
      return s;
    }();
    if (m.empty()) return nullptr;
    name = m[1];
    return name.c_str();
  };
  expectSameRows(readmeRows("configs/README.md", prefixOf), declaredRows(runConfigKeys()),
                 "configs/README.md");
}

TEST(ConfigKeysTest, SensorsReadmeTablesMatchTheDeclaredKeys) {
  const auto prefixOf = [](const std::string& heading) -> const char* {
    static const std::map<std::string, const char*> sections = {
        {"Common parameters (every model)", "common"},
        {"Instrument bins (streak and SPAD)", "bins"},
        {"Streak camera", "streak"},
        {"SPAD", "spad"},
        {"Continuous-wave ToF", "cwtof"},
        {"Linear-mode APD", "apd"}};
    const auto it = sections.find(heading);
    return it == sections.end() ? nullptr : it->second;
  };
  expectSameRows(readmeRows("sensors/README.md", prefixOf), declaredRows(sensorConfigKeys()),
                 "sensors/README.md");
}

void leafPaths(const YAML::Node& node, const std::string& path, std::set<std::string>& out) {
  if (node.IsMap()) {
    out.insert(path);
    for (const auto& e : node) {
      leafPaths(e.second, (path.empty() ? "" : path + ".") + e.first.as<std::string>(), out);
    }
  } else {
    out.insert(path);
  }
}

class ConfigKeysWriterTest : public test::TempDirTest {};

// The writer emits exactly the declared keys (gltf_camera only when set), so
// a key the parser gains without a declaration, or the other way, shows here.
TEST_F(ConfigKeysWriterTest, EffectiveConfigWritesEveryDeclaredKey) {
  std::ofstream(dir_ / "scene.gltf") << "{}";
  std::ofstream(dir_ / "c.yaml") << "scene: scene.gltf\ncamera: {gltf_camera: cam}\nlight: {}\n"
                                    "time: {}\n";
  const RunConfig c = loadRunConfig(dir_ / "c.yaml");
  std::set<std::string> written;
  leafPaths(YAML::Load(effectiveConfigYaml(c)), "", written);
  // An nlos capture instead of the camera and the light: its keys, exhaustive
  // (the laser grid) and single (the laser point).
  for (const char* scan : {"exhaustive", "single"}) {
    std::ofstream(dir_ / "n.yaml") << "scene: scene.gltf\nnlos: {relay_wall: w, scan: " << scan
                                   << ", sensor_origin: [0, 0, 1], laser_origin: [0, 0, 1]}\n"
                                      "time: {}\n";
    leafPaths(YAML::Load(effectiveConfigYaml(loadRunConfig(dir_ / "n.yaml"))), "", written);
  }
  // A lens, inline and from a calibration file (their keys exclude each other).
  std::ofstream(dir_ / "calib.yaml") << "%YAML:1.0\n---\nimage_width: 64\nimage_height: 64\n"
                                        "camera_matrix: !!opencv-matrix\n"
                                        "  rows: 3\n  cols: 3\n  dt: d\n"
                                        "  data: [50, 0, 31.5, 0, 50, 31.5, 0, 0, 1]\n"
                                        "distortion_coefficients: [0.1, 0, 0, 0, 0]\n";
  for (const char* lens : {"{camera_matrix: [50, 0, 31.5, 0, 50, 31.5, 0, 0, 1], "
                           "distortion: [0.1, 0, 0, 0]}",
                           "{calibration: calib.yaml}"}) {
    std::ofstream(dir_ / "l.yaml")
        << "scene: scene.gltf\ncamera: {lens: " << lens << "}\nlight: {}\ntime: {}\n";
    leafPaths(YAML::Load(effectiveConfigYaml(loadRunConfig(dir_ / "l.yaml"))), "", written);
  }
  // A PSF, parametric and from a kernel file (their keys exclude each other).
  const std::vector<float> kernel = {0, 1, 0, 1, 4, 1, 0, 1, 0};
  io::writeNpy(dir_ / "psf.npy", {3, 3}, kernel.data());
  for (const char* psf :
       {"{core_sigma: 0.5, halo_weight: 0.1, halo_radius: 4}", "{file: psf.npy}"}) {
    std::ofstream(dir_ / "p.yaml")
        << "scene: scene.gltf\ncamera: {psf: " << psf << "}\nlight: {}\ntime: {}\n";
    leafPaths(YAML::Load(effectiveConfigYaml(loadRunConfig(dir_ / "p.yaml"))), "", written);
  }
  // An aperture (its keys are written only with one, a pinhole's config
  // keeping its bytes).
  std::ofstream(dir_ / "a.yaml") << "scene: scene.gltf\ncamera: {aperture: 0.01, "
                                    "focus_distance: 2}\nlight: {}\ntime: {}\n";
  leafPaths(YAML::Load(effectiveConfigYaml(loadRunConfig(dir_ / "a.yaml"))), "", written);
  // A sequence, by rate and count and as a list of times.
  for (const char* sequence : {"{start: 1 s, rate: 30 Hz, count: 2}", "{times: [0 s, 1 s]}"}) {
    std::ofstream(dir_ / "s.yaml") << "scene: scene.gltf\ncamera: {}\nlight: {}\ntime: {}\n"
                                      "sequence: "
                                   << sequence << "\n";
    const std::string yaml = effectiveConfigYaml(loadRunConfig(dir_ / "s.yaml"));
    leafPaths(YAML::Load(yaml), "", written);
    std::ofstream(dir_ / "s2.yaml") << yaml;  // and reloads to the same config
    EXPECT_EQ(effectiveConfigYaml(loadRunConfig(dir_ / "s2.yaml")), yaml);
  }
  // A ray list in place of the camera.
  std::ofstream(dir_ / "rays.csv") << "0,0,1,0,0,-1\n";
  std::ofstream(dir_ / "r.yaml") << "scene: scene.gltf\nrays: {file: rays.csv}\nlight: {}\ntime: {}\n";
  leafPaths(YAML::Load(effectiveConfigYaml(loadRunConfig(dir_ / "r.yaml"))), "", written);
  // Materials, one of each model (their keys exclude each other), the
  // material's name written as the docs write it.
  std::ofstream(dir_ / "kernel.csv") << "0,1\n1e-10,0\n";
  for (const char* delay : {"{model: exponential, lifetime: 1 ns}",
                            "{model: gaussian, mean: 1 ns, sigma: 10 ps}",
                            "{model: table, file: kernel.csv}"}) {
    std::ofstream(dir_ / "m.yaml") << "scene: scene.gltf\ncamera: {}\nlight: {}\ntime: {}\n"
                                      "materials: {wax: {scattering_delay: "
                                   << delay << "}}\n";
    std::set<std::string> paths;
    leafPaths(YAML::Load(effectiveConfigYaml(loadRunConfig(dir_ / "m.yaml"))), "", paths);
    for (std::string p : paths) {
      if (p.rfind("materials.wax", 0) == 0) p = "materials.<name>" + p.substr(13);
      written.insert(p);
    }
  }
  // A medium, by its coefficients (Henyey-Greenstein's g) and as fog by its
  // visibility (their keys exclude each other).
  for (const char* medium : {"{sigma_a: 0.1, sigma_s: [0.1, 0.2, 0.3], "
                             "phase: {model: henyey_greenstein, g: 0.5}}",
                             "{visibility: 50 m}"}) {
    std::ofstream(dir_ / "md.yaml") << "scene: scene.gltf\ncamera: {}\nlight: {}\ntime: {}\n"
                                       "medium: "
                                    << medium << "\n";
    leafPaths(YAML::Load(effectiveConfigYaml(loadRunConfig(dir_ / "md.yaml"))), "", written);
  }
  // Per-region media (a list: its entries' keys are documented in their own
  // section), on the CPU backend.
  std::ofstream(dir_ / "me.yaml") << "scene: scene.gltf\ncamera: {}\nlight: {}\ntime: {}\n"
                                     "render: {backend: cpu}\nmedia: [{region: tank, sigma_a: 0.1}]\n";
  leafPaths(YAML::Load(effectiveConfigYaml(loadRunConfig(dir_ / "me.yaml"))), "", written);
  // A lidar in place of the camera and the light (channels as a count).
  std::ofstream(dir_ / "li.yaml") << "scene: scene.gltf\nlidar: {position: [0, 0, 1], "
                                     "orientation: {look_at: [1, 0, 1]}, channels: {count: 2, "
                                     "min: -1, max: 1}}\ntime: {}\n";
  leafPaths(YAML::Load(effectiveConfigYaml(loadRunConfig(dir_ / "li.yaml"))), "", written);
  // A lidar's multipath (its keys are written only with it on, the
  // direct-light configs keeping their bytes).
  std::ofstream(dir_ / "lm.yaml") << "scene: scene.gltf\nlidar: {position: [0, 0, 1], "
                                     "orientation: {look_at: [1, 0, 1]}, channels: [0], "
                                     "multipath: {bounces: 1}}\ntime: {}\n";
  leafPaths(YAML::Load(effectiveConfigYaml(loadRunConfig(dir_ / "lm.yaml"))), "", written);
  // A preset's multizone sensor (a grid scan: its grid and zone keys).
  std::ofstream(dir_ / "mz.yaml") << "scene: scene.gltf\nlidar: {preset: multizone-8x8, "
                                     "position: [0, 0, 1], orientation: {look_at: [1, 0, 1]}}\n"
                                     "time: {}\n";
  leafPaths(YAML::Load(effectiveConfigYaml(loadRunConfig(dir_ / "mz.yaml"))), "", written);
  // A raster (its frame rate).
  std::ofstream(dir_ / "ra.yaml") << "scene: scene.gltf\nlidar: {scan: raster, position: [0, 0, 1], "
                                     "orientation: {look_at: [1, 0, 1]}, grid: {rows: 2, columns: 2}, "
                                     "field_of_view: {horizontal: 10, vertical: 10}}\ntime: {}\n";
  leafPaths(YAML::Load(effectiveConfigYaml(loadRunConfig(dir_ / "ra.yaml"))), "", written);
  written.erase("");
  std::set<std::string> declared;
  for (const ConfigKey& k : runConfigKeys()) declared.insert(k.path);
  EXPECT_EQ(written, declared);
}

}  // namespace
}  // namespace tofsim::config
