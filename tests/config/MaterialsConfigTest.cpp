// Issue 41's `materials:` section and a glTF material's extras
// (apps/config/src MaterialSection, MaterialDelays): each model's keys reach
// the material's ResponseKernel (times with units, a bare number in seconds,
// re-emission rows = re-emitted channel in glm's column-major layout), the
// effective config reloads to the same kernels, the config's entry replaces
// the extras' whole, and bad input is a located error: in the config at its
// line, in the extras by the glTF file and the material.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/TempDir.h"
#include "tofsim/config/MaterialDelays.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

namespace tofsim::config {
namespace {

using physics::ResponseKernel;
using physics::ResponseModel;

class MaterialsConfigTest : public test::TempDirTest {
 protected:
  RunConfig load(const std::string& materials, const std::string& extra = "") {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    std::ofstream(dir_ / "c.yaml") << "scene: scene.gltf\ncamera: {}\nlight: {}\ntime: {}\n"
                                   << extra << "materials:\n"
                                   << materials;
    return loadRunConfig(dir_ / "c.yaml");
  }
  std::string errorOf(const std::string& materials, const std::string& extra = "") {
    try {
      load(materials, extra);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  static const ResponseKernel& kernel(const RunConfig& c, std::size_t i = 0) {
    return *c.materials.at(i).scattering_delay.kernel;
  }
};

TEST_F(MaterialsConfigTest, EachModelReachesTheKernel) {
  const RunConfig c = load(
      "  wax:\n    scattering_delay: {model: exponential, lifetime: 2.5 ns, fraction: 0.6}\n"
      "  skin:\n    scattering_delay: {model: gaussian, mean: 40 ps, sigma: 15 ps}\n"
      "  dye:\n    scattering_delay: {model: exponential, lifetime: 1.2 ns}\n"
      "  plain:\n    scattering_delay: none\n");
  ASSERT_EQ(c.materials.size(), 4u);
  EXPECT_EQ(c.materials[0].name, "wax");
  EXPECT_EQ(kernel(c, 0).model, ResponseModel::Exponential);
  EXPECT_DOUBLE_EQ(kernel(c, 0).lifetime_s, 2.5e-9);
  EXPECT_DOUBLE_EQ(kernel(c, 0).fraction, 0.6);
  EXPECT_EQ(kernel(c, 0).reemission, glm::dmat3(1.0));
  EXPECT_EQ(kernel(c, 1).model, ResponseModel::Gaussian);
  EXPECT_DOUBLE_EQ(kernel(c, 1).mean_s, 40e-12);
  EXPECT_DOUBLE_EQ(kernel(c, 1).sigma_s, 15e-12);
  EXPECT_DOUBLE_EQ(kernel(c, 1).fraction, 1.0);  // the default
  // A bare number is seconds, as for every duration of the config.
  EXPECT_DOUBLE_EQ(kernel(c, 2).lifetime_s, 1.2e-9);
  EXPECT_FALSE(c.materials[3].scattering_delay.kernel.has_value());
}

TEST_F(MaterialsConfigTest, ReemissionRowsAreTheReemittedChannel) {
  // Light absorbed in G comes back 60 % in R, 40 % in G; R and B stay.
  const RunConfig c = load(
      "  dye:\n    scattering_delay:\n      model: exponential\n      lifetime: 3.5 ns\n"
      "      reemission: [[1, 0.6, 0], [0, 0.4, 0], [0, 0, 1]]\n");
  const glm::dmat3& m = kernel(c).reemission;
  const glm::dvec3 out = m * glm::dvec3(0.0, 1.0, 0.0);  // out = M in
  EXPECT_DOUBLE_EQ(out.r, 0.6);
  EXPECT_DOUBLE_EQ(out.g, 0.4);
  EXPECT_DOUBLE_EQ(out.b, 0.0);
  EXPECT_EQ(m * glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(1.0, 0.0, 0.0));
}

TEST_F(MaterialsConfigTest, TheEffectiveConfigReloadsToTheSameKernels) {
  std::ofstream(dir_ / "kernel.csv") << "delay,weight\n0,1\n2,0.5\n4,0\n";
  const RunConfig c = load(
      "  wax:\n    scattering_delay: {model: exponential, lifetime: 2.5 ns, fraction: 0.6,\n"
      "                               reemission: [[1, 0.25, 0], [0, 0.5, 0], [0, 0, 0.75]]}\n"
      "  skin:\n    scattering_delay: {model: gaussian, mean: 0 ps, sigma: 15 ps}\n"
      "  film:\n    scattering_delay: {model: table, file: kernel.csv, delay_unit: ns}\n"
      "  plain:\n    scattering_delay: none\n");
  const std::string written = effectiveConfigYaml(c);
  std::ofstream(dir_ / "again.yaml") << written;
  const RunConfig again = loadRunConfig(dir_ / "again.yaml");
  ASSERT_EQ(again.materials.size(), c.materials.size());
  for (std::size_t i = 0; i < c.materials.size(); ++i) {
    EXPECT_EQ(again.materials[i].name, c.materials[i].name);
    EXPECT_EQ(again.materials[i].scattering_delay.kernel, c.materials[i].scattering_delay.kernel)
        << c.materials[i].name;
  }
  EXPECT_EQ(effectiveConfigYaml(again), written);
  EXPECT_DOUBLE_EQ(kernel(c, 2).tableDelay_s.back(), 4e-9);
  // Without materials the effective config has no such key (its bytes stay).
  std::ofstream(dir_ / "none.yaml") << "scene: scene.gltf\ncamera: {}\nlight: {}\ntime: {}\n";
  EXPECT_EQ(effectiveConfigYaml(loadRunConfig(dir_ / "none.yaml")).find("\nmaterials:"),
            std::string::npos);
}

TEST_F(MaterialsConfigTest, BadEntriesAreLocatedErrors) {
  struct Case {
    const char* entry;
    const char* key;
    const char* message;
  };
  std::ofstream(dir_ / "bad.csv") << "delay,weight\n0,1\n";  // one row
  for (const Case& c : {
           Case{"{model: exponential, lifetime: -1 ns}", "wax.scattering_delay.lifetime",
                "must be > 0"},
           Case{"{model: exponential, lifetime: 1 ns, fraction: 1.5}",
                "wax.scattering_delay.fraction", "must be in [0, 1]"},
           Case{"{model: exponential, lifetime: 1 ns, fraction: -0.1}",
                "wax.scattering_delay.fraction", "must be in [0, 1]"},
           Case{"{model: exponential, lifetime: 1 ns, reemission: [[1, 0.7, 0], [0, 0.4, 0], "
                "[0, 0, 1]]}",
                "wax.scattering_delay.reemission", "column G (light absorbed in G) sums to 1.1"},
           Case{"{model: exponential, lifetime: 1 ns, reemission: [[1, 0], [0, 1]]}",
                "wax.scattering_delay.reemission", "3x3 matrix"},
           Case{"{model: lorentzian, lifetime: 1 ns}", "wax.scattering_delay.model",
                "must be exponential, gaussian or table (got 'lorentzian')"},
           Case{"{model: gaussian, lifetime: 1 ns, sigma: 1 ps}", "wax.scattering_delay.lifetime",
                "is a key of model: exponential"},
           Case{"{model: exponential}", "wax.scattering_delay.lifetime", "required key is missing"},
           Case{"{model: exponential, lifetime: 2 fortnights}", "wax.scattering_delay.lifetime",
                "unknown time unit"},
           Case{"{model: table, file: bad.csv}", "wax.scattering_delay.file", "at least 2 rows"},
           Case{"{model: gaussian, mean: 1 us, sigma: 1 us}", "wax.scattering_delay", "8192"},
           Case{"fast", "wax.scattering_delay", "or none (got 'fast')"},
       }) {
    SCOPED_TRACE(c.entry);
    const std::string what =
        errorOf(std::string("  wax:\n    scattering_delay: ") + c.entry + "\n");
    ASSERT_FALSE(what.empty()) << "accepted";
    EXPECT_NE(what.find("c.yaml:7:"), std::string::npos) << what;
    EXPECT_NE(what.find(std::string("materials.") + c.key), std::string::npos) << what;
    EXPECT_NE(what.find(c.message), std::string::npos) << what;
  }
  const std::string what = errorOf(
      "  wax:\n    scattering_delay: {model: exponential, "
      "lifetime: 1 ns, lifetme: 2 ns}\n");
  EXPECT_NE(what.find("materials.wax.scattering_delay.lifetme: unknown key"), std::string::npos)
      << what;
}

scene::Material material(const std::string& name) {
  scene::Material m;
  m.name = name;
  return m;
}

TEST_F(MaterialsConfigTest, TheConfigEntryReplacesTheExtrasWhole) {
  scene::Scene scene;
  scene.materials = {material("plain"), material("wax"), material("dye"), material("lamp")};
  // As the loader gives them (LoadReport::materialExtras).
  const MaterialExtras extras = {
      {},
      {{"scattering_delay.model", "exponential"},
       {"scattering_delay.lifetime", "2.5 ns"},
       {"scattering_delay.fraction", "0.59999999999999998"}},
      {{"scattering_delay.model", "exponential"},
       {"scattering_delay.lifetime", "2 ns"},
       {"scattering_delay.reemission.0.0", "1"},
       {"scattering_delay.reemission.0.1", "1"},
       {"scattering_delay.reemission.0.2", "0"},
       {"scattering_delay.reemission.1.0", "0"},
       {"scattering_delay.reemission.1.1", "0"},
       {"scattering_delay.reemission.1.2", "0"},
       {"scattering_delay.reemission.2.0", "0"},
       {"scattering_delay.reemission.2.1", "0"},
       {"scattering_delay.reemission.2.2", "1"},
       {"label", "not ours"}},
      {{"scattering_delay.model", "exponential"}, {"scattering_delay.lifetime", "1 ns"}}};
  // wax: the config's Gaussian, its fraction 1 (not the extras' 0.6);
  // lamp: none, whatever its extras say.
  const RunConfig c = load(
      "  wax:\n    scattering_delay: {model: gaussian, mean: 40 ps, sigma: 15 ps}\n"
      "  lamp:\n    scattering_delay: none\n");
  applyMaterialDelays(c, scene, extras);
  EXPECT_FALSE(scene.materials[0].scatteringDelay.has_value());
  ASSERT_TRUE(scene.materials[1].scatteringDelay.has_value());
  EXPECT_EQ(scene.materials[1].scatteringDelay->model, ResponseModel::Gaussian);
  EXPECT_DOUBLE_EQ(scene.materials[1].scatteringDelay->fraction, 1.0);
  ASSERT_TRUE(scene.materials[2].scatteringDelay.has_value());  // from its extras
  EXPECT_DOUBLE_EQ(scene.materials[2].scatteringDelay->lifetime_s, 2e-9);
  EXPECT_EQ(scene.materials[2].scatteringDelay->reemission * glm::dvec3(0, 1, 0),
            glm::dvec3(1, 0, 0));
  EXPECT_FALSE(scene.materials[3].scatteringDelay.has_value());
}

TEST_F(MaterialsConfigTest, AnUnknownNameListsTheScenesMaterials) {
  scene::Scene scene;
  scene.materials = {material("wall"), material("floor")};
  const RunConfig c = load("  wal:\n    scattering_delay: {model: exponential, lifetime: 1 ns}\n");
  try {
    applyMaterialDelays(c, scene, {});
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("c.yaml:7:"), std::string::npos) << what;
    EXPECT_NE(what.find("materials.wal"), std::string::npos) << what;
    EXPECT_NE(what.find("its materials: wall, floor"), std::string::npos) << what;
  }
}

TEST_F(MaterialsConfigTest, BadExtrasNameTheGltfAndTheMaterial) {
  const RunConfig c = load("  {}\n");
  for (const auto& [key, value, message] :
       {std::tuple{"scattering_delay.lifetime", "-1 ns", "lifetime: must be > 0"},
        std::tuple{"scattering_delay.lifetime", "2e-9", "a time needs a unit"},
        std::tuple{"scattering_delay.fraction", "2", "fraction: must be in [0, 1]"},
        std::tuple{"scattering_delay.lifetme", "1 ns", "lifetme: unknown key"}}) {
    scene::Scene scene;
    std::map<std::string, std::string> wax = {{"scattering_delay.model", "exponential"},
                                              {"scattering_delay.lifetime", "1 ns"}};
    wax[key] = value;
    scene.materials = {material("plain"), material("wax")};
    try {
      applyMaterialDelays(c, scene, {{}, wax});
      ADD_FAILURE() << key << " accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("scene.gltf: materials[1] 'wax'.extras.scattering_delay."),
                std::string::npos)
          << what;
      EXPECT_NE(what.find(message), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace tofsim::config
