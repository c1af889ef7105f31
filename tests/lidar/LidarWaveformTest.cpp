// Issue 43's first slice: a lidar's direct-light waveforms and returns
// against closed forms. A box room: every beam's first return lies on the
// room along its own beam; a beam over a step edge returns two echoes whose
// energies split as the profile's parts on each side; a plane's echo
// follows power rho cos(theta) / (pi r^2) (x the medium's two-way
// transmittance); the bytes do not depend on the thread count.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "support/AnalyticScenes.h"
#include "support/TracedScene.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/lidar/BeamPattern.h"
#include "tofsim/lidar/DirectWaveforms.h"
#include "tofsim/lidar/Echoes.h"
#include "tofsim/lidar/LidarReturns.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::lidar {
namespace {

// A lidar at `position` spinning about +z, azimuth 0 along +x.
LidarSpec spinning(const glm::vec3& position, std::vector<double> elevations, double step_deg) {
  LidarSpec s;
  s.position_world = position;
  s.elevations_deg = std::move(elevations);
  s.azimuth_step_deg = step_deg;
  return s;
}

using Traced = test::TracedScene;

// 1.5 mm of range per bin.
TimeAxis axisTo(double range_m) {
  TimeAxis axis;
  axis.bin_width_s = 10e-12;
  axis.bins = static_cast<int32_t>(std::ceil(2.0 * range_m / (axis.bin_width_s * 299792458.0)));
  return axis;
}

std::vector<Echo> beamEchoes(const LidarSpec& spec, const WaveformScene& scene,
                             const TimeAxis& axis, int32_t ring, int32_t azimuth) {
  std::vector<float> w(static_cast<std::size_t>(axis.bins), 0.0f);
  const std::vector<BeamRay> rays = beamRays(spec.beam_rays, spec.divergence_rad, spec.profile);
  addBeamWaveform(spec, rays, scene, axis, ring, azimuth, w.data());
  return findEchoes(w.data(), axis, spec.returns);
}

// Distance from p (inside) along unit d to the cube [-h, h]^3.
double boxExit(const glm::dvec3& p, const glm::dvec3& d, double h) {
  double t = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (d[i] != 0.0) t = std::min(t, ((d[i] > 0.0 ? h : -h) - p[i]) / d[i]);
  }
  return t;
}

TEST(LidarWaveformTest, EveryBeamsFirstReturnLiesOnTheBoxRoom) {
  Traced room(test::makeClosedBox(4.0f, glm::vec3(0.5f)));
  const glm::vec3 p(0.3f, -0.2f, 0.1f);
  std::vector<double> elevations;
  for (int i = 0; i < 16; ++i) elevations.push_back(-15.0 + 2.0 * i);
  LidarSpec spec = spinning(p, elevations, 5.0);
  spec.returns.mode = ReturnMode::First;
  spec.returns.max = 1;
  const TimeAxis axis = axisTo(4.0);
  const LidarWaveforms w = renderDirectWaveforms(spec, room.traced, axis, 2);
  const LidarReturns r = lidarReturns(spec, w.volume, 10.0);
  ASSERT_EQ(r.points.size(), static_cast<std::size_t>(16 * 72));  // one per beam
  double worst = 0.0;
  for (const LidarPoint& point : r.points) {
    const glm::vec3 d = beamDirection(spec, point.ring, static_cast<int32_t>(std::lround(
                                                           (point.azimuth_deg) / 5.0)));
    const double expected = boxExit(glm::dvec3(p), glm::dvec3(d), 2.0);
    const glm::vec3 x(point.x, point.y, point.z);
    const double along = glm::dot(glm::dvec3(x - p), glm::dvec3(d));
    worst = std::max(worst, std::fabs(along - expected));
    // On its own beam: no offset across it.
    EXPECT_LT(glm::length(glm::dvec3(x - p) - along * glm::dvec3(d)), 1e-4);
  }
  EXPECT_LT(worst, 0.01) << "the worst return is " << worst << " m off the room";
  EXPECT_EQ(w.lost.before + w.lost.after, 0.0);
}

