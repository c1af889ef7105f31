// Equal-error benchmark (issue 4): on the Cornell box, how long the CPU
// reference path tracer needs to reach the error of a transient instant
// radiosity render, both measured against a long-converged reference, all in
// one run on one machine. Also prints where each IR render's time went
// (RenderResult::passSeconds).
// Usage: equal_error SCENE.gltf [resolution] [gl|cpu] [point|box] [bounces]
//  - the IR backend, default gl (llvmpipe without a GPU);
//  - the pixel model (issue 14), default point: the ground truth and the
//    reference sweep use that render.reference.pixel_filter. point: IR with
//    render.pixel_footprint false (both sample pixel centres, issue 4's
//    bench); box: the pixel-area truth, and every IR setting is run with the
//    footprint (vpl_footprint true) and without it (pixel_footprint false),
//    with 2 x 2 samples everywhere, and with 2 x 2, 3 x 3 and 4 x 4 only at
//    the edges (render.adaptive_pixel_samples);
//  - bounces N (issue 15): IR with render.indirect.bounces N against the
//    reference with N + 1 interactions (truth and sweep alike) on a longer
//    axis, 1.5 .. 6.5 m (500 bins of 1 cm), that holds the later bounces'
//    light; without it, issue 4's bench: 1 bounce, 1.5 .. 3.5 m.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "support/TestJobs.h"  // the Cornell box job shared with the tests
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/compare/VolumeComparison.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/gl/Context.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/render/GlBackend.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/volume/PhysicalConstants.h"

#include "../BenchArgs.h"

namespace {

using namespace tofsim;

capture::RenderJob cornellJob(const scene::Scene& scene, int resolution, int bins) {
  capture::RenderJob job = test::cornellBoxJob(scene, resolution, bins, 0.01);
  job.settings.shadow_map_resolution = 1024;
  return job;
}

struct Measured {
  double seconds;
  compare::VolumeComparison error;
};

template <typename Render>
Measured measure(const capture::RenderJob& job, const TransientVolume& truth, Render render) {
  capture::VolumeCollector out(job.camera().width, job.camera().height, job.settings.time, 3);
  const auto start = std::chrono::steady_clock::now();
  render(out);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {seconds, compare::compareVolumes(out.total(), truth)};
}

Measured referenceRun(const capture::RenderJob& job, const TransientVolume& truth, int spp,
                      reference::PixelFilter filter, int bounces) {
  reference::ReferenceSettings s;
  s.bounces = bounces + 1;
  s.pixel_filter = filter;
  s.samples_per_pixel = spp;
  return measure(job, truth, [&](capture::VolumeCollector& out) {
    reference::ReferenceRenderer(s).render(job, out);
  });
}

// Reference time at which its transient error equals `target`, interpolated
// on the log-log line between the two sample counts that bracket it.
double timeAtError(const std::vector<std::pair<double, double>>& timeError, double target) {
  for (std::size_t i = 1; i < timeError.size(); ++i) {
    const auto [t0, e0] = timeError[i - 1];
    const auto [t1, e1] = timeError[i];
    if (e1 <= target && e0 >= target) {
      const double f = std::log(e0 / target) / std::log(e0 / e1);
      return std::exp(std::log(t0) + f * (std::log(t1) - std::log(t0)));
    }
  }
  return NAN;
}

struct IrCase {
  const char* name;
  capture::Visibility visibility;
  double clamp;
  int rsm;
  bool footprint;
  int pixelSamples;
  bool adaptive = false;  ///< render.adaptive_pixel_samples
};

std::vector<IrCase> irCases(bool box) {
  std::vector<IrCase> cases;
  for (bool footprint : box ? std::vector<bool>{true, false} : std::vector<bool>{false}) {
    for (const IrCase& c : {IrCase{"IR, ISM 32^2, clamp 100", capture::Visibility::Ism, 100.0, 32},
                            IrCase{"IR, ISM 32^2, clamp 100", capture::Visibility::Ism, 100.0, 64},
                            IrCase{"IR, exact, no clamp", capture::Visibility::Exact, 0.0, 32},
                            IrCase{"IR, exact, no clamp", capture::Visibility::Exact, 0.0, 64}}) {
      IrCase withFootprint = c;
      withFootprint.footprint = footprint;
      withFootprint.pixelSamples = 1;
      cases.push_back(withFootprint);
    }
  }
  if (!box) return cases;
  // Against the pixel-area truth the silhouettes need sub-pixel samples:
  // everywhere (2 x 2), and only at the G-buffer's edges (2 x 2, 3 x 3 and
  // 4 x 4 with RSM 32^2).
  for (std::size_t i = 0; i < 4; ++i) {
    IrCase supersampled = cases[i];
    supersampled.pixelSamples = 2;
    cases.push_back(supersampled);
  }
  for (const int n : {2, 3, 4}) {
    for (const std::size_t i : {std::size_t{0}, std::size_t{2}}) {
      IrCase adaptive = cases[i];
      adaptive.pixelSamples = n;
      adaptive.adaptive = true;
      cases.push_back(adaptive);
    }
  }
  return cases;
}

// Ground truth: the transport IR simulates (its bounces + 1 interactions),
// many paths, seed 99.
TransientVolume groundTruth(const capture::RenderJob& job, reference::PixelFilter filter,
                            int bounces) {
  capture::RenderJob truthJob = job;
  truthJob.settings.seed = 99;
  reference::ReferenceSettings truthSettings;
  truthSettings.bounces = bounces + 1;
  truthSettings.pixel_filter = filter;
  truthSettings.samples_per_pixel = 16384;
  capture::VolumeCollector truthOut(job.camera().width, job.camera().height, job.settings.time, 3);
  const auto t0 = std::chrono::steady_clock::now();
  reference::ReferenceRenderer(truthSettings).render(truthJob, truthOut);
  const double truthSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf(
      "ground truth: reference, %d interactions, pixel_filter %s, %d paths/pixel, %.1f s\n\n",
      truthSettings.bounces, filter == reference::PixelFilter::Box ? "box" : "point",
      truthSettings.samples_per_pixel, truthSeconds);
  return truthOut.total();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: equal_error SCENE.gltf [resolution] [gl|cpu] [point|box] [bounces]\n");
    return 2;
  }
  const int resolution = bench::arg(argc, argv, 2, 64);
  const scene::Scene scene = scene::loadGltf(argv[1]);
  const bool multiBounce = argc > 5;
  const int bounces = bench::arg(argc, argv, 5, 1);
  if (bounces < 1 || bounces > 8) {
    std::fprintf(stderr, "equal_error: bounces must be in [1, 8]\n");
    return 2;
  }
  capture::RenderJob job = cornellJob(scene, resolution, multiBounce ? 500 : 200);
  job.settings.indirect.bounces = bounces;
  const bool onCpu = argc > 3 && std::string(argv[3]) == "cpu";
  const bool box = argc > 4 && std::string(argv[4]) == "box";
  const reference::PixelFilter filter =
      box ? reference::PixelFilter::Box : reference::PixelFilter::Point;
  std::unique_ptr<gl::Context> context = onCpu ? nullptr : std::make_unique<gl::Context>();
  const auto makeIr = [&] {
    if (onCpu) return ir::IrRenderer(std::make_unique<cpu::CpuBackend>());
    return ir::IrRenderer(std::make_unique<render::GlBackend>(*context));
  };
  std::printf("IR device: %s; reference: Embree, %u threads\n", makeIr().description().c_str(),
              std::thread::hardware_concurrency());
  std::printf(
      "IR: %d indirect bounce(s); axis %.1f .. %.1f m of optical path\n", bounces,
      job.settings.time.start_m(),
      job.settings.time.start_m() + job.settings.time.bins * job.settings.time.bin_width_m());
  const TransientVolume truth = groundTruth(job, filter, bounces);

