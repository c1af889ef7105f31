// Issue 43: a lidar beam's multipath (core/lidar MultipathWaveforms.h).
//  - An integrating sphere: a Lambertian point source on a sphere lights
//    every other point of it with the same irradiance, Phi rho / (4 pi R^2)
//    (the point-to-patch form factor of a sphere is the patch's area over
//    4 pi R^2), so one bounce returns the uniform radiance
//    L1 = Phi rho^2 / (4 pi^2 R^2) in every receiver direction, and the
//    receiver collects Omega_r L1 whatever its rays' layout; every later
//    bounce multiplies it by rho (the child VPLs light the sphere uniformly
//    too, and none escapes): closed forms for one and three bounces.
//  - A beam into a concave corner: its tail beyond the direct echo against
//    the reference path tracer lit by the same laser cone (a spot light) and
//    seen through the same receiver rays (a ray-list imager).
//  - The same bytes for 1 and 2 threads, later bounces included.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "support/AnalyticScenes.h"
#include "support/TracedScene.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/lidar/MultipathWaveforms.h"
#include "tofsim/reference/ReferenceRenderer.h"

namespace tofsim::lidar {
namespace {

constexpr double kPi = M_PI;

using Traced = test::TracedScene;

// A UV sphere of radius r about the origin, normals facing in, `rings`
// rings of 2 x rings segments.
scene::Scene insideSphere(float r, int rings, const glm::vec3& albedo) {
  scene::Scene scene;
  scene::Material material;
  material.name = "sphere";
  material.albedo = albedo;
  scene.materials.push_back(material);
  scene::Mesh mesh;
  mesh.name = "sphere";
  const int segments = 2 * rings;
  for (int i = 0; i <= rings; ++i) {
    const double theta = kPi * i / rings;
    for (int j = 0; j <= segments; ++j) {
      const double phi = 2.0 * kPi * j / segments;
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                        std::cos(theta));
      mesh.positions_world.push_back(r * n);
      mesh.normals_world.push_back(-n);
    }
  }
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      const auto a = static_cast<uint32_t>(i * (segments + 1) + j);
      const auto b = a + static_cast<uint32_t>(segments + 1);
      mesh.indices.insert(mesh.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
    }
  }
  scene.meshes.push_back(mesh);
  return scene;
}

TimeAxis axisTo(double path_m, double binWidth_s) {
  TimeAxis axis;
  axis.bin_width_s = binWidth_s;
  axis.bins = static_cast<int32_t>(std::ceil(path_m / (binWidth_s * 299792458.0)));
  return axis;
}

double sum(const std::vector<float>& w) {
  double s = 0.0;
  for (float v : w) s += v;
  return s;
}

// The multipath of one beam along `axis` (on and off the time axis).
double beamMultipath(const LidarSpec& spec, const MultipathSettings& settings,
                     const WaveformScene& scene, const TimeAxis& time, const glm::vec3& axis,
                     std::vector<float>* waveform = nullptr) {
  std::vector<float> w(static_cast<std::size_t>(time.bins), 0.0f);
  const WaveformLoss lost = addBeamMultipath(spec, settings, multipathRays(spec, settings), scene,
                                             time, glm::normalize(axis), 0, w.data());
  if (waveform != nullptr) *waveform = w;
  return sum(w) + lost.before + lost.after;
}

TEST(LidarMultipathTest, IntegratingSphereMatchesItsFormFactor) {
  // 128 rings: facets delta = 1.4 deg across. The faceted sphere's
  // cos cos / d^2 departs from 1 / (4 R^2) by O(delta^2) = 6e-4; its
  // interpolated normals let even the spot's own facet see the spot. 0.3 %.
  const float radius = 1.0f;
  const double rho = 0.6;
  Traced sphere(insideSphere(radius, 128, glm::vec3(static_cast<float>(rho))));
  LidarSpec spec;
  spec.divergence_rad = 3e-3;
  spec.power_W = 2.0;
  const TimeAxis time = axisTo(5.0, 10e-12);
  for (const double fov : {0.25, 0.5}) {
    MultipathSettings settings;
    settings.bounces = 1;
    settings.receiver_rays = 256;
    settings.receiver_fov_rad = fov;
    const double omega = 2.0 * kPi * (1.0 - std::cos(0.5 * fov));
    const double l1 = spec.power_W * rho * rho / (4.0 * kPi * kPi * radius * radius);
    const glm::vec3 axis(1.0f, 0.3f, 0.2f);
    const double one = beamMultipath(spec, settings, sphere.traced, time, axis) / (omega * l1);
    EXPECT_NEAR(one, 1.0, 0.003) << "fov " << fov;
    // Two more bounces: rho and rho^2 of it again, whichever points the
    // child VPLs land on.
    settings.bounces = 3;
    const double three = beamMultipath(spec, settings, sphere.traced, time, axis) /
                         (omega * l1 * (1.0 + rho + rho * rho));
    EXPECT_NEAR(three, 1.0, 0.003) << "fov " << fov;
    std::printf("fov %.2f rad: one bounce %.5f, three %.5f of the closed form\n", fov, one, three);
  }
}