// Power of a beam beyond angle a on one side of a straight edge through
// the beam's cross-section: Gaussian (1/e^2 half angle w): 0.5 erfc(sqrt 2
// a / w); tophat of half angle R: the circular segment's area fraction.
double coveredBeyond(double a, double divergence, BeamProfile profile) {
  const double half = 0.5 * divergence;
  if (profile == BeamProfile::Gaussian) return 0.5 * std::erfc(std::sqrt(2.0) * a / half);
  const double x = a / half;
  return (std::acos(x) - x * std::sqrt(1.0 - x * x)) / M_PI;
}

class LidarStepEdgeTest : public ::testing::TestWithParam<BeamProfile> {};

TEST_P(LidarStepEdgeTest, ABeamOnAStepEdgeReturnsTwoEchoesSplitByItsProfile) {
  // A near plate at x = 5 covering y < 0 in front of a far wall at x = 8;
  // the beam's axis passes 0.3 mrad to the +y side of the plate's edge.
  scene::Scene s;
  test::addQuad(s, glm::vec3(5.0f, -1.0f, 0.0f), glm::vec3(-1, 0, 0), 2.0f, glm::vec3(0.5f));
  test::addQuad(s, glm::vec3(8.0f, 0.0f, 0.0f), glm::vec3(-1, 0, 0), 8.0f, glm::vec3(0.5f));
  Traced edge(std::move(s));
  const double a = 0.3e-3;
  LidarSpec spec = spinning(glm::vec3(0.0f), {0.0}, glm::degrees(a));
  spec.azimuth_end_deg = 2.0 * glm::degrees(a);  // azimuths 0 and a
  spec.divergence_rad = 3e-3;
  spec.profile = GetParam();
  spec.beam_rays = 1024;
  const std::vector<Echo> echoes = beamEchoes(spec, edge.traced, axisTo(9.0), 0, 1);
  ASSERT_EQ(echoes.size(), 2u);
  EXPECT_NEAR(echoes[0].range_m, 5.0, 0.002);
  EXPECT_NEAR(echoes[1].range_m, 8.0, 0.002);
  const double nearShare = coveredBeyond(a, spec.divergence_rad, spec.profile);
  const double perShare = spec.power_W * 0.5 / M_PI;  // rho / pi at normal incidence
  // 16 rings x 64 sectors place the edge to within about a sector's share
  // of the rings it crosses: 1 % of the beam.
  EXPECT_NEAR(echoes[0].intensity / (perShare / 25.0), nearShare, 0.01);
  EXPECT_NEAR(echoes[1].intensity / (perShare / 64.0), 1.0 - nearShare, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Profiles, LidarStepEdgeTest,
                         ::testing::Values(BeamProfile::Gaussian, BeamProfile::Tophat),
                         [](const ::testing::TestParamInfo<BeamProfile>& info) {
                           return info.param == BeamProfile::Gaussian ? "Gaussian" : "Tophat";
                         });

TEST(LidarWaveformTest, APlanesEchoIsRhoCosOverPiRSquared) {
  const double rho = 0.3;
  for (const double r : {2.0, 5.0, 12.0}) {
    for (const double theta_deg : {0.0, 30.0, 60.0}) {
      const double t = glm::radians(theta_deg);
      scene::Scene s;
      test::addQuad(s, glm::vec3(float(r), 0.0f, 0.0f),
                    glm::vec3(float(-std::cos(t)), float(std::sin(t)), 0.0f), 20.0f,
                    glm::vec3(float(rho)));
      Traced plane(std::move(s));
      const LidarSpec spec = spinning(glm::vec3(0.0f), {0.0}, 1.0);
      const std::vector<Echo> echoes = beamEchoes(spec, plane.traced, axisTo(r + 2.0), 0, 0);
      ASSERT_EQ(echoes.size(), 1u);
      const double expected = spec.power_W * rho * std::cos(t) / (M_PI * r * r);
      EXPECT_NEAR(echoes[0].intensity / expected, 1.0, 0.01) << r << " m, " << theta_deg << " deg";
      EXPECT_NEAR(echoes[0].range_m, r, 0.002);
    }
  }
}

TEST(LidarWaveformTest, AMediumAttenuatesTheEchoBothWays) {
  scene::Scene s;
  test::addQuad(s, glm::vec3(6.0f, 0.0f, 0.0f), glm::vec3(-1, 0, 0), 20.0f, glm::vec3(0.5f));
  Traced plane(std::move(s));
  plane.traced.medium.sigma_a_per_m = glm::vec3(0.02f, 0.05f, 0.08f);
  const LidarSpec spec = spinning(glm::vec3(0.0f), {0.0}, 1.0);
  const std::vector<Echo> echoes = beamEchoes(spec, plane.traced, axisTo(8.0), 0, 0);
  ASSERT_EQ(echoes.size(), 1u);
  const double vacuum = spec.power_W * 0.5 / (M_PI * 36.0);
  const double t = (std::exp(-0.24) + std::exp(-0.6) + std::exp(-0.96)) / 3.0;  // 2 x 6 m
  EXPECT_NEAR(echoes[0].intensity / (vacuum * t), 1.0, 1e-4);
}

TEST(LidarWaveformTest, TheSameBytesOnAnyThreadCount) {
  Traced room(test::makeClosedBox(4.0f, glm::vec3(0.5f)));
  const LidarSpec spec = spinning(glm::vec3(0.1f), {-10.0, 0.0, 10.0}, 3.0);
  const TimeAxis axis = axisTo(4.0);
  const LidarWaveforms one = renderDirectWaveforms(spec, room.traced, axis, 1);
  const LidarWaveforms two = renderDirectWaveforms(spec, room.traced, axis, 2);
  EXPECT_EQ(one.volume.values(), two.volume.values());
}

// A frame rendered without its dense volume (returns found on each beam's
// nonzero bins) gives the volume's returns to the bit, and its bins are the
// volume's: a room with a plate across half of it, so that beams over the
// plate's edges return two echoes.
TEST(LidarWaveformTest, TheReturnsAreTheSameWithOrWithoutTheVolume) {
  scene::Scene s = test::makeClosedBox(4.0f, glm::vec3(0.5f));
  test::addQuad(s, glm::vec3(1.0f, 0.8f, 0.0f), glm::vec3(-1, 0, 0), 1.6f, glm::vec3(0.8f));
  Traced room(std::move(s));
  LidarSpec spec = spinning(glm::vec3(0.0f), {-12.0, -4.0, 0.0, 4.0, 12.0}, 1.0);
  spec.divergence_rad = 0.03;  // wide beams: many over an edge
  spec.returns.mode = ReturnMode::All;
  spec.returns.max = 4;
  spec.returns.separation_m = 0.05;
  const TimeAxis axis = axisTo(4.0);
  const LidarWaveforms dense = renderDirectWaveforms(spec, room.traced, axis, 2, true);
  for (int threads : {1, 2}) {
    const LidarWaveforms sparse = renderDirectWaveforms(spec, room.traced, axis, threads, false);
    EXPECT_EQ(sparse.volume.size(), 0u);
    std::vector<float> w(static_cast<std::size_t>(axis.bins));
    for (std::size_t b = 0; b < sparse.sparse.beams(); ++b) {
      sparse.beamWaveform(b, w.data());
      ASSERT_EQ(0, std::memcmp(w.data(), dense.volume.data() + b * dense.volume.pixelStride(),
                               w.size() * 4))
          << "beam " << b;
    }
    EXPECT_EQ(sparse.lost.before, dense.lost.before);
    EXPECT_EQ(sparse.lost.after, dense.lost.after);
    const LidarReturns a = lidarReturns(spec, dense.volume, 10.0);
    const LidarReturns b = lidarReturns(spec, sparse, 10.0, threads);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i) {
      const LidarPoint &p = a.points[i], &q = b.points[i];
      EXPECT_TRUE(p.x == q.x && p.y == q.y && p.z == q.z && p.intensity == q.intensity &&
                  p.ring == q.ring && p.azimuth_deg == q.azimuth_deg &&
                  p.return_index == q.return_index && p.time_offset_s == q.time_offset_s)
          << "point " << i;
    }
    EXPECT_EQ(a.range_m.data, b.range_m.data);
    EXPECT_EQ(a.intensity.data, b.intensity.data);
    std::size_t twoEchoes = 0;
    for (std::size_t i = 0; i < a.points.size(); ++i) twoEchoes += a.points[i].return_index == 1;
    EXPECT_GE(twoEchoes, 5u);  // the comparison covers beams with several echoes (10)
  }
}