  std::printf(
      "| renderer | setting | seconds | steady rel. L1 | transient rel. L1 "
      "|\n|---|---|---|---|---|\n");
  std::vector<std::pair<std::string, Measured>> irRuns;
  std::vector<capture::PassSeconds> irPasses;
  for (const IrCase& c : irCases(box)) {
    capture::RenderJob irJob = job;
    irJob.settings.indirect.visibility = c.visibility;
    irJob.settings.indirect.geometry_term_clamp_per_m2 = c.clamp;
    irJob.settings.indirect.rsm_resolution = c.rsm;
    irJob.settings.pixel_footprint = c.footprint;
    irJob.settings.indirect.vpl_footprint = c.footprint;
    irJob.settings.pixel_samples = c.pixelSamples;
    irJob.settings.adaptive_pixel_samples = c.adaptive;
    const ir::IrRenderer renderer = makeIr();
    capture::RenderResult result;
    const Measured m = measure(
        irJob, truth, [&](capture::VolumeCollector& out) { result = renderer.render(irJob, out); });
    irPasses.push_back(result.passSeconds);
    const std::string setting =
        std::string(c.name) + ", RSM " + std::to_string(c.rsm) + "^2" +
        (c.footprint ? ", footprint" : ", no footprint") +
        (c.pixelSamples > 1
             ? ", pixel_samples " + std::to_string(c.pixelSamples) + (c.adaptive ? " at edges" : "")
             : "");
    std::printf("| IR | %s | %.2f | %.4f | %.4f |\n", setting.c_str(), m.seconds,
                m.error.steadyRelativeL1, m.error.transientRelativeL1);
    irRuns.emplace_back(setting, m);
  }
  std::printf(
      "\n| IR setting | surfaces | VPLs | visibility | direct | indirect | read-back | other "
      "|\n|---|---|---|---|---|---|---|---|\n");
  for (std::size_t i = 0; i < irRuns.size(); ++i) {
    const capture::PassSeconds& p = irPasses[i];
    std::printf("| %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |\n",
                irRuns[i].first.c_str(), p.surfaces, p.vpls, p.visibility, p.direct, p.indirect,
                p.readBack, p.other);
  }
  std::printf("\n");
  std::vector<std::pair<double, double>> timeError;
  for (int spp = 1; spp <= 4096; spp *= 2) {
    const Measured m = referenceRun(job, truth, spp, filter, bounces);
    std::printf("| reference | %d paths/pixel | %.2f | %.4f | %.4f |\n", spp, m.seconds,
                m.error.steadyRelativeL1, m.error.transientRelativeL1);
    timeError.emplace_back(m.seconds, m.error.transientRelativeL1);
  }
  std::printf(
      "\n| IR setting | IR seconds | reference seconds at equal transient error | speed-up "
      "|\n|---|---|---|---|\n");
  for (const auto& [setting, m] : irRuns) {
    const double t = timeAtError(timeError, m.error.transientRelativeL1);
    std::printf("| %s | %.2f | %s | %s |\n", setting.c_str(), m.seconds,
                std::isnan(t) ? "outside the measured range" : std::to_string(t).c_str(),
                std::isnan(t) ? "-" : std::to_string(t / m.seconds).c_str());
  }
  return 0;
}
