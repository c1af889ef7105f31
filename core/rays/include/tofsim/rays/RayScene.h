#pragma once
// The scene's triangles in an Embree BVH, and what the path tracer needs to
// know about a hit: position, normals facing the incoming ray (surfaces are
// two-sided, as in the GL renderer), its material and what its textures give.

#include <embree3/rtcore.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/scene/Scene.h"

namespace tofsim::rays {

struct SurfaceHit {
  float distance_m = 0.0f;  ///< along the (unit) ray direction
  glm::vec3 position_world{0.0f};
  glm::vec3 normal_world{0.0f};     ///< interpolated shading normal, facing the ray origin
  glm::vec3 geometric_world{0.0f};  ///< triangle normal, facing the ray origin
  /// The mesh's material (index into Scene::materials) and what its textures
  /// give at the hit (scene::baseColorTexel, scene::metallicRoughnessTexel;
  /// 1 where it has none): ir::hitVertex makes the vertex of them.
  int32_t material = 0;
  glm::vec3 baseColorTexel{1.0f};
  glm::vec2 metallicRoughnessTexel{1.0f};
  /// The point on its triangle, for finding it again when the scene moves:
  /// Scene::meshes[mesh]'s triangle `triangle`, at w p0 + u p1 + v p2 with
  /// (u, v) = barycentric, w = 1 - u - v.
  uint32_t mesh = 0;
  uint32_t triangle = 0;
  glm::vec2 barycentric{0.0f};
};

/// The point of Scene::meshes[mesh]'s triangle `triangle` at `barycentric`
/// (SurfaceHit's fields): w p0 + u p1 + v p2, in the scene as it is now (a
/// hit found again after the scene moved).
glm::vec3 surfacePoint(const scene::Scene& scene, uint32_t mesh, uint32_t triangle,
                       glm::vec2 barycentric);

namespace detail {
class BeamBvh;
struct BundleTriangle;
}  // namespace detail

class RayScene {
 public:
  /// threads: Embree's build threads, 0 = all. isa: the instruction set
  /// Embree runs (its device config's isa=, such as "avx2"; empty: the
  /// CPU's best), which intersectPacket's own kernels follow: tests pin it.
  RayScene(const scene::Scene& scene, int threads, const std::string& isa = {});
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  /// Closest hit along origin + t * direction (direction unit), t in (tNear, inf).
  std::optional<SurfaceHit> intersect(const glm::vec3& origin, const glm::vec3& direction,
                                      float tNear = 0.0f) const;
  /// Rays in a packet: a lidar beam's 16 receiver rays, or 16 beams' one.
  static constexpr int kPacketSize = 16;
  /// The closest hits of `count` (<= kPacketSize) rays from one origin, as
  /// intersect(origin, directions[i]) gives them, bit for bit: hits[i] for
  /// ray i. Rays within a narrow cone (a lidar beam's receiver rays,
  /// neighbouring beams) are traced together through a BVH of the scene's
  /// own (BeamBvh.h: each node tested once for all of them, each triangle
  /// against every ray at once, in Embree's own arithmetic), built on the
  /// first call; a wide packet, or a CPU without AVX2, goes to Embree.
  /// Returns how many of the rays the bundle answered (the others Embree).
  int intersectPacket(const glm::vec3& origin, const glm::vec3* directions, int count,
                      std::optional<SurfaceHit>* hits) const;
  /// Whether intersectPacket traces bundles (the default) or gives every
  /// packet to intersectEmbreePacket: benches time the one against the other.
  void setBundles(bool on) { bundles_ = on; }
  /// intersectPacket through Embree alone (rtcIntersect8 packets): what
  /// the bundles are checked and timed against.
  void intersectEmbreePacket(const glm::vec3& origin, const glm::vec3* directions, int count,
                             std::optional<SurfaceHit>* hits) const;
  /// After the scene's meshes `moved` were re-baked in place (same vertex
  /// and triangle counts: scene::AnimatedScene::updateScene), their vertices
  /// copied again and the BVH rebuilt on the same device: the hits of a
  /// RayScene built anew, without a new device per update (a rolling lidar
  /// scan updates per azimuth column). Returns false, changing nothing, when
  /// a mesh's counts differ from what was built: build a new RayScene then.
  bool updateMeshes(const std::vector<std::size_t>& moved);
  /// True when something lies strictly between `from` and `to`. `from` should
  /// already be offset off its surface (see offsetOrigin).
  bool occluded(const glm::vec3& from, const glm::vec3& to) const;

  /// A ray origin moved off the surface along the geometric normal, on the side
  /// `towards` points to, far enough to avoid hitting the surface itself.
  glm::vec3 offsetOrigin(const SurfaceHit& hit, const glm::vec3& towards) const;

  const scene::Scene& scene() const { return scene_; }

  /// A length proportional to the scene's size, for self-intersection epsilons.
  float epsilon_m() const { return epsilon_m_; }

 private:
  /// unitNormal: the triangle's unit normal (triangleNormal), where known.
  SurfaceHit completeHit(const glm::vec3& direction, float distance_m, uint32_t geomID,
                         uint32_t primID, glm::vec2 barycentric,
                         const glm::vec3* unitNormal = nullptr) const;
  glm::vec3 triangleNormal(uint32_t geomID, uint32_t primID) const;
  /// The scene's triangles as Embree holds them, mesh by mesh.
  std::vector<detail::BundleTriangle> bundleTriangles() const;
  /// The bundles' BVH, built on first use (null: Embree traces packets).
  const detail::BeamBvh* beamBvh() const;
  /// Whether `bvh`'s bundles hit what rtcIntersect1 hits, bit for bit, on
  /// probe rays through the scene's triangles: the kernels copy Embree
  /// 3.13.5's arithmetic, and another Embree build or version may differ.
  bool bundlesAgree(const detail::BeamBvh& bvh) const;

  const scene::Scene& scene_;
  RTCDevice device_ = nullptr;
  RTCScene rtcScene_ = nullptr;
  float epsilon_m_ = 1e-5f;
  bool packets_ = false;  ///< the device traces 8-wide packets natively
  std::string isa_;
  bool bundles_ = true;
  mutable std::once_flag beamOnce_;
  mutable std::unique_ptr<detail::BeamBvh> beamBvh_;
  std::vector<std::size_t> builtVertices_;  ///< per mesh slot: vertices built (0: none)
};

}  // namespace tofsim::rays
