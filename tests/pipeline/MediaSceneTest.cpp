// Issue 42's per-region media where the pipeline configures the scene
// (ConfiguredScene.cpp, PreparedRenderer.cpp): regions whose boxes overlap
// or nest are refused at the later entry's `region`, apart ones are taken
// out of the surfaces in order; a batch worker that keeps its scene reads
// the file again when the regions change (a region's mesh is a surface
// again without `media:`). No GL: nothing renders.

#include <gtest/gtest.h>

#include <string>

#include "support/AnalyticScenes.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/ConfiguredScene.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {
namespace {

using test::addBox;

config::RunConfig withRegions(std::initializer_list<const char*> names) {
  config::RunConfig c;
  int line = 10;
  for (const char* name : names) {
    capture::RegionMedium r;
    r.region = name;
    r.medium.sigma_a_per_m = glm::vec3(0.1f);
    c.render.media.push_back(r);
    c.media.push_back({FileLoc{"c.yaml", line, 5}, FileLoc{"c.yaml", line, 14}});
    ++line;
  }
  return c;
}

TEST(MediaSceneTest, RegionsThatOverlapOrNestAreRefusedApartOnesAreTakenOut) {
  scene::Scene s = test::makePlane(4.0f);
  addBox(s, "a", glm::vec3(0.0f), glm::vec3(1.0f));
  addBox(s, "b", glm::vec3(0.5f), glm::vec3(1.5f));          // overlaps a
  addBox(s, "inner", glm::vec3(0.25f), glm::vec3(0.75f));    // inside a
  addBox(s, "c", glm::vec3(2.0f), glm::vec3(3.0f));          // apart
  for (const char* other : {"b", "inner"}) {
    scene::Scene copy = s;
    try {
      takeMediumRegions(withRegions({"a", other}), copy);
      ADD_FAILURE() << other << " was not refused";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("c.yaml:11:14: media[1].region: the region '" + std::string(other) +
                          "' overlaps the region 'a' (c.yaml:10:14)"),
                std::string::npos)
          << what;
    }
  }
  takeMediumRegions(withRegions({"c", "a"}), s);
  ASSERT_EQ(s.regions.size(), 2u);
  EXPECT_EQ(s.regions[0].name, "c");
  EXPECT_EQ(s.regions[1].name, "a");
  EXPECT_EQ(s.meshes.size(), 3u);  // the plane, b and inner stay surfaces
}

TEST(MediaSceneTest, APreparedSceneIsReadAgainWhenTheRegionsChange) {
  config::RunConfig water = withRegions({"water_tank"});
  water.scene_file = std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/water_tank.gltf";
  water.backend = config::IrBackendKind::Cpu;
  config::RunConfig air = water;
  air.render.media.clear();
  air.media.clear();
  PreparedRenderer prepared;
  prepared.prepare(water);
  const std::size_t surfaces = prepared.scene().meshes.size();
  EXPECT_EQ(prepared.scene().regions.size(), 1u);
  EXPECT_FALSE(prepared.changeFor(water).scene);
  const SetupChange change = prepared.changeFor(air);
  EXPECT_TRUE(change.scene);
  EXPECT_EQ(change.what, "the media's regions (media:)");
  prepared.prepare(air);
  EXPECT_TRUE(prepared.scene().regions.empty());
  EXPECT_EQ(prepared.scene().meshes.size(), surfaces + 1);  // the tank is a surface again
}

}  // namespace
}  // namespace tofsim::pipeline