// A beam's rays traced as Embree packets hit what each ray alone hits, bit
// for bit: lidar_street's beams along +x (azimuth 0), whose rays' lateral
// components have both signs, and their neighbours (Embree's
// coherent-context traversal lost half of such a packet).
TEST(LidarWaveformTest, PacketsHitWhatTheirRaysHitAlone) {
  const scene::Scene street = scene::loadGltf(std::string(TOFSIM_SOURCE_DIR) +
                                              "/configs/scenes/lidar_street.gltf");
  const rays::RayScene rays(street, 1);
  LidarSpec spec;
  spec.position_world = {0.0f, 1.8f, 0.0f};
  spec.up_world = {0.0f, 1.0f, 0.0f};
  spec.forward_world = {1.0f, 0.0f, 0.0f};
  for (int c = 0; c < 16; ++c) spec.elevations_deg.push_back(-15.0 + 2.0 * c);
  const ReceiverRays receiver(beamRays(16, 3e-3, BeamProfile::Gaussian));
  constexpr int kPacket = rays::RayScene::kPacketSize;
  glm::vec3 d[kPacket];
  std::optional<rays::SurfaceHit> hits[kPacket];
  int compared = 0;
  for (int32_t ring = 0; ring < 16; ++ring) {
    for (int32_t a : {0, 1, 900, 1799}) {
      const BeamFrame f = beamFrame(beamDirection(spec, ring, a), spec.up_world);
      for (int first = 0; first < 16; first += kPacket) {
        for (int i = 0; i < kPacket; ++i) d[i] = rayDirection(f, receiver.tilts[first + i]);
        rays.intersectPacket(spec.position_world, d, kPacket, hits);
        for (int i = 0; i < kPacket; ++i) {
          const std::optional<rays::SurfaceHit> alone = rays.intersect(spec.position_world, d[i]);
          ASSERT_EQ(bool(alone), bool(hits[i])) << "ring " << ring << ", azimuth " << a;
          if (!alone) continue;
          ++compared;
          EXPECT_EQ(alone->distance_m, hits[i]->distance_m) << "ring " << ring << ", azimuth " << a;
          EXPECT_EQ(alone->triangle, hits[i]->triangle) << "ring " << ring << ", azimuth " << a;
        }
      }
    }
  }
  EXPECT_GT(compared, 300);  // of 512 rays: the highest rings see the sky
}

