// Issue 42, item 5: the reference path tracer's half of a by-hand comparison
// with mitransient's transient_prbvolpath (mitransient_fog_cornell.py):
// the Cornell box glTF, the demo camera, a point light 5 cm beside it (and
// 1 cm ahead), fog
// filling the scene (sigma_s 2 /m, sigma_a 0.1 /m, Henyey-Greenstein g 0.5),
// eta 1, box pixel filter, 20 ps bins from 1.5 m of optical path, 2 vertices
// per path (mitransient's max_depth 3; medium events count in both). Writes
// OUT (H, W, T, 3) float32, direct + indirect.
//
//   build/bench/tofsim_reference_fog_cornell SPP OUT.npy [SIDE] [BINS]

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "support/AnalyticScenes.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/io/Npy.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/volume/PhysicalConstants.h"

using namespace tofsim;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s SPP OUT.npy [SIDE] [BINS]\n", argv[0]);
    return 1;
  }
  const int spp = std::atoi(argv[1]);
  const int side = argc > 3 ? std::atoi(argv[3]) : 64;
  const int bins = argc > 4 ? std::atoi(argv[4]) : 200;
  scene::Scene box = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  // mitransient's fog ends at its cube's near face, just in front of the
  // pinhole: light that crosses it leaves for good. A black plane 0.1 mm
  // behind the pinhole does the same here.
  test::addQuad(box, glm::vec3(0.278f, 0.273f, -0.8001f), glm::vec3(0, 0, 1), 20.0f, glm::vec3(0.0f));
  capture::RenderJob job;
  job.scene = &box;
  job.camera().position_world = {0.278f, 0.273f, -0.8f};
  job.camera().look_at_world = {0.278f, 0.273f, 0.2f};
  job.camera().fov_y_deg = 39.3076481f;
  job.camera().width = job.camera().height = side;
  // 5 cm right of the pinhole (right = -x), 1 cm ahead: inside
  // mitransient's fog cube, whose near face is 0.1 mm in front of the pinhole.
  job.light.position_world = {0.228f, 0.273f, -0.79f};
  job.light.intensity_W_per_sr = glm::vec3(1.0f);
  job.settings.time = TimeAxis{1.5 / kSpeedOfLight_m_per_s, 20e-12, bins};
  job.settings.medium.sigma_s_per_m = glm::vec3(2.0f);
  job.settings.medium.sigma_a_per_m = glm::vec3(0.1f);
  job.settings.medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
  job.settings.medium.g = 0.5f;
  reference::ReferenceSettings settings;
  settings.bounces = 2;
  settings.samples_per_pixel = spp;
  capture::VolumeCollector out(side, side, job.settings.time, 3);
  const auto start = std::chrono::steady_clock::now();
  reference::ReferenceRenderer(settings).render(job, out);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  io::writeNpy(argv[2], out.total());
  std::printf("{\"spp\": %d, \"seconds\": %.3f}\n", spp, seconds);
  return 0;
}
