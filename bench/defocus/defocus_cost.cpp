// The cost of thin-lens defocus (camera.aperture, capture/ThinLens.h)
// against the pinhole, in one run: the Cornell box (configs/scenes), its
// published camera with the light at the lens, on the CPU IR backend (the
// one that gathers aperture samples), rendered `runs` times per variant with
// the variants interleaved so that the machine's load hits them alike. Each
// variant traces and gathers `aperture_samples` K points of the aperture
// per pixel (focus on the back wall, 0.8 m + 0.56 m away; an 8 mm aperture).
// Prints each variant's median render seconds, its passes (surfaces: the
// first-surface rays; direct; indirect gathers) and the ratio to the pinhole,
// beside the pinhole with 4 x 4 sub-pixel samples (the rays of K = 16).
// Usage: tofsim_defocus_cost [side=48] [runs=3] [threads=2] [bins=256]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/scene/GltfLoader.h"

#include "../BenchArgs.h"

namespace {

using namespace tofsim;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Samples {
  std::vector<double> total, surfaces, direct, indirect;
};

}  // namespace

int main(int argc, char** argv) {
  const int side = bench::arg(argc, argv, 1, 48);
  const int runs = bench::arg(argc, argv, 2, 3);
  const int threads = bench::arg(argc, argv, 3, 2);
  const int bins = bench::arg(argc, argv, 4, 256);
  const scene::Scene box = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  capture::RenderJob job = test::cornellBoxJob(box, side, bins, 0.01);
  job.settings.indirect.rsm_resolution = 16;
  // The pinhole, K aperture points, and for scale the pinhole with 4 x 4
  // sub-pixel samples (render.pixel_samples: 4): as many rays as K = 16.
  struct Variant {
    const char* name;
    int aperture_samples;  ///< 0: the pinhole
    int pixel_samples;
  };
  const Variant variants[] = {{"pinhole", 0, 1},
                              {"K = 4", 4, 1},
                              {"K = 16", 16, 1},
                              {"K = 64", 64, 1},
                              {"pinhole, 4 x 4 sub-pixels", 0, 4}};
  std::vector<Samples> samples(std::size(variants));
  std::size_t vpls = 0;
  const ir::IrRenderer renderer(std::make_unique<cpu::CpuBackend>(cpu::CpuBackendOptions{threads}));
  for (int r = 0; r < runs; ++r) {
    for (std::size_t v = 0; v < std::size(variants); ++v) {
      capture::Camera& c = job.camera();
      c.aperture_m = variants[v].aperture_samples == 0 ? 0.0f : 0.008f;
      c.focus_distance_m = 1.36f;
      c.aperture_samples = std::max(2, variants[v].aperture_samples);
      job.settings.pixel_samples = variants[v].pixel_samples;
      capture::VolumeCollector volume(side, side, job.settings.time, capture::kChannels);
      const capture::RenderResult result = renderer.render(job, volume);
      vpls = result.vpls;
      samples[v].total.push_back(result.seconds);
      samples[v].surfaces.push_back(result.passSeconds.surfaces);
      samples[v].direct.push_back(result.passSeconds.direct);
      samples[v].indirect.push_back(result.passSeconds.indirect);
    }
  }
  std::printf("Cornell box %dx%d, %d bins, RSM 16^2 (%zu VPLs), CPU backend, %d threads, %d runs\n",
              side, side, bins, vpls, threads, runs);
  std::printf("| variant | render s | ratio | surfaces s | direct s | indirect s |\n");
  std::printf("|---|---|---|---|---|---|\n");
  const double base = median(samples[0].total);
  for (std::size_t v = 0; v < std::size(variants); ++v) {
    const double t = median(samples[v].total);
    std::printf("| %s | %.3f | %.2f | %.3f | %.3f | %.3f |\n", variants[v].name, t, t / base,
                median(samples[v].surfaces), median(samples[v].direct),
                median(samples[v].indirect));
  }
  return 0;
}
