// The paper's Fig. 4 and Fig. 5 sweeps on the Cornell box: render time
// against the video duration (time bins), the RSM size (VPL count), the ISM
// size and the points per VPL, each varied alone around a base setting.
// Prints a Markdown table: seconds, VPL-pixel gathers per second, VPLs,
// batches, segments and peak GPU bytes. Usage:
//   ir_sweeps SCENE.gltf [--quick]

#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "support/TestJobs.h"  // the Cornell box job shared with the tests
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/gl/Context.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/render/GlBackend.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace {

using namespace tofsim;

// Discards segments after touching them, as a consumer streaming to disk would.
class CountingSink : public capture::SegmentSink {
 public:
  void consume(const capture::Segment& s) override { floats += s.pixelCount; }
  std::size_t floats = 0;
};

struct Case {
  std::string sweep;
  int bins, rsm, ism, points;
};

capture::RenderJob baseJob(const scene::Scene& scene, int resolution, int bins) {
  capture::RenderJob job = test::cornellBoxJob(scene, resolution, bins, 2.0 / bins);
  job.settings.shadow_map_resolution = 1024;
  job.settings.memory_budget_bytes = std::size_t{1} << 30;
  return job;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: ir_sweeps SCENE.gltf [--quick]\n");
    return 2;
  }
  const bool quick = argc > 2 && std::strcmp(argv[2], "--quick") == 0;
  const scene::Scene scene = scene::loadGltf(argv[1]);
  gl::Context context;
  const ir::IrRenderer renderer(std::make_unique<render::GlBackend>(context));
  const int resolution = quick ? 64 : 128;
  // Base of the paper's Fig. 5: 128^2 RSM, 128^2 ISM, 2000 points per VPL;
  // Fig. 4 varies the duration at 128^2 RSM, 64^2 ISM, 4000 points.
  const int baseRsm = quick ? 32 : 128, baseIsm = quick ? 32 : 128, basePoints = quick ? 500 : 2000;
  std::vector<Case> cases;
  for (int bins : {125, 250, 500, 1000})
    cases.push_back({"duration", bins, baseRsm, quick ? 32 : 64, quick ? 500 : 4000});
  for (int rsm : {16, 32, 64, 128}) {
    if (!quick || rsm <= 32) cases.push_back({"rsm", 250, rsm, baseIsm, basePoints});
  }
  for (int ism : {32, 64, 128, 256}) {
    if (!quick || ism <= 64) cases.push_back({"ism", 250, baseRsm, ism, basePoints});
  }
  for (int points : {500, 1000, 2000, 4000, 8000}) {
    if (!quick || points <= 1000)
      cases.push_back({"points_per_vpl", 250, baseRsm, baseIsm, points});
  }
  std::printf("device: %s\nimage: %dx%d, Cornell box, spot light at the camera\n\n",
              context.description().c_str(), resolution, resolution);
  std::printf(
      "| sweep | bins | RSM | ISM | points/VPL | VPLs | batches | segments | seconds | "
      "VPL-pixel gathers/s | peak GPU MiB |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Case& c : cases) {
    capture::RenderJob job = baseJob(scene, resolution, c.bins);
    job.settings.indirect.rsm_resolution = c.rsm;
    job.settings.indirect.ism_resolution = c.ism;
    job.settings.indirect.points_per_vpl = c.points;
    CountingSink sink;
    const capture::RenderResult r = renderer.render(job, sink);
    const double gathers = static_cast<double>(r.vpls) * resolution * resolution;
    std::printf("| %s | %d | %d | %d | %d | %zu | %zu | %zu | %.2f | %.3g | %.1f |\n",
                c.sweep.c_str(), c.bins, c.rsm, c.ism, c.points, r.vpls, r.vplBatches, r.segments,
                r.seconds, gathers / r.seconds, r.peakGpuBytes / 1048576.0);
    std::fflush(stdout);
  }
  return 0;
}