// The corner (floor y = 0, wall z = 0), the lidar at (0, 1, 1) aiming at the
// floor 0.3 m from the crease, its receiver wide enough to see the wall.
struct CornerBeam {
  glm::vec3 position{0.0f, 1.0f, 1.0f};
  glm::vec3 axis = glm::normalize(glm::vec3(0.0f, -1.0f, -0.7f));
  LidarSpec spec;
  MultipathSettings settings;
  CornerBeam() {
    spec.position_world = position;
    spec.up_world = {1.0f, 0.0f, 0.0f};
    spec.divergence_rad = 0.2;
    spec.profile = BeamProfile::Tophat;
    settings.bounces = 1;
    settings.receiver_fov_rad = 0.6;
    settings.receiver_rays = 64;
  }
};

// The reference path tracer: a spot light of the beam's cone and intensity,
// seen through the receiver's rays; the receiver's waveform of its indirect
// light (W m^-2 per bin: each ray's radiance times its solid angle).
std::vector<double> referenceTail(const CornerBeam& b, const scene::Scene& scene,
                                  const TimeAxis& time, uint64_t seed) {
  const MultipathRays rays = multipathRays(b.spec, b.settings);
  const BeamFrame frame = beamFrame(b.axis, b.spec.up_world);
  capture::RayListImager imager;
  imager.width = static_cast<int32_t>(rays.receiver.size());
  for (const BeamRay& r : rays.receiver) {
    imager.rays.push_back({b.position, rayDirection(frame, r.offset_rad)});
  }
  capture::RenderJob job;
  job.scene = &scene;
  job.imager = imager;
  job.light.type = capture::Light::Type::Spot;
  job.light.position_world = b.position;
  job.light.direction_world = b.axis;
  job.light.cone_half_angle_deg = static_cast<float>(glm::degrees(0.5 * b.spec.divergence_rad));
  job.light.cone_falloff_deg = 0.0f;
  const double laserOmega = 2.0 * kPi * (1.0 - std::cos(0.5 * b.spec.divergence_rad));
  job.light.intensity_W_per_sr = glm::vec3(static_cast<float>(b.spec.power_W / laserOmega));
  job.settings.time = time;
  job.settings.seed = seed;
  reference::ReferenceSettings settings;
  settings.bounces = 2;
  settings.samples_per_pixel = 1024;
  settings.pixel_filter = reference::PixelFilter::Point;
  settings.threads = 2;
  capture::VolumeCollector collector(imager.width, 1, time, 3);
  reference::ReferenceRenderer(settings).render(job, collector);
  std::vector<double> tail(static_cast<std::size_t>(time.bins), 0.0);
  for (int32_t x = 0; x < imager.width; ++x) {
    for (int32_t t = 0; t < time.bins; ++t) {
      double v = 0.0;
      for (int32_t c = 0; c < 3; ++c) v += collector.indirect.at(0, x, t, c);
      tail[static_cast<std::size_t>(t)] += rays.receiverRaySolidAngle_sr * v / 3.0;
    }
  }
  return tail;
}

// Energy and mean path of a waveform.
struct Moments {
  double energy = 0.0, meanBin = 0.0;
};
template <typename T>
Moments momentsOf(const std::vector<T>& w) {
  Moments m;
  for (std::size_t i = 0; i < w.size(); ++i) {
    m.energy += w[i];
    m.meanBin += (i + 0.5) * w[i];
  }
  m.meanBin /= m.energy;
  return m;
}

