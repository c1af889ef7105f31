// Issue 43: a lidar's beams per second with multipath (core/lidar's
// addMultipathWaveforms: each beam's spot VPLs lighting its receiver points
// through Embree shadow rays), beside the direct light alone on the same
// frame, on a glTF scene (default: configs/scenes/lidar_street.gltf, the
// lidar 1.8 m above its street, spin axis +y, as tofsim_lidar_beams).
//
// Usage: tofsim_lidar_multipath [channels] [azimuths] [bins] [bounces] [spot_rays]
//                               [receiver_rays] [receiver_fov_mrad] [threads] [repeats] [scene]
// Defaults: 16 1800 1000 1 4 16 20 0 (all cores) 3. Prints the best of the repeats.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/lidar/DirectWaveforms.h"
#include "tofsim/lidar/MultipathWaveforms.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/ParallelFor.h"
#include "../BenchArgs.h"
#include "StreetFrame.h"

using namespace tofsim;

int main(int argc, char** argv) {
  const auto arg = [&](int i, double fallback) { return bench::arg(argc, argv, i, fallback); };
  const auto channels = static_cast<int>(arg(1, 16));
  const auto azimuths = static_cast<int>(arg(2, 1800));
  lidar::MultipathSettings settings;
  settings.bounces = static_cast<int32_t>(arg(4, 1));
  settings.spot_rays = static_cast<int32_t>(arg(5, 4));
  settings.receiver_rays = static_cast<int32_t>(arg(6, 16));
  settings.receiver_fov_rad = arg(7, 20.0) * 1e-3;
  const int threads = resolveThreads(static_cast<int>(arg(8, 0)));
  const int repeats = std::max(1, static_cast<int>(arg(9, 3)));
  const std::string scenePath =
      argc > 10 ? argv[10] : std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/lidar_street.gltf";

  const scene::Scene scene = scene::loadGltf(scenePath);
  const rays::RayScene rayScene(scene, threads);
  lidar::WaveformScene traced{
      &rayScene, ir::materialVertices(scene, physics::VERTEX_LAMBERTIAN), {}};
  const auto [spec, axis] =
      bench::streetFrame(channels, azimuths, static_cast<int32_t>(arg(3, 1000)));

  double bestDirect = 1e300, bestMultipath = 1e300, direct = 0.0, multipath = 0.0;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    lidar::LidarWaveforms w = lidar::renderDirectWaveforms(spec, traced, axis, threads);
    bestDirect = std::min(bestDirect, bench::seconds(start));
    direct = 0.0;
    for (float v : w.volume.values()) direct += v;
    const auto mpStart = std::chrono::steady_clock::now();
    lidar::addMultipathWaveforms(spec, settings, traced, axis, threads, w);
    bestMultipath = std::min(bestMultipath, bench::seconds(mpStart));
    multipath = -direct;
    for (float v : w.volume.values()) multipath += v;
  }
  const double beams = double(channels) * azimuths;
  const double pairs = double(settings.spot_rays) * settings.receiver_rays;
  std::printf(
      "scene %s, %d x %d beams, %d bins, %d threads; multipath: %d bounce(s), %d spot x "
      "%d receiver rays, receiver fov %.1f mrad\n",
      scenePath.c_str(), channels, azimuths, axis.bins, threads, settings.bounces,
      settings.spot_rays, settings.receiver_rays, settings.receiver_fov_rad * 1e3);
  std::printf("direct: %.3f s = %.0f beams/s\n", bestDirect, beams / bestDirect);
  std::printf("multipath added: %.3f s = %.0f beams/s (%.2f M shadow rays/s at most)\n",
              bestMultipath, beams / bestMultipath, beams * pairs / bestMultipath * 1e-6);
  std::printf("direct + multipath: %.3f s = %.0f beams/s; multipath energy %.4g of the direct's\n",
              bestDirect + bestMultipath, beams / (bestDirect + bestMultipath), multipath / direct);
  return 0;
}
