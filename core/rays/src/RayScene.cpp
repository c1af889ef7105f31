#include "tofsim/rays/RayScene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "BeamBvh.h"
#include "tofsim/scene/TextureSampling.h"
#include "tofsim/util/Error.h"

namespace tofsim::rays {

namespace {

void throwIfDeviceError(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) {
    throw InputError(std::string("embree: ") + what + " failed (error " +
                     std::to_string(static_cast<int>(error)) + ")");
  }
}

glm::vec3 faceTowards(glm::vec3 n, const glm::vec3& towards) {
  return glm::dot(n, towards) < 0.0f ? -n : n;
}

}  // namespace

glm::vec3 surfacePoint(const scene::Scene& scene, uint32_t mesh, uint32_t triangle,
                       glm::vec2 barycentric) {
  const scene::Mesh& m = scene.meshes[mesh];
  const uint32_t* tri = &m.indices[static_cast<std::size_t>(triangle) * 3];
  const float u = barycentric.x, v = barycentric.y, w = 1.0f - u - v;
  return w * m.positions_world[tri[0]] + u * m.positions_world[tri[1]] +
         v * m.positions_world[tri[2]];
}

RayScene::RayScene(const scene::Scene& scene, int threads, const std::string& isa)
    : scene_(scene), isa_(isa) {
  std::string config = threads > 0 ? "threads=" + std::to_string(threads) : std::string();
  if (!isa.empty()) config += (config.empty() ? "isa=" : ",isa=") + isa;
  device_ = rtcNewDevice(config.c_str());
  if (device_ == nullptr) throw InputError("embree: cannot create a device");
  rtcScene_ = rtcNewScene(device_);
  // Robust: watertight traversal, so rays through shared edges never slip through.
  rtcSetSceneFlags(rtcScene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(rtcScene_, RTC_BUILD_QUALITY_HIGH);
  builtVertices_.assign(scene.meshes.size(), 0);
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const scene::Mesh& mesh = scene.meshes[m];
    if (mesh.triangleCount() == 0) continue;
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Copies into Embree-owned (padded) buffers; the scene's vectors are not padded.
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), mesh.positions_world.size()));
    auto* indices = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(uint32_t), mesh.triangleCount()));
    throwIfDeviceError(device_, "buffer allocation");
    for (std::size_t i = 0; i < mesh.positions_world.size(); ++i) {
      for (int k = 0; k < 3; ++k) vertices[3 * i + k] = mesh.positions_world[i][k];
    }
    std::copy_n(mesh.indices.data(), mesh.triangleCount() * 3, indices);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(rtcScene_, geometry, static_cast<unsigned>(m));
    builtVertices_[m] = mesh.positions_world.size();
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(rtcScene_);
  throwIfDeviceError(device_, "BVH build");
  packets_ = rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) != 0;
  const scene::Bounds b = scene.bounds();
  epsilon_m_ = std::max(1e-5f * glm::length(b.max - b.min), 1e-7f);
}

bool RayScene::updateMeshes(const std::vector<std::size_t>& moved) {
  for (std::size_t m : moved) {
    const scene::Mesh& mesh = scene_.meshes[m];
    RTCGeometry geometry = mesh.triangleCount() == 0
                               ? nullptr
                               : rtcGetGeometry(rtcScene_, static_cast<unsigned>(m));
    if (mesh.triangleCount() != 0 && geometry == nullptr) return false;
    if (geometry != nullptr && builtVertices_[m] != mesh.positions_world.size()) return false;
    if (mesh.triangleCount() == 0 && builtVertices_[m] != 0) return false;
  }
  for (std::size_t m : moved) {
    const scene::Mesh& mesh = scene_.meshes[m];
    if (mesh.triangleCount() == 0) continue;
    RTCGeometry geometry = rtcGetGeometry(rtcScene_, static_cast<unsigned>(m));
    auto* vertices =
        static_cast<float*>(rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_VERTEX, 0));
    for (std::size_t i = 0; i < mesh.positions_world.size(); ++i) {
      for (int k = 0; k < 3; ++k) vertices[3 * i + k] = mesh.positions_world[i][k];
    }
    rtcUpdateGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0);
    rtcCommitGeometry(geometry);
  }
  rtcCommitScene(rtcScene_);
  throwIfDeviceError(device_, "BVH update");
#if defined(TOFSIM_RAYS_BUNDLES)
  if (beamBvh_) beamBvh_->refit(bundleTriangles());
