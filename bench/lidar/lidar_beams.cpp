// Issue 43: a lidar's direct-light beams per second (core/lidar's
// renderDirectWaveforms: receiver rays through Embree, each beam's waveform
// on the time axis) and, on the same frame, the echoes and returns
// (lidarReturns), on a glTF scene (default: configs/scenes/lidar_street.gltf,
// the lidar 1.8 m above its street, spin axis +y). Both ways a run makes
// them: with the dense (channels, azimuths, bins) volume (what a sensor on
// the waveforms needs) and without it, the returns found on each beam's
// nonzero bins (a frame whose waveforms no sensor reads).
//
// Usage: tofsim_lidar_beams [channels] [azimuths] [bins] [beam_rays] [threads] [repeats] [scene]
// Defaults: 16 1800 1000 16 0 (all cores) 3. Prints the best of the repeats.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "../BenchArgs.h"
#include "StreetFrame.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/lidar/BeamPattern.h"
#include "tofsim/lidar/DirectWaveforms.h"
#include "tofsim/lidar/LidarReturns.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/ParallelFor.h"

using namespace tofsim;

int main(int argc, char** argv) {
  const auto arg = [&](int i, long long fallback) { return bench::arg(argc, argv, i, fallback); };
  const auto channels = static_cast<int>(arg(1, 16));
  const auto azimuths = static_cast<int>(arg(2, 1800));
  const auto bins = static_cast<int32_t>(arg(3, 1000));
  const auto rays = static_cast<int32_t>(arg(4, 16));
  const int threads = resolveThreads(static_cast<int>(arg(5, 0)));
  const int repeats = static_cast<int>(std::max(1LL, arg(6, 3)));
  const std::string scenePath =
      argc > 7 ? argv[7] : std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/lidar_street.gltf";

  const scene::Scene scene = scene::loadGltf(scenePath);
  rays::RayScene rayScene(scene, threads);
  lidar::WaveformScene traced{
      &rayScene, ir::materialVertices(scene, physics::VERTEX_LAMBERTIAN), {}};
  auto [spec, axis] = bench::streetFrame(channels, azimuths, bins);
  spec.beam_rays = rays;

  // The rays alone (Embree's closest hits, nothing done with them): what
  // the waveforms cost beyond tracing.
  const std::vector<lidar::BeamRay> beamRays =
      lidar::beamRays(spec.beam_rays, spec.divergence_rad, spec.profile);
  // The same rays as packets, a beam's rays traced together: as one bundle
  // (RayScene::intersectPacket) or as Embree's packets (rtcIntersect8).
  const auto tracePackets = [&](bool embree) {
    std::vector<double> sums(static_cast<std::size_t>(channels) * azimuths / 256 + 1, 0.0);
    parallelForBlocks(static_cast<std::size_t>(channels) * azimuths, 256, threads,
                      [&](std::size_t begin, std::size_t end) {
                        constexpr int kPacket = rays::RayScene::kPacketSize;
                        glm::vec3 d[kPacket];
                        std::optional<rays::SurfaceHit> hits[kPacket];
                        for (std::size_t b = begin; b < end; ++b) {
                          const lidar::BeamFrame f = lidar::beamFrame(
                              lidar::beamDirection(spec, static_cast<int32_t>(b / azimuths),
                                                   static_cast<int32_t>(b % azimuths)),
                              spec.up_world);
                          for (std::size_t first = 0; first < beamRays.size(); first += kPacket) {
                            const int n = static_cast<int>(
                                std::min<std::size_t>(kPacket, beamRays.size() - first));
                            for (int i = 0; i < n; ++i) {
                              d[i] = lidar::rayDirection(f, beamRays[first + i].offset_rad);
                            }
                            if (embree) {
                              rayScene.intersectEmbreePacket(spec.position_world, d, n, hits);
                            } else {
                              rayScene.intersectPacket(spec.position_world, d, n, hits);
                            }
                            for (int i = 0; i < n; ++i) {
                              if (hits[i]) sums[begin / 256] += hits[i]->distance_m;
                            }
                          }
                        }
                      });
    return sums[0];
  };
  const auto traceAll = [&] {
    std::vector<double> sums(static_cast<std::size_t>(channels) * azimuths / 256 + 1, 0.0);
    parallelForBlocks(static_cast<std::size_t>(channels) * azimuths, 256, threads,
                      [&](std::size_t begin, std::size_t end) {
                        for (std::size_t b = begin; b < end; ++b) {
                          const lidar::BeamFrame f = lidar::beamFrame(
                              lidar::beamDirection(spec, static_cast<int32_t>(b / azimuths),
                                                   static_cast<int32_t>(b % azimuths)),
                              spec.up_world);
                          for (const lidar::BeamRay& r : beamRays) {
                            const auto hit = rayScene.intersect(
                                spec.position_world, lidar::rayDirection(f, r.offset_rad));
                            if (hit) sums[begin / 256] += hit->distance_m;
                          }
                        }
                      });
    return sums[0];
  };
  double bestTrace = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    (void)traceAll();
    bestTrace = std::min(bestTrace, bench::seconds(start));
  }
  double bestPackets = 1e300, bestEmbreePackets = 1e300;
  for (int r = 0; r < repeats; ++r) {
    auto start = std::chrono::steady_clock::now();
    (void)tracePackets(false);
    bestPackets = std::min(bestPackets, bench::seconds(start));
    start = std::chrono::steady_clock::now();
    (void)tracePackets(true);
    bestEmbreePackets = std::min(bestEmbreePackets, bench::seconds(start));
  }
  double best = 1e300, bestReturns = 1e300;
  double bestSparse = 1e300, bestSparseReturns = 1e300, bestFrame = 1e300;
  std::size_t points = 0, sparsePoints = 0;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const lidar::LidarWaveforms w = lidar::renderDirectWaveforms(spec, traced, axis, threads);
    best = std::min(best, bench::seconds(start));
    const auto returnsStart = std::chrono::steady_clock::now();
    points = lidar::lidarReturns(spec, w.volume, 10.0).points.size();
    bestReturns = std::min(bestReturns, bench::seconds(returnsStart));
  }
  // The frame without the volume, its rays as bundles and as Embree's
  // packets alternately (RayScene::setBundles), in wall and CPU seconds
  // (the process's, both threads: what a loaded machine does not blur).
  double bestCpu = 1e300, bestEmbreeFrame = 1e300, bestEmbreeCpu = 1e300;
  for (int r = 0; r < repeats; ++r) {
    for (bool bundles : {true, false}) {
      rayScene.setBundles(bundles);
      const double cpuStart = bench::cpuSeconds();
      const auto start = std::chrono::steady_clock::now();
      const lidar::LidarWaveforms w =
          lidar::renderDirectWaveforms(spec, traced, axis, threads, false);
      const double waveforms = bench::seconds(start);
      const auto returnsStart = std::chrono::steady_clock::now();
      sparsePoints = lidar::lidarReturns(spec, w, 10.0, threads).points.size();
      const double cpu = bench::cpuSeconds() - cpuStart;
      if (bundles) {
        bestSparse = std::min(bestSparse, waveforms);
        bestSparseReturns = std::min(bestSparseReturns, bench::seconds(returnsStart));
        bestFrame = std::min(bestFrame, bench::seconds(start));
        bestCpu = std::min(bestCpu, cpu);
      } else {
        bestEmbreeFrame = std::min(bestEmbreeFrame, bench::seconds(start));
        bestEmbreeCpu = std::min(bestEmbreeCpu, cpu);
      }
    }
  }
  rayScene.setBundles(true);
  const double beams = double(channels) * azimuths;
  std::printf("scene %s, %d x %d beams, %d bins, %d rays per beam, %d threads\n", scenePath.c_str(),
              channels, azimuths, bins, rays, threads);
  std::printf("rays alone: %.3f s = %.0f beams/s (%.0f rays/s)\n", bestTrace, beams / bestTrace,
              beams * rays / bestTrace);
  std::printf(
      "waveforms: %.3f s = %.0f beams/s (%.0f rays/s); returns: %.3f s = %.0f beams/s; "
      "%zu points\n",
      best, beams / best, beams * rays / best, bestReturns, beams / bestReturns, points);
  std::printf("rays alone, packets: %.3f s = %.0f beams/s (%.0f rays/s)\n", bestPackets,
              beams / bestPackets, beams * rays / bestPackets);
  std::printf("rays alone, Embree packets: %.3f s = %.0f beams/s (%.0f rays/s)\n",
              bestEmbreePackets, beams / bestEmbreePackets, beams * rays / bestEmbreePackets);
  std::printf(
      "waveforms, no volume: %.3f s = %.0f beams/s; returns: %.3f s; waveforms and "
      "returns: %.3f s = %.0f beams/s; %zu points\n",
      bestSparse, beams / bestSparse, bestSparseReturns, bestFrame, beams / bestFrame,
      sparsePoints);
  std::printf(
      "waveforms and returns, no volume: bundles %.3f s = %.0f beams/s (%.3f CPU s); "
      "Embree packets %.3f s = %.0f beams/s (%.3f CPU s)\n",
      bestFrame, beams / bestFrame, bestCpu, bestEmbreeFrame, beams / bestEmbreeFrame,
      bestEmbreeCpu);
  return 0;
}
