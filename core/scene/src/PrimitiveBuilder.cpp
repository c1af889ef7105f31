#include "PrimitiveBuilder.h"

#include <cmath>
#include <numeric>
#include <string>
#include <utility>

#include "AccessorReader.h"
#include "tofsim/scene/SceneBound.h"
#include "tofsim/util/Error.h"

namespace tofsim::scene::detail {

namespace {

/// Vertex indices of each triangle, three per triangle, per the glTF rules.
std::vector<uint32_t> triangleList(const std::vector<uint32_t>& idx, int mode) {
  std::vector<uint32_t> tri;
  const std::size_t n = idx.size();
  if (mode == kTriangles) {
    tri.assign(idx.begin(), idx.begin() + static_cast<std::ptrdiff_t>(n / 3 * 3));
  } else if (mode == kTriangleStrip) {
    for (std::size_t i = 0; i + 2 < n; ++i) {  // {i, i+1+i%2, i+2-i%2}
      tri.insert(tri.end(), {idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]});
    }
  } else if (mode == kTriangleFan) {
    for (std::size_t i = 0; i + 2 < n; ++i) tri.insert(tri.end(), {idx[i + 1], idx[i + 2], idx[0]});
  }
  return tri;
}

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Throws the InputError of one primitive: its file and "mesh[m].primitives[p]".
class PrimitiveErrors {
 public:
  PrimitiveErrors(const GltfDocument& doc, const PrimitiveRef& ref)
      : file_(doc.file),
        where_("mesh[" + std::to_string(ref.mesh) + "].primitives[" +
               std::to_string(ref.primitive) + "]") {}
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(FileLoc{file_}, where_, message);
  }

 private:
  std::string file_;
  std::string where_;
};

/// A primitive's vertex attributes as the file holds them (model space).
struct Attributes {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  ///< empty when NORMAL is absent
  std::vector<glm::vec2> uvs;      ///< empty when TEXCOORD_<uvSet> is absent
};

/// POSITION (finite), NORMAL and the chosen TEXCOORD, checked to agree in count.
Attributes readAttributes(const GltfDocument& doc, const Primitive& prim, const PrimitiveRef& ref,
                          const PrimitiveErrors& errors) {
  Attributes a;
  a.positions = readVec3(doc, prim.position, "POSITION");
  for (std::size_t i = 0; i < a.positions.size(); ++i) {
    if (!finite(a.positions[i])) {
      errors.fail("accessor[" + std::to_string(prim.position) + "] POSITION element " +
                  std::to_string(i) + " is NaN or infinite");
    }
  }
  if (prim.normal >= 0) a.normals = readVec3(doc, prim.normal, "NORMAL");
  if (ref.uvSet < static_cast<int>(prim.texcoords.size()) && prim.texcoords[ref.uvSet] >= 0) {
    a.uvs = readVec2(doc, prim.texcoords[ref.uvSet], "TEXCOORD_" + std::to_string(ref.uvSet));
  }
  const std::size_t count = a.positions.size();
  if ((!a.normals.empty() && a.normals.size() != count) ||
      (!a.uvs.empty() && a.uvs.size() != count)) {
    errors.fail("attributes have different counts");
  }
  return a;
}

/// The primitive's vertex indices (0, 1, 2, ... without an index accessor),
/// each checked to name one of `vertexCount` vertices.
std::vector<uint32_t> readVertexIndices(const GltfDocument& doc, const Primitive& prim,
                                        std::size_t vertexCount, const PrimitiveErrors& errors) {
  std::vector<uint32_t> idx;
  if (prim.indices >= 0) {
    idx = readIndices(doc, prim.indices);
    for (const uint32_t i : idx) {
      if (i >= vertexCount) {
        errors.fail("accessor[" + std::to_string(prim.indices) + "] index " + std::to_string(i) +
                    " out of range (" + std::to_string(vertexCount) + " vertices)");
      }
    }
  } else {
    idx.resize(vertexCount);
    std::iota(idx.begin(), idx.end(), 0u);
  }
  return idx;
}

/// Positions moved into the world by `world`, in double; each must lie within
/// kMaxSceneCoordinate_m (Scene.h), which the float the scene stores it as
/// and the tracers can hold.
std::vector<glm::dvec3> worldPositions(const std::vector<glm::vec3>& pos, const glm::dmat4& world,
                                       int accessor, const PrimitiveErrors& errors) {
  std::vector<glm::dvec3> p(pos.size());
  for (std::size_t i = 0; i < pos.size(); ++i) {
    p[i] = glm::dvec3(world * glm::dvec4(pos[i], 1.0));
    // Finite in the file, but the node transforms may carry it past float's
    // range (found by fuzz_gltf), or past what a ray can start from (an
    // Embree assertion mid-render).
    if (!withinSceneBound(p[i])) {
      errors.fail("accessor[" + std::to_string(accessor) + "] POSITION element " +
                  std::to_string(i) + " lies " + sceneBoundText(p[i]) +
                  " after the node transforms");
    }
  }
  return p;
}