#endif
  return true;
}

std::vector<detail::BundleTriangle> RayScene::bundleTriangles() const {
  std::vector<detail::BundleTriangle> out;
  for (std::size_t m = 0; m < scene_.meshes.size(); ++m) {
    const scene::Mesh& mesh = scene_.meshes[m];
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
      detail::BundleTriangle tri;
      float* corners[3] = {tri.v0, tri.v1, tri.v2};
      for (int k = 0; k < 3; ++k) {
        const glm::vec3& p = mesh.positions_world[mesh.indices[3 * t + k]];
        for (int c = 0; c < 3; ++c) corners[k][c] = p[c];
      }
      tri.mesh = static_cast<uint32_t>(m);
      tri.triangle = static_cast<uint32_t>(t);
      const glm::vec3 n = triangleNormal(tri.mesh, tri.triangle);
      for (int c = 0; c < 3; ++c) tri.normal[c] = n[c];
      out.push_back(tri);
    }
  }
  return out;
}

const detail::BeamBvh* RayScene::beamBvh() const {
#if defined(TOFSIM_RAYS_BUNDLES)
  std::call_once(beamOnce_, [this] {
    const detail::BundleIsa isa = detail::bundleIsaFor(isa_.c_str());
    if (isa != detail::BundleIsa::None) {
      auto bvh = std::make_unique<detail::BeamBvh>(bundleTriangles(), isa);
      if (bundlesAgree(*bvh)) beamBvh_ = std::move(bvh);  // else Embree traces every packet
    }
  });
#endif
  return beamBvh_.get();
}

bool RayScene::bundlesAgree(const detail::BeamBvh& bvh) const {
#if defined(TOFSIM_RAYS_BUNDLES)
  // Up to 64 triangles spread over the scene, each seen from a point off
  // its plane by 16 rays through points across it (near its edges too).
  const std::vector<detail::BundleTriangle> triangles = bundleTriangles();
  const std::size_t step = std::max<std::size_t>(1, triangles.size() / 64);
  for (std::size_t k = 0; k < triangles.size(); k += step) {
    const detail::BundleTriangle& tri = triangles[k];
    const glm::vec3 p0(tri.v0[0], tri.v0[1], tri.v0[2]), p1(tri.v1[0], tri.v1[1], tri.v1[2]),
        p2(tri.v2[0], tri.v2[1], tri.v2[2]);
    const glm::vec3 centre = (p0 + p1 + p2) / 3.0f;
    const glm::vec3 normal(tri.normal[0], tri.normal[1], tri.normal[2]);
    const float size = glm::length(p1 - p0) + glm::length(p2 - p0);
    if (!(size > 0.0f) || !(glm::dot(normal, normal) > 0.5f)) continue;
    const glm::vec3 origin = centre + normal * size + (p1 - p0) * 0.1f;
    detail::BundleRays rays;
    rays.ox = origin.x;
    rays.oy = origin.y;
    rays.oz = origin.z;
    for (int i = 0; i < detail::kBundleLanes; ++i) {
      const float a = 0.06f * float(i % 4) + 0.02f, b = 0.2f * float(i / 4) + 0.05f;
      const glm::vec3 d = glm::normalize(p0 + a * (p1 - p0) + b * (p2 - p0) - origin);
      rays.dx[i] = d.x;
      rays.dy[i] = d.y;
      rays.dz[i] = d.z;
      rays.active[i] = -1;
    }
    if (!bvh.trace(rays)) continue;
    for (int i = 0; i < detail::kBundleLanes; ++i) {
      if (rays.tie[i] != 0 || (std::isfinite(rays.edgeT[i]) && rays.edgeT[i] <= rays.t[i]))
        continue;
      // intersect() is rtcIntersect1's hit as every other caller gets it.
      const std::optional<SurfaceHit> single =
          intersect(origin, glm::vec3(rays.dx[i], rays.dy[i], rays.dz[i]));
      if (single.has_value() != (rays.hit[i] >= 0)) return false;
      if (!single) continue;
      const detail::BundleTriangle& hit = bvh.triangle(rays.hit[i]);
      if (hit.mesh != single->mesh || hit.triangle != single->triangle ||
          rays.t[i] != single->distance_m || rays.u[i] != single->barycentric.x ||
          rays.v[i] != single->barycentric.y) {
        return false;
      }
    }
  }
#else
  (void)bvh;
#endif
  return true;
}

