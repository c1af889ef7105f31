// render.indirect.merge_pixel_samples on the CPU backend: the samples of one
// flat surface merge into one with their summed albedo weight and a footprint
// over their bounding box; a merged render's indirect light is near the
// per-sample render's and keeps an edge pixel's coverage (far from one
// sample's), its direct light is the per-sample render's, and its bytes do
// not depend on the thread count;
// without pixel samples or with glTF materials nothing changes.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "MergedSamples.h"
#include "support/CpuRender.h"
#include "support/TestJobs.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::cpu {
namespace {

using test::CpuRender;
using test::renderOnCpu;

PixelSurface sample(bool wall, float u, float v) {
  PixelSurface s;
  s.x = wall ? glm::vec3(u, v, 0.0f) : glm::vec3(u, 0.0f, v);
  s.n = wall ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  s.brdf = glm::vec3(0.1f, 0.2f, 0.3f) * (1.0f + u);
  s.dxdu = glm::vec3(0.01f, 0.0f, 0.0f);
  s.dxdv = glm::vec3(0.0f, 0.02f, 0.0f);
  return s;
}

TEST(MergedPixelSamplesTest, SamplesOnOneSurfaceMergeWithTheirWeight) {
  // 3 x 3 samples: the left two columns on the wall, the right one on the
  // floor, the floor's top sample sees nothing.
  constexpr int n = 3;
  PixelSurface samples[n * n];
  unsigned char lit[n * n];
  for (int s = 0; s < n * n; ++s) {
    samples[s] = sample(s % n < 2, 0.01f * (s % n), 0.01f * (s / n + 1));
    lit[s] = s != 8 ? 1 : 0;
  }
  std::vector<PixelSurface> merged;
  mergePixelSamples(samples, lit, n, merged);
  ASSERT_EQ(merged.size(), 2u);
  glm::vec3 wall(0.0f), floor(0.0f);
  for (int s = 0; s < n * n; ++s) {
    if (lit[s]) (s % n < 2 ? wall : floor) += samples[s].brdf;
  }
  // The wall's 6: centroid (0.5, 1), nearest (0, 1) first; a 2 x 3 box, full.
  EXPECT_EQ(merged[0].x, samples[3].x);
  EXPECT_FLOAT_EQ(merged[0].brdf.g, wall.g);
  EXPECT_FLOAT_EQ(merged[0].dxdu.x, 0.02f);
  EXPECT_FLOAT_EQ(merged[0].dxdv.y, 0.06f);
  // The floor's 2: centroid (2, 0.5), nearest (2, 0); a 1 x 2 box.
  EXPECT_EQ(merged[1].x, samples[2].x);
  EXPECT_FLOAT_EQ(merged[1].brdf.b, floor.b);
  EXPECT_FLOAT_EQ(merged[1].dxdu.x, 0.01f);
  EXPECT_FLOAT_EQ(merged[1].dxdv.y, 0.04f);
  // A lone sample is itself.
  unsigned char one[n * n] = {0, 0, 0, 0, 1, 0, 0, 0, 0};
  merged.clear();
  mergePixelSamples(samples, one, n, merged);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(std::memcmp(&merged[0], &samples[4], sizeof(PixelSurface)), 0);
}

bool sameBytes(const TransientVolume& a, const TransientVolume& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// Per-pixel light summed over time and channels.
std::vector<double> steady(const TransientVolume& v) {
  std::vector<double> light(static_cast<std::size_t>(v.width()) * v.height(), 0.0);
  const std::size_t perPixel = static_cast<std::size_t>(v.bins()) * v.channels();
  for (std::size_t i = 0; i < v.size(); ++i) light[i / perPixel] += v.data()[i];
  return light;
}

double relativeL1(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0.0, sum = 0.0;
  for (std::size_t p = 0; p < a.size(); ++p) diff += std::abs(a[p] - b[p]), sum += b[p];
  return diff / sum;
}

TEST(MergedPixelSamplesTest, MergedIndirectLightIsThePerSampleRendersAndKeepsTheCoverage) {
  const scene::Scene scene = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  capture::RenderJob job = test::cornellBoxJob(scene, 24, 120, 0.02);
  job.settings.indirect.rsm_resolution = 24;
  job.settings.indirect.visibility = capture::Visibility::Exact;
  job.settings.pixel_samples = 3;
  job.settings.adaptive_pixel_samples = true;
  const CpuRender all = renderOnCpu(job);
  job.settings.indirect.merge_pixel_samples = true;
  const CpuRender merged = renderOnCpu(job);
  const CpuRender mergedOneThread = renderOnCpu(job, {1, true});
  job.settings.pixel_samples = 1;
  const CpuRender one = renderOnCpu(job);
  // The direct light keeps every sample: the same bytes.
  EXPECT_TRUE(sameBytes(merged.volume.direct, all.volume.direct));
  EXPECT_TRUE(sameBytes(merged.volume.indirect, mergedOneThread.volume.indirect));
  const double toAll = relativeL1(steady(merged.volume.indirect), steady(all.volume.indirect));
  const double oneToAll = relativeL1(steady(one.volume.indirect), steady(all.volume.indirect));
  std::printf("steady indirect, relative L1 to every sample's: merged %.4f, one sample %.4f\n",
              toAll, oneToAll);
  // Measured 0.026 against 0.111: at 24 x 24 a pixel beside a crease is
  // wide enough for its indirect light to curve across it (it rises toward
  // the crease), which one gather at the group's middle sample misses; at
  // 64^2 and 256^2 the protocol's all-pixel error moved by 0.1 and 0.0 %
  // (bench/README.md, "Merged pixel samples").
  EXPECT_LT(toAll, 0.035);
  EXPECT_LT(toAll, 0.3 * oneToAll) << "the edge pixels' coverage must stay";
}

TEST(MergedPixelSamplesTest, WithoutPixelSamplesOrWithGltfMaterialsNothingChanges) {
  test::CornerJob s(12);
  s.job.settings.indirect.rsm_resolution = 12;
  const CpuRender plain = renderOnCpu(s.job);
  s.job.settings.indirect.merge_pixel_samples = true;
  EXPECT_TRUE(sameBytes(renderOnCpu(s.job).volume.indirect, plain.volume.indirect));
  s.job.settings.materials = capture::MaterialModel::Gltf;
  s.job.settings.pixel_samples = 2;
  const CpuRender gltfMerged = renderOnCpu(s.job);
  s.job.settings.indirect.merge_pixel_samples = false;
  EXPECT_TRUE(sameBytes(gltfMerged.volume.indirect, renderOnCpu(s.job).volume.indirect));
}

}  // namespace
}  // namespace tofsim::cpu
