// IR with exact visibility against the converged reference path tracer,
// region by region and time window by time window (issue 45, item 2): at
// RSM 256^2 the one-bounce light of every 8 x 8 pixel block of the image must
// be the reference's within 2 % in each window (the direct peak, the next
// 400 ps, after 1 ns), the late multipath light included. The Cornell box
// protocol of bench/equal_error (30-degree hard spot, 20 ps bins from 1.5 m,
// clamp 0) at 32 x 32 pixel centres (render.pixel_footprint: false against
// the reference's point filter): 16 regions.
//
// The reference at 8192 paths per pixel (524k paths per region): its own
// noise per region and window, from a second seed, is 0.01 / 0.40 / 0.54 %
// rms and 0.04 / 1.1 / 1.1 % at most. IR's worst region against it (the
// direct peak / the next 400 ps / after 1 ns): 0.49 / 1.86 / 0.96 % (seed 2:
// 0.48 / 1.32 / 0.93 %); the 1.9 % is a floor region next to the camera,
// 1.5 % over the reference with both seeds, IR's own, so the margin is
// small. The test fails with a wrong setting: RSM 64^2 (2.7 / 3.5 % in the
// late windows; 128^2 passes at 1.9 %), no visibility (every VPL sees every
// pixel: 24 / 115 %, checked below on every run) and a reference with two
// bounces (reference.bounces 3: 29 / 95 %). A window's error is relative to
// the region's own light, or to a quarter of the mean region's where a region
// holds less (2 regions of 16 after 1 ns). About 5 CPU-seconds: IR 1.5, the
// reference 3.
// bench/README.md, "The ISM's bias".

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::cpu {
namespace {

using namespace capture;

constexpr int kSide = 32, kBlock = 8, kRegions = kSide / kBlock;
using WindowLight = std::array<double, 3>;  ///< the direct peak, the next 400 ps, after 1 ns

double lightAt(const TransientVolume& v, int y, int x, int32_t t) {
  double sum = 0.0;
  for (int c = 0; c < v.channels(); ++c) sum += v.at(y, x, t, c);
  return sum;
}

// Each pixel's peak bin (the direct light: exact in both renderers).
std::vector<int32_t> peaksOf(const TransientVolume& v) {
  std::vector<int32_t> peaks;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      int32_t best = 0;
      for (int32_t t = 1; t < v.bins(); ++t)
        best = lightAt(v, y, x, t) > lightAt(v, y, x, best) ? t : best;
      peaks.push_back(best);
    }
  }
  return peaks;
}

// The light of each region in the three windows, each from its pixel's peak
// (up to 100 ps after it; 100-500 ps after; more than 1 ns after).
std::vector<WindowLight> regionLight(const TransientVolume& v, const std::vector<int32_t>& peaks) {
  const auto after = [&](double s) { return static_cast<int32_t>(s / v.axis().bin_width_s + 0.5); };
  const int32_t peakEnd = after(100e-12), nextEnd = after(500e-12), late = after(1e-9);
  std::vector<WindowLight> out(kRegions * kRegions, WindowLight{});
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const int32_t peak = peaks[y * kSide + x];
      WindowLight& r = out[(y / kBlock) * kRegions + x / kBlock];
      for (int32_t t = 0; t < v.bins(); ++t) {
        const double light = lightAt(v, y, x, t);
        if (t <= peak + peakEnd)
          r[0] += light;
        else if (t <= peak + nextEnd)
          r[1] += light;
        if (t > peak + late) r[2] += light;
      }
    }
  }
  return out;
}

// The worst region's |IR - reference| per window, relative to the region's
// light or to a quarter of the mean region's, whichever is more.
WindowLight worstRegion(const std::vector<WindowLight>& ir, const std::vector<WindowLight>& ref) {
  WindowLight worst{};
  for (int w = 0; w < 3; ++w) {
    double mean = 0.0;
    for (const WindowLight& r : ref) mean += r[w] / static_cast<double>(ref.size());
    for (std::size_t i = 0; i < ref.size(); ++i) {
      worst[w] =
          std::max(worst[w], std::abs(ir[i][w] - ref[i][w]) / std::max(ref[i][w], 0.25 * mean));
    }
  }
  return worst;
}

TEST(ExactVisibilityRegionsTest, ExactVisibilityAtRsm256IsTheReferenceByRegionAndWindow) {
  const scene::Scene scene = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  RenderJob job = test::cornellBoxJob(scene, kSide, 371, 0.006);
  job.light.cone_half_angle_deg = 30.0f;
  job.settings.indirect.rsm_resolution = 256;
  job.settings.indirect.visibility = Visibility::Exact;
  job.settings.indirect.geometry_term_clamp_per_m2 = 0.0;
  job.settings.pixel_footprint = false;  // pixel centres, as the point filter
  reference::ReferenceSettings settings;
  settings.pixel_filter = reference::PixelFilter::Point;
  settings.bounces = 2;  // direct + one bounce, as IR's RSM VPLs
  settings.samples_per_pixel = 8192;
  settings.threads = 2;
  VolumeCollector ref(kSide, kSide, job.settings.time, 3);
  reference::ReferenceRenderer(settings).render(job, ref);
  const auto irRegions = [&](bool visibility, std::vector<int32_t>& peaks) {
    VolumeCollector ir(kSide, kSide, job.settings.time, 3);
    ir::IrRenderer(std::make_unique<CpuBackend>(CpuBackendOptions{2, visibility})).render(job, ir);
    const TransientVolume total = ir.total();
    if (peaks.empty()) peaks = peaksOf(total);
    return regionLight(total, peaks);
  };
  std::vector<int32_t> peaks;
  const std::vector<WindowLight> exact = irRegions(true, peaks);
  const std::vector<WindowLight> truth = regionLight(ref.total(), peaks);
  const WindowLight worst = worstRegion(exact, truth);
  const char* names[] = {"the direct peak", "the next 400 ps", "after 1 ns"};
  for (int w = 0; w < 3; ++w) EXPECT_LT(worst[w], 0.02) << names[w];
  // The same comparison sees a wrong visibility: every VPL lighting every
  // pixel puts light behind the blocks, late.
  const WindowLight unshadowed = worstRegion(irRegions(false, peaks), truth);
  std::printf("worst region: exact %.4f / %.4f / %.4f, without visibility %.4f / %.4f / %.4f\n",
              worst[0], worst[1], worst[2], unshadowed[0], unshadowed[1], unshadowed[2]);
  EXPECT_GT(unshadowed[2], 0.2) << "without visibility, after 1 ns";
}

}  // namespace
}  // namespace tofsim::cpu
