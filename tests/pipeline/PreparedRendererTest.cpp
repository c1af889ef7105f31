// pipeline::PreparedRenderer, the renderer that stays loaded (issue 45 item
// 4): what a config may change without a reload and what forces one, decided
// in changeFor; renders through it keep the scene loaded and prepared once
// and write the bytes of a render of their own (CPU backend, no GL).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "MovingPlaneTest.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/RenderRun.h"

namespace tofsim::pipeline {
namespace {

using test_sequence::bytesOf;

// A still plane (the moving plane's scene at speed 0), 8 x 8 pixels.
class PreparedRendererTest : public test_sequence::MovingPlaneTest {
 protected:
  void SetUp() override {
    test_sequence::MovingPlaneTest::SetUp();
    writeScene(0.0);
  }
  config::RunConfig with(const std::vector<config::Override>& overrides) {
    return config::loadRunConfigText(configYaml("", kTime),
                                     dir_ / "c.yaml", overrides);
  }
};

TEST_F(PreparedRendererTest, WhatReloadsIsDecidedByChangeFor) {
  PreparedRenderer prepared;
  const config::RunConfig base = with({});
  EXPECT_TRUE(prepared.changeFor(base).scene);  // nothing loaded yet
  prepared.prepare(base);
  prepared.renderer(base);
  EXPECT_FALSE(prepared.changeFor(base).any());
  // Kept: the camera, the light, the time axis, the seed, the outputs.
  EXPECT_FALSE(prepared
                   .changeFor(with({{"camera.position", "[0.1, 0, 0]"},
                                    {"light.intensity", "7"},
                                    {"time.bins", "100"},
                                    {"render.seed", "9"},
                                    {"output.depth", "false"}}))
                   .any());
  // The renderer made again: its threads, its kind, its backend.
  const SetupChange threads = prepared.changeFor(with({{"render.threads", "1"}}));
  EXPECT_TRUE(threads.renderer);
  EXPECT_FALSE(threads.scene);
  EXPECT_EQ(threads.what, "render.threads");
  EXPECT_EQ(prepared.changeFor(with({{"render.renderer", "reference"}})).what, "render.renderer");
  EXPECT_EQ(prepared.changeFor(with({{"render.backend", "gl"}})).what, "render.backend");
  // The scene loaded again: another file, or the same file changed on disk.
  std::filesystem::copy_file(dir_ / "plane.gltf", dir_ / "other.gltf");
  const SetupChange other = prepared.changeFor(with({{"scene", "other.gltf"}}));
  EXPECT_TRUE(other.scene);
  EXPECT_FALSE(other.renderer);
  EXPECT_NE(other.what.find("the scene ("), std::string::npos) << other.what;
  std::ofstream(dir_ / "plane.gltf", std::ios::app) << "\n";
  EXPECT_NE(prepared.changeFor(base).what.find("contents"), std::string::npos);
}

// The materials' delays (issue 41) changing while the file stays: the scene
// is copied with the new delays (a new object, which an IR renderer prepares
// again), not loaded again; the same delays keep it.
TEST_F(PreparedRendererTest, NewMaterialDelaysCopyTheSceneWithoutAReload) {
  PreparedRenderer prepared;
  const config::RunConfig base = with({});
  prepared.prepare(base);
  const scene::Scene* before = &prepared.scene();
  ASSERT_EQ(before->materials.back().name, "default");  // the plane has no material of its own
  EXPECT_FALSE(before->materials.back().scatteringDelay.has_value());
  const config::RunConfig delayed =
      with({{"materials.default.scattering_delay", "{model: exponential, lifetime: 1 ns}"}});
  const SetupChange change = prepared.changeFor(delayed);
  EXPECT_TRUE(change.scene);
  EXPECT_FALSE(change.renderer);
  EXPECT_EQ(change.what, "the materials' scattering delays (materials:)");
  prepared.prepare(delayed);
  EXPECT_EQ(prepared.sceneLoads(), 1u);
  EXPECT_NE(&prepared.scene(), before);
  ASSERT_TRUE(prepared.scene().materials.back().scatteringDelay.has_value());
  EXPECT_DOUBLE_EQ(prepared.scene().materials.back().scatteringDelay->lifetime_s, 1e-9);
  EXPECT_FALSE(prepared.changeFor(delayed).any());
  EXPECT_TRUE(prepared.changeFor(base).scene);  // back to none
}

TEST_F(PreparedRendererTest, ReferenceSettingsMakeTheReferenceAgain) {
  PreparedRenderer prepared;
  const config::RunConfig reference = with({{"render.renderer", "reference"}});
  prepared.prepare(reference);
  prepared.renderer(reference);
  EXPECT_FALSE(prepared.changeFor(with({{"render.renderer", "reference"}})).any());
  EXPECT_EQ(prepared
                .changeFor(with({{"render.renderer", "reference"},
                                 {"render.reference.samples_per_pixel", "8"}}))
                .what,
            "render.reference");
}

TEST_F(PreparedRendererTest, RendersKeepTheSceneAndWriteTheBytesOfARenderOfTheirOwn) {
  PreparedRenderer prepared;
  for (const char* x : {"0", "0.2", "0.4"}) {
    const config::RunConfig c = with({{"camera.position", std::string("[") + x + ", 0, 0]"}});
    RunOptions kept, fresh;
    kept.quiet = fresh.quiet = true;
    kept.outputDirectory = dir_ / (std::string("kept_") + x);
    fresh.outputDirectory = dir_ / (std::string("fresh_") + x);
    runRender(c, prepared, kept);
    runRender(c, fresh);
    for (const char* f : {"transient.npy", "depth.npy", "config.effective.yaml"}) {
      EXPECT_EQ(bytesOf(kept.outputDirectory / f), bytesOf(fresh.outputDirectory / f)) << f;
    }
    // Light on the axis: the comparison is of a real render.
    const std::string volume = bytesOf(kept.outputDirectory / "transient.npy");
    EXPECT_NE(volume.find_first_not_of('\0', 128), std::string::npos);
  }
  EXPECT_EQ(prepared.sceneLoads(), 1u);
  EXPECT_EQ(prepared.rendererMakes(), 1u);
  EXPECT_EQ(prepared.scenePreparations(), 1u);
}

}  // namespace
}  // namespace tofsim::pipeline
