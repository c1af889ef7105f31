// Pairs per second of the indirect gather (VPL x pixel pairs, every pixel of
// the image counted) on the corner scene, on the CPU backend and on the GL one
// (llvmpipe without a GPU) in the same run: without visibility (CPU only; the
// GL backend always tests it), with exact visibility (Embree occlusion rays /
// the GL's BVH shadow rays) and with ISMs (build included). The read-back of
// the segment waits for the GL's work; a second read-back, timed alone, is
// taken off on both backends.
// Usage: tofsim_cpu_gather [threads] [side] [rsm_resolution] [pixel_footprint 0|1, default 1]
//        [cpu_only 0|1, default 0]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "support/TestJobs.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/gl/Context.h"
#include "tofsim/render/GlBackend.h"

namespace {

using namespace tofsim;

double gatherSeconds(const capture::RenderJob& job, ir::IrBackend& backend, std::size_t& pairs) {
  backend.prepareSurfaces(job);
  const auto vpls = backend.generateVpls(job);
  backend.setVpls(vpls);
  const std::size_t pixels = static_cast<std::size_t>(job.camera.width) * job.camera.height;
  backend.allocate(pixels, vpls.size());
  const auto start = std::chrono::steady_clock::now();
  backend.buildVisibility(0, vpls.size());
  backend.beginSegment(0, pixels);
  backend.gatherIndirect(0, vpls.size());
  std::vector<float> direct(pixels * job.settings.time.bins * capture::kChannels),
      indirect(direct.size());
  AxisLoss offAxis;
  backend.readSegment(direct.data(), indirect.data(), offAxis);  // waits for the GL's work
  const auto gathered = std::chrono::steady_clock::now();
  // A second read-back of the finished segment: the copy alone, taken off
  // so that only the gather (and the ISM build) is timed on both backends.
  backend.readSegment(direct.data(), indirect.data(), offAxis);
  const auto copied = std::chrono::steady_clock::now();
  pairs = pixels * vpls.size();
  return std::chrono::duration<double>(gathered - start).count() -
         std::chrono::duration<double>(copied - gathered).count();
}

}  // namespace

int main(int argc, char** argv) {
  const int threads = argc > 1 ? std::atoi(argv[1]) : 2;
  const int side = argc > 2 ? std::atoi(argv[2]) : 128;
  const int rsm = argc > 3 ? std::atoi(argv[3]) : 32;
  const bool footprint = argc > 4 ? std::atoi(argv[4]) != 0 : true;
  test::CornerJob corner(side);
  corner.job.settings.indirect.rsm_resolution = rsm;
  corner.job.settings.pixel_footprint = footprint;
  std::printf("corner %dx%d, rsm %d, %d threads, pixel_footprint %s\n", side, side, rsm, threads,
              footprint ? "true" : "false");
  const bool cpuOnly = argc > 5 && std::atoi(argv[5]) != 0;
  const struct {
    const char* name;
    bool visibility;
    capture::Visibility kind;
  } cases[] = {{"none", false, capture::Visibility::Exact},
               {"exact", true, capture::Visibility::Exact},
               {"ism", true, capture::Visibility::Ism}};
  gl::Context context;
  std::printf(
      "GL: %s\n\n| visibility | pairs | cpu M pairs/s | gl M pairs/s | cpu / gl |\n"
      "|---|---|---|---|---|\n",
      context.description().c_str());
  for (const auto& c : cases) {
    corner.job.settings.indirect.visibility = c.kind;
    std::size_t pairs = 0;
    cpu::CpuBackend cpuBackend({threads, c.visibility});
    const double cpuSeconds = gatherSeconds(corner.job, cpuBackend, pairs);
    const double cpuMps = pairs / cpuSeconds * 1e-6;
    if (!c.visibility || cpuOnly) {
      std::printf("| %s | %zu | %.1f | n/a | n/a |\n", c.name, pairs, cpuMps);
      continue;
    }
    render::GlBackend glBackend(context);
    const double glSeconds = gatherSeconds(corner.job, glBackend, pairs);
    const double glMps = pairs / glSeconds * 1e-6;
    std::printf("| %s | %zu | %.1f | %.1f | %.1f |\n", c.name, pairs, cpuMps, glMps,
                cpuMps / glMps);
  }
  return 0;
}
