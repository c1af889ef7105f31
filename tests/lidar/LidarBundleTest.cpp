// A packet of rays from one origin traced as one bundle
// (RayScene::intersectPacket: core/rays BeamBvh's pyramid traversal, each
// triangle tested against every ray at once in Embree's own arithmetic)
// hits what Embree's single-ray rtcIntersect1 hits, bit for bit (same
// mesh, triangle, distance and barycentrics): every ray of lidar_street's
// whole frame, 16 x 1800 beams of 16 receiver rays, and one ray a beam (16
// neighbouring beams to a packet), from the config's position and from an
// off-axis one (beams along the street's axes have rays on both sides of
// an edge), for each instruction set the bundle kernels have on this CPU.
// The packets must be the bundles' (not Embree's fallback) for >= 99 % of
// the rays.

#include <gtest/gtest.h>

#include <optional>
#include <sstream>
#include <string>

#include "tofsim/lidar/BeamPattern.h"
#include "tofsim/lidar/DirectWaveforms.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::lidar {
namespace {

LidarSpec streetLidar(const glm::vec3& position) {
  LidarSpec spec;
  spec.position_world = position;
  spec.up_world = {0.0f, 1.0f, 0.0f};
  spec.forward_world = {1.0f, 0.0f, 0.0f};
  for (int c = 0; c < 16; ++c) spec.elevations_deg.push_back(-15.0 + 2.0 * c);
  spec.azimuth_step_deg = 0.2;
  return spec;
}

struct FrameComparison {
  long rays = 0, bundled = 0, hits = 0, wrong = 0;
  std::string first;  // the first mismatch
};

// Every beam's `beamRays` rays, packed kPacketSize at a time across beams as
// DirectWaveforms' tracePacked packs them, against each ray alone.
FrameComparison compareFrame(const rays::RayScene& scene, const LidarSpec& spec, int beamRays) {
  const ReceiverRays receiver(lidar::beamRays(beamRays, 3e-3, BeamProfile::Gaussian));
  constexpr int kPacket = rays::RayScene::kPacketSize;
  glm::vec3 d[kPacket];
  std::optional<rays::SurfaceHit> hits[kPacket];
  FrameComparison out;
  int n = 0;
  const auto flush = [&] {
    out.bundled += scene.intersectPacket(spec.position_world, d, n, hits);
    for (int i = 0; i < n; ++i) {
      ++out.rays;
      const std::optional<rays::SurfaceHit> alone = scene.intersect(spec.position_world, d[i]);
      const bool same =
          bool(alone) == bool(hits[i]) &&
          (!alone || (alone->mesh == hits[i]->mesh && alone->triangle == hits[i]->triangle &&
                      alone->distance_m == hits[i]->distance_m &&
                      alone->barycentric == hits[i]->barycentric));
      out.hits += bool(alone);
      if (!same && out.wrong++ == 0) {
        std::ostringstream s;
        s << "direction (" << d[i].x << ", " << d[i].y << ", " << d[i].z << "): alone "
          << (alone ? std::to_string(alone->triangle) + " at " + std::to_string(alone->distance_m)
                    : std::string("nothing"))
          << ", packet "
          << (hits[i]
                  ? std::to_string(hits[i]->triangle) + " at " + std::to_string(hits[i]->distance_m)
                  : std::string("nothing"));
        out.first = s.str();
      }
    }
    n = 0;
  };
  for (int32_t ring = 0; ring < spec.channels(); ++ring) {
    for (int32_t a = 0; a < spec.azimuths(); ++a) {
      const BeamFrame f = beamFrame(beamDirection(spec, ring, a), spec.up_world);
      for (const RayTilt& tilt : receiver.tilts) {
        d[n] = rayDirection(f, tilt);
        if (++n == kPacket) flush();
      }
    }
  }
  if (n > 0) flush();
  return out;
}

TEST(LidarBundleTest, BundlesHitWhatEachRayHitsAlone) {
  const scene::Scene street =
      scene::loadGltf(std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/lidar_street.gltf");
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) {
    GTEST_SKIP() << "no AVX2 here: Embree traces every packet";
  }
  // "": the CPU's best (AVX-512 where it has it); "avx2": Embree and the
  // kernels pinned to AVX2 (its reciprocal differs from AVX-512's).
  for (const std::string isa : {"", "avx2"}) {
    const rays::RayScene scene(street, 1, isa);
    for (const glm::vec3 position : {glm::vec3(0.0f, 1.8f, 0.0f), glm::vec3(0.37f, 1.3f, -2.1f)}) {
      for (int beamRays : {16, 1}) {
        const FrameComparison c = compareFrame(scene, streetLidar(position), beamRays);
        SCOPED_TRACE("isa '" + isa + "', " + std::to_string(beamRays) + " rays a beam, position " +
                     std::to_string(position.x));
        EXPECT_EQ(c.wrong, 0) << "of " << c.rays << " rays; first: " << c.first;
        EXPECT_GE(c.bundled, c.rays * 99 / 100) << "rays the bundles answered";
        EXPECT_GT(c.hits, c.rays / 2);  // the frame sees the street, not the sky
      }
    }
  }
}

}  // namespace
}  // namespace tofsim::lidar