RayScene::~RayScene() {
  if (rtcScene_ != nullptr) rtcReleaseScene(rtcScene_);
  if (device_ != nullptr) rtcReleaseDevice(device_);
}

std::optional<SurfaceHit> RayScene::intersect(const glm::vec3& origin, const glm::vec3& direction,
                                              float tNear) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = origin.x;
  rh.ray.org_y = origin.y;
  rh.ray.org_z = origin.z;
  rh.ray.dir_x = direction.x;
  rh.ray.dir_y = direction.y;
  rh.ray.dir_z = direction.z;
  rh.ray.tnear = tNear;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(rtcScene_, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return completeHit(direction, rh.ray.tfar, rh.hit.geomID, rh.hit.primID, {rh.hit.u, rh.hit.v});
}

int RayScene::intersectPacket(const glm::vec3& origin, const glm::vec3* directions, int count,
                              std::optional<SurfaceHit>* hits) const {
  TOFSIM_CHECK(count >= 0 && count <= kPacketSize);
  static_assert(kPacketSize == detail::kBundleLanes);
  // A bundle's traversal costs about what Embree's single rays do for a
  // few rays (measured: one ray a bundle is 3-6x slower): few rays go to Embree.
  constexpr int kFewestBundled = 4;
  if (const detail::BeamBvh* bvh = bundles_ && count >= kFewestBundled ? beamBvh() : nullptr) {
    detail::BundleRays rays;
    rays.ox = origin.x;
    rays.oy = origin.y;
    rays.oz = origin.z;
    for (int i = 0; i < kPacketSize; ++i) {
      const glm::vec3 d = i < count ? directions[i] : directions[0];
      rays.dx[i] = d.x;
      rays.dy[i] = d.y;
      rays.dz[i] = d.z;
      rays.active[i] = i < count ? -1 : 0;
    }
#if defined(TOFSIM_RAYS_BUNDLES)
    if (bvh->trace(rays)) {
      int bundled = 0;
      for (int i = 0; i < count; ++i) {
        // Where Embree's own order or boxes decide (two triangles at the
        // same t, a hit within rounding of an edge), Embree answers.
        const bool edge = rays.edgeT[i] <= rays.t[i] && std::isfinite(rays.edgeT[i]);
        if (rays.tie[i] != 0 || edge) {
          hits[i] = intersect(origin, directions[i]);
        } else if (rays.hit[i] < 0) {
          hits[i].reset();
          ++bundled;
        } else {
          const detail::BundleTriangle& tri = bvh->triangle(rays.hit[i]);
          const glm::vec3 normal(tri.normal[0], tri.normal[1], tri.normal[2]);
          hits[i] = completeHit(directions[i], rays.t[i], tri.mesh, tri.triangle,
                                {rays.u[i], rays.v[i]}, &normal);
          ++bundled;
        }
      }
      return bundled;
    }
#endif
  }
  intersectEmbreePacket(origin, directions, count, hits);
  return 0;
}

