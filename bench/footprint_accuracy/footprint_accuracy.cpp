// IR (CPU backend) against the converged reference path tracer with the box
// pixel filter (the pixel-area truth, issue 14), in 100 ps bins, on the
// corner (floor + wall) and the Cornell box: transient and steady relative L1
// of the total, the direct and the indirect volume, with the pixel footprint
// and without it, so that a test can state bounds. The reference's own noise
// (the same render with another seed) is printed next to them: the floor
// below which no bound can go.
// Usage: tofsim_footprint_accuracy [reference_spp=16384] [corner_side=16] [cornell_side=24]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/compare/VolumeComparison.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/volume/PhysicalConstants.h"

#include "../BenchArgs.h"

namespace {

using namespace tofsim;

constexpr double kBin_s = 100e-12;

struct Parts {
  TransientVolume total, direct, indirect;
  double seconds = 0.0;
};

Parts collect(const capture::RenderJob& job, const capture::Renderer& renderer) {
  capture::VolumeCollector out(job.camera().width, job.camera().height, job.settings.time, 3);
  const auto start = std::chrono::steady_clock::now();
  renderer.render(job, out);
  Parts parts{out.total(), out.direct, out.indirect};
  parts.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return parts;
}

Parts referenceRender(capture::RenderJob job, int spp, uint64_t seed) {
  reference::ReferenceSettings settings;
  settings.pixel_filter = reference::PixelFilter::Box;
  settings.bounces = 2;
  settings.samples_per_pixel = spp;
  job.settings.seed = seed;
  return collect(job, reference::ReferenceRenderer(settings));
}

void printRow(const std::string& name, const Parts& a, const Parts& truth) {
  const auto total = compare::compareVolumes(a.total, truth.total);
  const auto direct = compare::compareVolumes(a.direct, truth.direct);
  const auto indirect = compare::compareVolumes(a.indirect, truth.indirect);
  std::printf("| %s | %.2f | %.4f | %.4f | %.4f | %.4f | %.4f |\n", name.c_str(), a.seconds,
              total.transientRelativeL1, direct.transientRelativeL1, indirect.transientRelativeL1,
              total.steadyRelativeL1, indirect.steadyRelativeL1);
}

struct IrCase {
  const char* name;
  bool footprint;
  bool vplFootprint;
  int pixelSamples;
  int rsm;
};

void compareScene(const char* title, capture::RenderJob job, int spp) {
  job.settings.indirect.visibility = capture::Visibility::Exact;
  job.settings.indirect.geometry_term_clamp_per_m2 = 0.0;
  const Parts truth = referenceRender(job, spp, 99);
  std::printf(
      "\n%s: %dx%d, %d bins of 100 ps from %.3f m; IR: CPU backend, exact visibility, "
      "no clamp; truth: reference, box filter, 2 bounces, %d paths/pixel, seed 99 (%.1f s)\n\n",
      title, job.camera().width, job.camera().height, job.settings.time.bins,
      job.settings.time.start_s * kSpeedOfLight_m_per_s, spp, truth.seconds);
  std::printf(
      "| render | seconds | total transient L1 | direct transient L1 | indirect transient L1 "
      "| total steady L1 | indirect steady L1 |\n|---|---|---|---|---|---|---|\n");
  printRow("reference, box, seed 7 (noise floor)", referenceRender(job, spp, 7), truth);
  reference::ReferenceSettings point;
  point.pixel_filter = reference::PixelFilter::Point;
  point.samples_per_pixel = spp;
  printRow("reference, point filter", collect(job, reference::ReferenceRenderer(point)), truth);
  for (const IrCase& c : {IrCase{"footprint, vpl_footprint", true, true, 1, 32},
                          IrCase{"footprint, no vpl_footprint", true, false, 1, 32},
                          IrCase{"no footprint", false, false, 1, 32},
                          IrCase{"footprint, vpl_footprint", true, true, 1, 64},
                          IrCase{"no footprint", false, false, 1, 64},
                          IrCase{"footprint, vpl_footprint, pixel_samples 2", true, true, 2, 64},
                          IrCase{"no footprint, pixel_samples 2", false, false, 2, 64}}) {
    capture::RenderJob irJob = job;
    irJob.settings.pixel_footprint = c.footprint;
    irJob.settings.indirect.vpl_footprint = c.vplFootprint;
    irJob.settings.pixel_samples = c.pixelSamples;
    irJob.settings.indirect.rsm_resolution = c.rsm;
    const ir::IrRenderer renderer(std::make_unique<cpu::CpuBackend>());
    printRow("IR RSM " + std::to_string(c.rsm) + "^2, " + c.name, collect(irJob, renderer), truth);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int spp = bench::arg(argc, argv, 1, 16384);
  const int cornerSide = bench::arg(argc, argv, 2, 16);
  const int cornellSide = bench::arg(argc, argv, 3, 24);
  test::CornerJob corner(cornerSide);
  corner.job.settings.time = TimeAxis{0.0, kBin_s, 334};  // 0 .. 10 m, as CornerJob's axis
  compareScene("corner", corner.job, spp);
  const scene::Scene box = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  capture::RenderJob cornell =
      test::cornellBoxJob(box, cornellSide, 80, kBin_s * kSpeedOfLight_m_per_s);  // 1.5 .. 3.9 m
  cornell.settings.shadow_map_resolution = 1024;
  compareScene("Cornell box", cornell, spp);
  return 0;
}
