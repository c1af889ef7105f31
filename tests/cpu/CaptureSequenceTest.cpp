// A sequence of captures through one renderer (IrRenderer::render called
// again with the same scene): the scene is prepared once (one Embree BVH for
// the backend and the later bounces), and every capture's bytes are those of
// a render on a fresh renderer, whatever came before it.

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "support/CpuRender.h"
#include "support/TestJobs.h"

namespace tofsim::cpu {
namespace {

bool sameBytes(const TransientVolume& a, const TransientVolume& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// Three captures of the corner with two bounces: two light positions (a
// scan's laser positions) and a point-set imager on the wall between them.
std::vector<capture::RenderJob> captures(const test::CornerJob& corner) {
  capture::RenderJob base = corner.job;
  base.settings.indirect.bounces = 2;
  base.settings.indirect.rsm_resolution = 8;
  std::vector<capture::RenderJob> jobs(3, base);
  jobs[1].light.position_world = {-0.4f, 1.3f, 0.8f};
  jobs[2].imager =
      capture::gridOnPlanarMesh(corner.scene, "quad1", 6, 5, glm::vec3(0.2f, 1.0f, 1.5f));
  return jobs;
}

TEST(CaptureSequenceTest, CapturesThroughOneRendererGiveTheBytesOfSeparateRenders) {
  const test::CornerJob corner(12);
  const std::vector<capture::RenderJob> jobs = captures(corner);
  const ir::IrRenderer renderer(std::make_unique<CpuBackend>(CpuBackendOptions{2, true}));
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    const capture::RenderJob& job = jobs[k];
    capture::VolumeCollector inSequence(capture::imageWidth(job.imager),
                                        capture::imageHeight(job.imager), job.settings.time,
                                        capture::kChannels);
    renderer.render(job, inSequence);
    const test::CpuRender alone = test::renderOnCpu(job);
    EXPECT_TRUE(sameBytes(inSequence.total(), alone.volume.total())) << "capture " << k;
    EXPECT_GT(alone.result.vpls, 0u);
  }
  EXPECT_EQ(renderer.scenePreparations(), 1u) << "one scene, prepared once";
}

TEST(CaptureSequenceTest, AChangedOrOtherSceneIsPreparedAgain) {
  test::CornerJob corner(8);
  const ir::IrRenderer renderer(std::make_unique<CpuBackend>(CpuBackendOptions{2, true}));
  capture::VolumeCollector sink(8, 8, corner.job.settings.time, capture::kChannels);
  renderer.render(corner.job, sink);
  renderer.render(corner.job, sink);
  EXPECT_EQ(renderer.scenePreparations(), 1u);
  // Moved in place (an animation's next frame): the renderer is told.
  for (glm::vec3& p : corner.scene.meshes[1].positions_world) p.z -= 0.25f;
  renderer.sceneChanged();
  capture::VolumeCollector moved(8, 8, corner.job.settings.time, capture::kChannels);
  renderer.render(corner.job, moved);
  EXPECT_EQ(renderer.scenePreparations(), 2u);
  EXPECT_TRUE(sameBytes(moved.total(), test::renderOnCpu(corner.job).volume.total()))
      << "the moved wall's light, not the old one's";
  const test::CornerJob other(8);
  renderer.render(other.job, sink);
  EXPECT_EQ(renderer.scenePreparations(), 3u);
}

}  // namespace
}  // namespace tofsim::cpu