void RayScene::intersectEmbreePacket(const glm::vec3& origin, const glm::vec3* directions,
                                     int count, std::optional<SurfaceHit>* hits) const {
  TOFSIM_CHECK(count >= 0 && count <= kPacketSize);
  constexpr int kEmbreePacket = 8;  // rtcIntersect8: AVX2's width
  if (count > kEmbreePacket) {
    intersectEmbreePacket(origin, directions, kEmbreePacket, hits);
    intersectEmbreePacket(origin, directions + kEmbreePacket, count - kEmbreePacket,
                          hits + kEmbreePacket);
    return;
  }
  if (!packets_) {  // an Embree built without ray packets: one ray at a time
    for (int i = 0; i < count; ++i) hits[i] = intersect(origin, directions[i]);
    return;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  // Not RTC_INTERSECT_CONTEXT_FLAG_COHERENT: its frustum traversal drops
  // rays whose direction's signs differ from the packet's (a beam straight
  // along an axis has both), which lidar_street's azimuth 0 showed.
  alignas(32) int valid[kEmbreePacket];
  alignas(32) RTCRayHit8 rh;
  for (int i = 0; i < kEmbreePacket; ++i) {
    const bool on = i < count;
    valid[i] = on ? -1 : 0;
    const glm::vec3 d = on ? directions[i] : glm::vec3(0.0f, 0.0f, 1.0f);
    rh.ray.org_x[i] = origin.x;
    rh.ray.org_y[i] = origin.y;
    rh.ray.org_z[i] = origin.z;
    rh.ray.dir_x[i] = d.x;
    rh.ray.dir_y[i] = d.y;
    rh.ray.dir_z[i] = d.z;
    rh.ray.tnear[i] = 0.0f;
    rh.ray.tfar[i] = std::numeric_limits<float>::infinity();
    rh.ray.time[i] = 0.0f;
    rh.ray.mask[i] = 0xFFFFFFFFu;
    rh.ray.id[i] = 0;
    rh.ray.flags[i] = 0;
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect8(valid, rtcScene_, &context, &rh);
  for (int i = 0; i < count; ++i) {
    if (rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) {
      hits[i].reset();
    } else {
      hits[i] = completeHit(directions[i], rh.ray.tfar[i], rh.hit.geomID[i], rh.hit.primID[i],
                            {rh.hit.u[i], rh.hit.v[i]});
    }
  }
}

glm::vec3 RayScene::triangleNormal(uint32_t geomID, uint32_t primID) const {
  const scene::Mesh& mesh = scene_.meshes[geomID];
  const uint32_t* tri = &mesh.indices[static_cast<std::size_t>(primID) * 3];
  const glm::vec3& p0 = mesh.positions_world[tri[0]];
  const glm::vec3& p1 = mesh.positions_world[tri[1]];
  const glm::vec3& p2 = mesh.positions_world[tri[2]];
  return glm::normalize(glm::cross(p1 - p0, p2 - p0));
}

SurfaceHit RayScene::completeHit(const glm::vec3& direction, float distance_m, uint32_t geomID,
                                 uint32_t primID, glm::vec2 barycentric,
                                 const glm::vec3* unitNormal) const {
  const scene::Mesh& mesh = scene_.meshes[geomID];
  const uint32_t* tri = &mesh.indices[static_cast<std::size_t>(primID) * 3];
  const float u = barycentric.x, v = barycentric.y, w = 1.0f - u - v;
  SurfaceHit hit;
  hit.distance_m = distance_m;
  hit.mesh = geomID;
  hit.triangle = primID;
  hit.barycentric = barycentric;
  // Barycentric interpolation, like the rasterizer's G-buffer, rather than
  // origin + t * direction: it lies on the triangle to float precision.
  hit.position_world = surfacePoint(scene_, hit.mesh, hit.triangle, hit.barycentric);
  const glm::vec3 back = -direction;
  hit.geometric_world =
      faceTowards(unitNormal != nullptr ? *unitNormal : triangleNormal(geomID, primID), back);
  glm::vec3 n = hit.geometric_world;
  if (mesh.normals_world.size() == mesh.positions_world.size()) {
    const glm::vec3 interpolated = w * mesh.normals_world[tri[0]] + u * mesh.normals_world[tri[1]] +
                                   v * mesh.normals_world[tri[2]];
    if (glm::dot(interpolated, interpolated) > 0.0f) n = glm::normalize(interpolated);
  }
  hit.normal_world = faceTowards(n, back);
  glm::vec2 uv(0.0f);
  if (mesh.uvs.size() == mesh.positions_world.size()) {
    uv = w * mesh.uvs[tri[0]] + u * mesh.uvs[tri[1]] + v * mesh.uvs[tri[2]];
  }
  hit.material = mesh.material;
  hit.baseColorTexel = scene::baseColorTexel(scene_, mesh.material, uv);
  hit.metallicRoughnessTexel = scene::metallicRoughnessTexel(scene_, mesh.material, uv);
  return hit;
}

bool RayScene::occluded(const glm::vec3& from, const glm::vec3& to) const {
  const glm::vec3 d = to - from;
  const float length = glm::length(d);
  if (length <= 2.0f * epsilon_m_) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = from.x;
  ray.org_y = from.y;
  ray.org_z = from.z;
  ray.dir_x = d.x / length;
  ray.dir_y = d.y / length;
  ray.dir_z = d.z / length;
  ray.tnear = 0.0f;
  // Stop short of the end point so the surface `to` lies on does not count.
  ray.tfar = length - epsilon_m_;
  ray.mask = 0xFFFFFFFFu;
  rtcOccluded1(rtcScene_, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

glm::vec3 RayScene::offsetOrigin(const SurfaceHit& hit, const glm::vec3& towards) const {
  const glm::vec3 n = faceTowards(hit.geometric_world, towards);
  return hit.position_world + n * epsilon_m_;
}

}  // namespace tofsim::rays
