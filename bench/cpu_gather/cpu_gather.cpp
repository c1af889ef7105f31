// Pairs per second of the CPU backend's indirect gather (VPL x pixel pairs,
// every pixel of the image counted) on the corner scene, without visibility,
// with exact visibility (Embree occlusion rays) and with CPU ISMs (build
// included). Usage: tofsim_cpu_gather [threads] [side] [rsm_resolution]
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "support/TestJobs.h"
#include "tofsim/cpu/CpuBackend.h"

namespace {

using namespace tofsim;

double gatherSeconds(const capture::RenderJob& job, const cpu::CpuBackendOptions& options,
                     std::size_t& pairs) {
  cpu::CpuBackend backend(options);
  backend.prepareSurfaces(job);
  const auto vpls = backend.generateVpls(job);
  backend.setVpls(vpls);
  const std::size_t pixels = static_cast<std::size_t>(job.camera.width) * job.camera.height;
  backend.allocate(pixels, vpls.size());
  const auto start = std::chrono::steady_clock::now();
  backend.buildVisibility(0, vpls.size());
  backend.beginSegment(0, pixels);
  backend.gatherIndirect(0, vpls.size());
  pairs = pixels * vpls.size();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  const int threads = argc > 1 ? std::atoi(argv[1]) : 2;
  const int side = argc > 2 ? std::atoi(argv[2]) : 128;
  const int rsm = argc > 3 ? std::atoi(argv[3]) : 32;
  test::CornerJob corner(side);
  corner.job.settings.indirect.rsm_resolution = rsm;
  std::printf("corner %dx%d, rsm %d, %d threads\n", side, side, rsm, threads);
  const struct {
    const char* name;
    bool visibility;
    capture::Visibility kind;
  } cases[] = {{"none", false, capture::Visibility::Exact},
               {"exact", true, capture::Visibility::Exact},
               {"ism", true, capture::Visibility::Ism}};
  for (const auto& c : cases) {
    corner.job.settings.indirect.visibility = c.kind;
    std::size_t pairs = 0;
    const double s = gatherSeconds(corner.job, {threads, c.visibility}, pairs);
    std::printf("%-6s %10zu pairs %8.3f s %8.1f M pairs/s\n", c.name, pairs, s, pairs / s * 1e-6);
  }
  return 0;
}
