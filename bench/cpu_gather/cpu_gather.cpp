// Pairs per second of the indirect gather (VPL x pixel pairs, every pixel of
// the image counted) on the corner scene, on the CPU backend and on the GL one
// (llvmpipe without a GPU) in the same run: without visibility (CPU only; the
// GL backend always tests it), with exact visibility (Embree occlusion rays /
// the GL's BVH shadow rays) and with ISMs (build included). The read-back of
// the segment waits for the GL's work; a second read-back, timed alone, is
// taken off on both backends ("gather"). "segment" adds what a render's
// segment pays around it: the clear at beginSegment and one read-back copy.
// Usage: tofsim_cpu_gather [threads] [side] [rsm_resolution] [pixel_footprint 0|1, default 1]
//        [cpu_only 0|1, default 0] [medium 0|1, default 0: an absorbing medium
//        filling the scene, sigma_a 0.1/m, which attenuates every pair (issue 42)]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "support/BackendScene.h"
#include "support/TestJobs.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/gl/Context.h"
#include "tofsim/render/GlBackend.h"

#include "../BenchArgs.h"

namespace {

using namespace tofsim;

struct GatherTimes {
  double gather_s = 0.0;       ///< visibility build + gather (the read-back's wait, not its copy)
  double segment_s = 0.0;      ///< the same plus the segment's clear and one read-back copy
  double gather_cpu_s = 0.0;   ///< the gather's CPU time, all threads (as gather_s)
  double segment_cpu_s = 0.0;  ///< the segment's CPU time, all threads (as segment_s)
};

// The process's CPU time, every thread: on a shared machine the CPU-seconds a
// gather took are steadier than its wall time.
double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The host volumes are allocated (and touched) before the clock starts: the
// first touch of fresh pages costs more than the gather it would be charged to.
GatherTimes gatherSeconds(const capture::RenderJob& job, ir::IrBackend& backend,
                          std::size_t& pairs) {
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  const test::BackendScene prepared(backend, *job.scene);
  backend.prepareSurfaces(job);
  const auto vpls = backend.generateVpls(job);
  backend.setVpls(vpls);
  const std::size_t pixels = static_cast<std::size_t>(job.camera().width) * job.camera().height;
  backend.allocate(pixels, vpls.size());
  std::vector<float> direct(pixels * job.settings.time.bins * capture::kChannels, 1.0f),
      indirect(direct.size(), 1.0f);
  AxisLoss offAxis;
  const auto start = Clock::now();
  const double cpuStart = processCpuSeconds();
  backend.beginSegment(0, pixels);
  const auto cleared = Clock::now();
  const double cpuCleared = processCpuSeconds();
  backend.buildVisibility(0, vpls.size());
  backend.gatherIndirect(0, vpls.size());
  backend.readSegment(direct.data(), indirect.data(), offAxis);  // waits for the GL's work
  const auto gathered = Clock::now();
  const double cpuGathered = processCpuSeconds();
  // A second read-back of the finished segment: the copy alone, taken off
  // the gather's time so that only the gather (and the ISM build) is timed on
  // both backends.
  backend.readSegment(direct.data(), indirect.data(), offAxis);
  const auto copied = Clock::now();
  const double cpuCopied = processCpuSeconds();
  pairs = pixels * vpls.size();
  const double copy = seconds(gathered, copied);
  return {seconds(cleared, gathered) - copy, seconds(start, gathered),
          (cpuGathered - cpuCleared) - (cpuCopied - cpuGathered), cpuGathered - cpuStart};
}

}  // namespace

int main(int argc, char** argv) {
  const int threads = bench::arg(argc, argv, 1, 2);
  const int side = bench::arg(argc, argv, 2, 128);
  const int rsm = bench::arg(argc, argv, 3, 32);
  const bool footprint = bench::arg(argc, argv, 4, 1) != 0;
  test::CornerJob corner(side);
  corner.job.settings.indirect.rsm_resolution = rsm;
  corner.job.settings.pixel_footprint = footprint;
  std::printf("corner %dx%d, rsm %d, %d threads, pixel_footprint %s\n", side, side, rsm, threads,
              footprint ? "true" : "false");
  const bool cpuOnly = bench::arg(argc, argv, 5, 0) != 0;
  if (bench::arg(argc, argv, 6, 0) != 0) {
    corner.job.settings.medium.sigma_a_per_m = glm::vec3(0.1f);
    std::printf("in an absorbing medium, sigma_a 0.1/m\n");
  }
  const struct {
    const char* name;
    bool visibility;
    capture::Visibility kind;
  } cases[] = {{"none", false, capture::Visibility::Exact},
               {"exact", true, capture::Visibility::Exact},
               {"ism", true, capture::Visibility::Ism}};
  gl::Context context;
  std::printf(
      "GL: %s\n\ngather: visibility build + gather; segment: also the segment's clear and its "
      "read-back\n\n| visibility | pairs | cpu M pairs/s (gather / segment) | gl M pairs/s "
      "(gather / segment) | cpu / gl (gather) | cpu M pairs per CPU-second (gather / segment) |\n"
      "|---|---|---|---|---|---|\n",
      context.description().c_str());
  for (const auto& c : cases) {
    corner.job.settings.indirect.visibility = c.kind;
    std::size_t pairs = 0;
    cpu::CpuBackend cpuBackend({threads, c.visibility});
    const GatherTimes cpuTimes = gatherSeconds(corner.job, cpuBackend, pairs);
    const double cpuMps = pairs / cpuTimes.gather_s * 1e-6;
    const double cpuSegmentMps = pairs / cpuTimes.segment_s * 1e-6;
    if (!c.visibility || cpuOnly) {
      std::printf("| %s | %zu | %.1f / %.1f | n/a | n/a | %.1f / %.1f |\n", c.name, pairs, cpuMps,
                  cpuSegmentMps, pairs / cpuTimes.gather_cpu_s * 1e-6,
                  pairs / cpuTimes.segment_cpu_s * 1e-6);
      continue;
    }
    render::GlBackend glBackend(context);
    const GatherTimes glTimes = gatherSeconds(corner.job, glBackend, pairs);
    const double glMps = pairs / glTimes.gather_s * 1e-6;
    std::printf("| %s | %zu | %.1f / %.1f | %.1f / %.1f | %.1f | %.1f / %.1f |\n", c.name, pairs,
                cpuMps, cpuSegmentMps, glMps, pairs / glTimes.segment_s * 1e-6, cpuMps / glMps,
                pairs / cpuTimes.gather_cpu_s * 1e-6, pairs / cpuTimes.segment_cpu_s * 1e-6);
  }
  return 0;
}