TEST(LidarEchoesTest, ModesKeepTheirReturns) {
  // Three echoes: weak, strong, medium.
  TimeAxis axis;
  axis.bin_width_s = 1e-9;
  axis.bins = 100;
  std::vector<float> w(100, 0.0f);
  w[10] = 1.0f;
  w[40] = 5.0f;
  w[41] = 1.0f;
  w[80] = 3.0f;
  ReturnSettings r;
  r.max = 3;
  const std::vector<Echo> echoes = findEchoes(w.data(), axis, r);
  ASSERT_EQ(echoes.size(), 3u);
  EXPECT_DOUBLE_EQ(echoes[1].intensity, 6.0);
  const auto firstOf = [&](ReturnMode m) {
    r.mode = m;
    std::vector<double> out;
    for (const Echo& e : selectReturns(echoes, r)) out.push_back(e.intensity);
    return out;
  };
  EXPECT_EQ(firstOf(ReturnMode::First), (std::vector<double>{1.0}));
  EXPECT_EQ(firstOf(ReturnMode::Strongest), (std::vector<double>{6.0}));
  EXPECT_EQ(firstOf(ReturnMode::Last), (std::vector<double>{3.0}));
  EXPECT_EQ(firstOf(ReturnMode::Dual), (std::vector<double>{6.0, 3.0}));
  EXPECT_EQ(firstOf(ReturnMode::All), (std::vector<double>{1.0, 6.0, 3.0}));
  r.max = 2;
  EXPECT_EQ(firstOf(ReturnMode::All), (std::vector<double>{1.0, 6.0}));
  // A threshold above the weak echo drops it.
  r.threshold = 2.0;
  EXPECT_EQ(findEchoes(w.data(), axis, r).size(), 2u);
}

}  // namespace
}  // namespace tofsim::lidar
