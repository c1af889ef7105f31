#include "tofsim/lidar/MultipathWaveforms.h"

#include <cmath>
#include <optional>

#include "tofsim/ir/BounceVpls.h"
#include "tofsim/ir/HitVertex.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/physics/TransientPhysics.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::lidar {

namespace {

// A receiver ray's surface point and what it returns toward the lidar.
struct ReceiverPoint {
  rays::SurfaceHit hit;
  physics::ScatterVertex vertex;
  glm::vec3 toLidar;   // unit, y -> lidar
  float cameraPath_m;  // eta r_y, or 0 with time.camera_unwarp
  glm::vec3 weight;    // the ray's solid angle x the medium's transmittance over r_y
};

// A beam's seed for its later bounces (splitmix64 of the run's seed and the
// beam): independent streams per beam, whatever thread renders it.
uint64_t beamSeed(uint64_t seed, uint64_t beam) {
  uint64_t z = seed + 0x9e3779b97f4a7c15ull * (beam + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

glm::vec3 transmittance(const capture::Medium& medium, float distance_m) {
  if (!medium.present()) return glm::vec3(1.0f);
  return physics::mediumTransmittance(medium.sigmaT(), distance_m);
}

// The spot's VPLs: each laser ray's hit, lit by the power its ray carries
// (as ir::Vpl holds it: albedo Phi / pi where the flux holds the scatter).
std::vector<ir::Vpl> spotVpls(const LidarSpec& spec, const MultipathRays& rays,
                              const WaveformScene& scene, const BeamFrame& frame, float eta) {
  std::vector<ir::Vpl> vpls;
  vpls.reserve(rays.spot.size());
  for (const BeamRay& ray : rays.spot) {
    const glm::vec3 d = rayDirection(frame, ray.offset_rad);
    const std::optional<rays::SurfaceHit> hit = scene.rays->intersect(spec.position_world, d);
    if (!hit || !(hit->distance_m > 0.0f)) continue;
    ir::Vpl v;
    v.vertex = ir::hitVertex(*hit, scene.materials);
    const glm::vec3 power =
        static_cast<float>(spec.power_W) * ray.share * transmittance(scene.medium, hit->distance_m);
    const bool holds = physics::vplFluxHoldsScatter(v.vertex);
    const glm::vec3 flux =
        holds ? glm::vec3(v.vertex.color) * power / static_cast<float>(M_PI) : power;
    v.positionPath = glm::vec4(hit->position_world, eta * hit->distance_m);
    v.normal = glm::vec4(hit->normal_world, 0.0f);
    v.flux = glm::vec4(flux, 0.0f);
    if (!holds) v.incoming = glm::vec4(-d, 0.0f);
    vpls.push_back(v);
  }
  return vpls;
}

std::vector<ReceiverPoint> receiverPoints(const LidarSpec& spec, const MultipathRays& rays,
                                          const WaveformScene& scene, const BeamFrame& frame,
                                          const TimeAxis& axis) {
  std::vector<ReceiverPoint> points;
  points.reserve(rays.receiver.size());
  const float eta = static_cast<float>(axis.index_of_refraction);
  for (const BeamRay& ray : rays.receiver) {
    const glm::vec3 d = rayDirection(frame, ray.offset_rad);
    const std::optional<rays::SurfaceHit> hit = scene.rays->intersect(spec.position_world, d);
    if (!hit || !(hit->distance_m > 0.0f) || !(glm::dot(hit->normal_world, -d) > 0.0f)) continue;
    const auto solidAngle = static_cast<float>(rays.receiverRaySolidAngle_sr);
    points.push_back({*hit, ir::hitVertex(*hit, scene.materials), -d,
                      physics::cameraPathLength(axis.camera_unwarp, eta, hit->distance_m),
                      solidAngle * transmittance(scene.medium, hit->distance_m)});
  }
  return points;
}

// The VPLs of the bounces after the spot's, by core/ir's bounce machinery.
void addLaterBounces(const MultipathSettings& settings, const WaveformScene& scene, float eta,
                     uint64_t seed, std::vector<ir::Vpl>& vpls) {
  ir::BounceTracing tracing;
  tracing.threads = 1;  // the beams are the parallel loop
  tracing.medium = scene.medium;
  ir::BounceMaterials materials;
  materials.vertexModel = settings.vertex_model;
  materials.brdfClamp = static_cast<float>(settings.brdf_clamp_per_sr);
  std::vector<ir::Vpl> parents = vpls;
  for (int32_t bounce = 2; bounce <= settings.bounces && !parents.empty(); ++bounce) {
    parents =
        ir::traceBounce(*scene.rays, parents, static_cast<std::size_t>(settings.vpls_per_bounce),
                        bounce, seed, eta, tracing, materials);
    vpls.insert(vpls.end(), parents.begin(), parents.end());
  }
}

}  // namespace

MultipathRays multipathRays(const LidarSpec& spec, const MultipathSettings& settings) {
  const double fov =
      settings.receiver_fov_rad > 0.0 ? settings.receiver_fov_rad : spec.divergence_rad;
  MultipathRays rays;
  rays.spot = beamRays(settings.spot_rays, spec.divergence_rad, spec.profile);
  rays.receiver = beamRays(settings.receiver_rays, fov, BeamProfile::Tophat);
  const double solidAngle = 2.0 * M_PI * (1.0 - std::cos(0.5 * fov));
  rays.receiverRaySolidAngle_sr = solidAngle / static_cast<double>(rays.receiver.size());
  return rays;
}

WaveformLoss addBeamMultipath(const LidarSpec& spec, const MultipathSettings& settings,
                              const MultipathRays& rays, const WaveformScene& scene,
                              const TimeAxis& axis, const glm::vec3& beamAxis, uint64_t beam,
                              float* waveform) {
  WaveformLoss lost;
  const BeamFrame frame = beamFrame(beamAxis, spec.up_world);
  const float eta = static_cast<float>(axis.index_of_refraction);
  std::vector<ir::Vpl> vpls = spotVpls(spec, rays, scene, frame, eta);
  if (vpls.empty()) return lost;
  const std::vector<ReceiverPoint> points = receiverPoints(spec, rays, scene, frame, axis);
  if (points.empty()) return lost;
  if (settings.bounces > 1)
    addLaterBounces(settings, scene, eta, beamSeed(settings.seed, beam), vpls);
  const float clamp = static_cast<float>(settings.geometry_clamp_per_m2);
  const float brdfClamp = static_cast<float>(settings.brdf_clamp_per_sr);
  const float start = static_cast<float>(axis.start_m());
  const float width = static_cast<float>(axis.bin_width_m());
  for (const ReceiverPoint& y : points) {
    const glm::vec3 n = y.hit.normal_world;
    for (const ir::Vpl& v : vpls) {
      const glm::vec3 p(v.positionPath);
      const glm::vec3 t = y.hit.position_world - p;
      const float dist2 = glm::dot(t, t);
      if (!(dist2 > 0.0f)) continue;
      const float dist = std::sqrt(dist2);
      const glm::vec3 w = t / dist;  // VPL -> y
      const glm::vec3 vn(v.normal);
      const float cosVpl = physics::vplEmitterCosine(vn, w);
      const float cosY = -glm::dot(n, w);
      if (!(cosVpl > 0.0f && cosY > 0.0f)) continue;
      if (scene.rays->occluded(scene.rays->offsetOrigin(y.hit, -w), p)) continue;
      const float g = physics::geometryTerm(cosVpl, cosY, dist2, clamp);
      const glm::vec3 fVpl = physics::vplScatter(v.vertex, vn, glm::vec3(v.incoming), w, brdfClamp);
      const glm::vec3 fY = physics::scatter(y.vertex, n, -w, y.toLidar).f;
      const glm::vec3 e = physics::vplRadiance(fY, fVpl, glm::vec3(v.flux), g) * y.weight *
                          transmittance(scene.medium, dist);
      const double value = (double(e.r) + e.g + e.b) / 3.0;  // one wavelength: the mean
      const int bin = physics::binOfPath(
          physics::vplPathLength(v.positionPath.w, eta, dist, y.cameraPath_m), start, width);
      if (bin < 0) {
        lost.before += value;
      } else if (bin >= axis.bins) {
        lost.after += value;
      } else {
        waveform[static_cast<std::size_t>(bin)] += static_cast<float>(value);
      }
    }
  }
  return lost;
}

void addMultipathWaveforms(const LidarSpec& spec, const MultipathSettings& settings,
                           const WaveformScene& scene, const TimeAxis& axis, int threads,
                           LidarWaveforms& waveforms) {
  if (!settings.enabled()) return;
  const int32_t azimuths = spec.azimuths();
  const auto beams = static_cast<std::size_t>(spec.channels()) * static_cast<std::size_t>(azimuths);
  const MultipathRays rays = multipathRays(spec, settings);
  std::vector<WaveformLoss> lost((beams + kMultipathBlock - 1) / kMultipathBlock);
  float* data = waveforms.volume.data();
  const std::size_t stride = waveforms.volume.pixelStride();
  parallelForBlocks(
      beams, kMultipathBlock, resolveThreads(threads), [&](std::size_t begin, std::size_t end) {
        WaveformLoss& l = lost[begin / kMultipathBlock];
        for (std::size_t b = begin; b < end; ++b) {
          const auto ring = static_cast<int32_t>(b / static_cast<std::size_t>(azimuths));
          const auto azimuth = static_cast<int32_t>(b % static_cast<std::size_t>(azimuths));
          const WaveformLoss beam =
              addBeamMultipath(spec, settings, rays, scene, axis,
                               beamDirection(spec, ring, azimuth), b, data + b * stride);
          l.before += beam.before;
          l.after += beam.after;
        }
      });
  for (const WaveformLoss& l : lost) {  // in block order: the same sum for any thread count
    waveforms.lost.before += l.before;
    waveforms.lost.after += l.after;
  }
}

}  // namespace tofsim::lidar