TEST(LidarMultipathTest, CornerTailMatchesTheReference) {
  const CornerBeam b;
  Traced corner(test::makeCorner(glm::vec3(0.7f), glm::vec3(0.5f)));
  const TimeAxis time = axisTo(4.0, 100e-12);  // 3 cm of path per bin
  // The reference: independent renders, their spread giving its error.
  constexpr int kRenders = 8;
  std::vector<Moments> ref;
  for (int k = 0; k < kRenders; ++k)
    ref.push_back(momentsOf(referenceTail(b, corner.scene, time, 11 + k)));
  double e = 0.0, e2 = 0.0, t = 0.0, t2 = 0.0;
  for (const Moments& m : ref) {
    e += m.energy, e2 += m.energy * m.energy, t += m.meanBin, t2 += m.meanBin * m.meanBin;
  }
  e /= kRenders, t /= kRenders;
  const double seE = std::sqrt((e2 / kRenders - e * e) / (kRenders - 1));
  const double seT = std::sqrt((t2 / kRenders - t * t) / (kRenders - 1));
  // The multipath: its spot integral by 64 laser rays; the change from 16
  // bounds its quadrature error.
  MultipathSettings settings = b.settings;
  std::vector<float> fine, coarse;
  settings.spot_rays = 64;
  beamMultipath(b.spec, settings, corner.traced, time, b.axis, &fine);
  settings.spot_rays = 16;
  beamMultipath(b.spec, settings, corner.traced, time, b.axis, &coarse);
  const Moments m = momentsOf(fine), mc = momentsOf(coarse);
  ASSERT_GT(e, 0.0);
  const double tolE = 4.0 * seE + std::abs(m.energy - mc.energy);
  const double tolT = 4.0 * seT + std::abs(m.meanBin - mc.meanBin);  // both bin a path alike
  EXPECT_NEAR(m.energy, e, tolE) << "reference " << e << " +- " << seE;
  EXPECT_NEAR(m.meanBin, t, tolT) << "reference " << t << " +- " << seT;
  EXPECT_LT(tolE, 0.1 * e);  // a test that could tell a wrong factor
  // The tail lies beyond the direct echo: later than 2 r of the spot's
  // farthest point.
  double farthest_m = 0.0;
  const BeamFrame frame = beamFrame(b.axis, b.spec.up_world);
  for (const BeamRay& r : multipathRays(b.spec, settings).spot) {
    const auto hit = corner.rays.intersect(b.position, rayDirection(frame, r.offset_rad));
    ASSERT_TRUE(hit.has_value());
    farthest_m = std::max(farthest_m, 2.0 * hit->distance_m);
  }
  EXPECT_GT(m.meanBin * time.bin_width_m(), farthest_m);
}

TEST(LidarMultipathTest, SameBytesForAnyThreadCount) {
  Traced room(test::makeClosedBox(4.0f, glm::vec3(0.5f)));
  LidarSpec spec;
  spec.position_world = {0.3f, -0.2f, 0.1f};
  spec.elevations_deg = {-10.0, 0.0, 10.0, 20.0};
  spec.azimuth_step_deg = 10.0;
  MultipathSettings settings;
  settings.bounces = 2;
  settings.receiver_fov_rad = 0.2;
  settings.vpls_per_bounce = 4;
  settings.seed = 7;
  const TimeAxis time = axisTo(30.0, 100e-12);
  LidarWaveforms one = renderDirectWaveforms(spec, room.traced, time, 1);
  LidarWaveforms two = renderDirectWaveforms(spec, room.traced, time, 2);
  const double direct = sum(one.volume.values());
  addMultipathWaveforms(spec, settings, room.traced, time, 1, one);
  addMultipathWaveforms(spec, settings, room.traced, time, 2, two);
  EXPECT_GT(sum(one.volume.values()), direct * 1.001);  // the multipath is there
  ASSERT_EQ(one.volume.values().size(), two.volume.values().size());
  EXPECT_EQ(0, std::memcmp(one.volume.data(), two.volume.data(),
                           one.volume.values().size() * sizeof(float)));
  EXPECT_EQ(one.lost.after, two.lost.after);
}

}  // namespace
}  // namespace tofsim::lidar
