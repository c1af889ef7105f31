// Issue 42's medium where a run's settings are recorded (no rendering): the
// run content key follows the medium, so a batch re-renders a run whose
// medium changed; batch sweeps and --set reach medium keys; transient.json
// says what the medium was, and says nothing of one without it.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "support/TempDir.h"
#include "tofsim/config/BatchConfig.h"
#include "tofsim/pipeline/Metadata.h"
#include "tofsim/pipeline/RunContentKey.h"

namespace tofsim::pipeline {
namespace {

const std::string kBase = std::string(TOFSIM_SOURCE_DIR) + "/configs/cornell_box.yaml";

config::RunConfig loadWith(const std::vector<std::string>& sets) {
  std::vector<config::Override> overrides;
  for (const std::string& s : sets) overrides.push_back(config::parseOverride(s));
  return config::loadRunConfig(kBase, overrides);
}

std::string configKey(const std::vector<std::string>& sets) {
  return runContentKey(loadWith(sets), "scene").config;
}

TEST(MediumRunRecordTest, ContentKeyChangesWithTheMedium) {
  const std::string vacuum = configKey({});
  const std::string fog = configKey({"medium.sigma_s=0.05"});
  EXPECT_NE(fog, vacuum);
  EXPECT_EQ(configKey({"medium.sigma_s=0.05"}), fog);  // the same medium, the same key
  EXPECT_NE(configKey({"medium.sigma_s=0.1"}), fog);
  EXPECT_NE(configKey({"medium.sigma_s=0.05", "medium.sigma_a=0.01"}), fog);
  EXPECT_NE(configKey({"medium.sigma_s=0.05", "medium.phase=rayleigh"}), fog);
  EXPECT_NE(configKey({"medium.visibility=50 m"}), configKey({"medium.visibility=40 m"}));
}

TEST(MediumRunRecordTest, MetadataRecordsTheMedium) {
  const config::RunConfig c = loadWith({"medium.visibility=50 m"});
  capture::RenderJob job;
  job.imager = c.camera.camera;
  job.light = c.light.light;
  job.settings = c.render;
  const nlohmann::json j =
      nlohmann::json::parse(transientMetadataJson(c, job, capture::RenderResult{}, "cpu", "test"));
  ASSERT_TRUE(j.contains("medium")) << j.dump(2);
  const nlohmann::json& m = j["medium"];
  EXPECT_NEAR(m["sigma_t_per_m"][1].get<double>(), 3.912 / 50.0, 1e-7);
  EXPECT_NEAR(m["albedo"][0].get<double>(), 0.99996, 1e-6);
  EXPECT_NEAR(m["sigma_a_per_m"][2].get<double>(), (1.0 - 0.99996) * 3.912 / 50.0, 1e-8);
  EXPECT_EQ(m["phase"], "henyey_greenstein");
  EXPECT_NEAR(m["g"].get<double>(), 0.845, 1e-6);
  EXPECT_DOUBLE_EQ(m["visibility_m"].get<double>(), 50.0);
  EXPECT_DOUBLE_EQ(m["index_of_refraction"].get<double>(), 1.0);

  // Coefficients given: no visibility; an isotropic medium has no g.
  const config::RunConfig iso = loadWith({"medium.sigma_s=[0.1, 0.2, 0.3]"});
  job.settings = iso.render;
  const nlohmann::json k = nlohmann::json::parse(
      transientMetadataJson(iso, job, capture::RenderResult{}, "cpu", "test"))["medium"];
  EXPECT_NEAR(k["sigma_s_per_m"][2].get<double>(), 0.3, 1e-7);
  EXPECT_EQ(k["phase"], "isotropic");
  EXPECT_FALSE(k.contains("g"));
  EXPECT_FALSE(k.contains("visibility_m"));

  // Without a medium, no `medium` key.
  const config::RunConfig vacuum = loadWith({});
  job.settings = vacuum.render;
  EXPECT_FALSE(nlohmann::json::parse(
                   transientMetadataJson(vacuum, job, capture::RenderResult{}, "cpu", "test"))
                   .contains("medium"));
}

class MediumBatchTest : public test::TempDirTest {};

TEST_F(MediumBatchTest, SweepsReachMediumKeys) {
  std::ofstream(dir_ / "batch.yaml")
      << "base: " << kBase
      << "\nsweep:\n  product:\n    medium.sigma_s: [0.02, 0.05]\n"
         "    medium.phase: [isotropic, {model: henyey_greenstein, g: 0.6}]\n";
  const config::BatchConfig b = config::loadBatchConfig(dir_ / "batch.yaml");
  ASSERT_EQ(b.runCount(), 4u);
  std::set<std::string> keys;
  for (std::size_t i = 0; i < b.runCount(); ++i) {
    const config::RunConfig c = config::loadRunConfig(b.base_config, b.run(i).overrides);
    EXPECT_FLOAT_EQ(c.render.medium.sigma_s_per_m.r, i < 2 ? 0.02f : 0.05f) << b.run(i).name;
    EXPECT_FLOAT_EQ(c.render.medium.g, i % 2 == 0 ? 0.0f : 0.6f) << b.run(i).name;
    keys.insert(runContentKey(c, "scene").config);
  }
  EXPECT_EQ(keys.size(), 4u);  // each run its own key
}

}  // namespace
}  // namespace tofsim::pipeline