/// Appends the shared vertices of a primitive with normals to `out`: world
/// positions, normals by the inverse transpose of `world` (zero where the
/// file's normal is zero or broken: normalSet[i] false) and uvs.
void appendSmoothVertices(const std::vector<glm::dvec3>& p, const Attributes& a,
                          const glm::dmat4& world, Mesh& out, std::vector<bool>& normalSet) {
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
  out.positions_world.insert(out.positions_world.end(), p.begin(), p.end());
  for (std::size_t i = 0; i < a.normals.size(); ++i) {
    const glm::dvec3 n = normalMatrix * glm::dvec3(a.normals[i]);
    const double len = glm::length(n);
    normalSet[i] = std::isfinite(len) && len > 0.0;
    out.normals_world.push_back(normalSet[i] ? glm::vec3(n / len) : glm::vec3(0.0f));
  }
  if (!a.uvs.empty()) out.uvs.insert(out.uvs.end(), a.uvs.begin(), a.uvs.end());
}

/// Appends the triangles of `tri` that have area, wound for a mirroring
/// `world` (flip). Flat: three vertices of their own per triangle with the
/// face normal; smooth: indices from `base` into the vertices
/// appendSmoothVertices added, the face normal filling those it left unset.
void appendTriangles(const std::vector<uint32_t>& tri, const std::vector<glm::dvec3>& p,
                     const std::vector<glm::vec2>& uv, bool flip, bool flat, uint32_t base,
                     std::vector<bool>& normalSet, Mesh& out, LoadReport& report) {
  for (std::size_t t = 0; t + 2 < tri.size(); t += 3) {
    uint32_t a = tri[t], b = tri[t + 1], c = tri[t + 2];
    if (flip) std::swap(b, c);
    const glm::dvec3 cross = glm::cross(p[b] - p[a], p[c] - p[a]);
    const double len = glm::length(cross);
    if (!(len > 0.0) || !std::isfinite(len)) {  // exactly zero area (or overflow)
      ++report.degenerateTriangles;
      continue;
    }
    const glm::vec3 face(cross / len);
    if (flat) {
      for (const uint32_t v : {a, b, c}) {
        out.indices.push_back(static_cast<uint32_t>(out.positions_world.size()));
        out.positions_world.push_back(p[v]);
        out.normals_world.push_back(face);
        if (!uv.empty()) out.uvs.push_back(uv[v]);
      }
    } else {
      for (const uint32_t v : {a, b, c}) {
        if (!normalSet[v]) {  // zero or broken normal in the file: use the face's
          out.normals_world[base + v] = face;
          normalSet[v] = true;
        }
        out.indices.push_back(base + v);
      }
    }
  }
}

}  // namespace

bool buildPrimitive(const GltfDocument& doc, const PrimitiveRef& ref, const glm::dmat4& world,
                    Mesh& out, LoadReport& report) {
  const Primitive& prim = doc.meshes[ref.mesh].primitives[ref.primitive];
  const PrimitiveErrors errors(doc, ref);
  if (prim.mode >= kPoints && prim.mode < kTriangles) {
    ++report.skippedPrimitives;
    return false;
  }
  if (prim.mode > kTriangleFan) errors.fail("unknown primitive mode " + std::to_string(prim.mode));
  if (prim.position < 0) errors.fail("has no POSITION");

  const Attributes attributes = readAttributes(doc, prim, ref, errors);
  const std::vector<uint32_t> tri =
      triangleList(readVertexIndices(doc, prim, attributes.positions.size(), errors), prim.mode);
  const bool flip = glm::determinant(glm::dmat3(world)) < 0.0;
  const std::vector<glm::dvec3> p =
      worldPositions(attributes.positions, world, prim.position, errors);

  const bool flat = attributes.normals.empty();
  if (flat) ++report.flatNormalPrimitives;
  const uint32_t base = static_cast<uint32_t>(out.positions_world.size());
  std::vector<bool> normalSet(attributes.positions.size(), false);
  if (!flat) appendSmoothVertices(p, attributes, world, out, normalSet);
  appendTriangles(tri, p, attributes.uvs, flip, flat, base, normalSet, out, report);
  return true;
}

}  // namespace tofsim::scene::detail
