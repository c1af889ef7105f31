#include "PrimitiveBuilder.h"

#include <cmath>
#include <numeric>
#include <string>
#include <utility>

#include "AccessorReader.h"
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

}  // namespace

bool buildPrimitive(const GltfDocument& doc, const PrimitiveRef& ref, const glm::dmat4& world,
                    Mesh& out, LoadReport& report) {
  const Primitive& prim = doc.meshes[ref.mesh].primitives[ref.primitive];
  const std::string where =
      "mesh[" + std::to_string(ref.mesh) + "].primitives[" + std::to_string(ref.primitive) + "]";
  const auto fail = [&](const std::string& message) -> void {
    throw InputError(FileLoc{doc.file}, where, message);
  };
  if (prim.mode >= kPoints && prim.mode < kTriangles) {
    ++report.skippedPrimitives;
    return false;
  }
  if (prim.mode > kTriangleFan) fail("unknown primitive mode " + std::to_string(prim.mode));
  if (prim.position < 0) fail("has no POSITION");

  const std::vector<glm::vec3> pos = readVec3(doc, prim.position, "POSITION");
  for (std::size_t i = 0; i < pos.size(); ++i) {
    if (!finite(pos[i])) {
      fail("accessor[" + std::to_string(prim.position) + "] POSITION element " + std::to_string(i) +
           " is NaN or infinite");
    }
  }
  std::vector<glm::vec3> nrm;
  if (prim.normal >= 0) nrm = readVec3(doc, prim.normal, "NORMAL");
  std::vector<glm::vec2> uv;
  if (ref.uvSet < static_cast<int>(prim.texcoords.size()) && prim.texcoords[ref.uvSet] >= 0) {
    uv = readVec2(doc, prim.texcoords[ref.uvSet], "TEXCOORD_" + std::to_string(ref.uvSet));
  }
  if ((!nrm.empty() && nrm.size() != pos.size()) || (!uv.empty() && uv.size() != pos.size())) {
    fail("attributes have different counts");
  }

  std::vector<uint32_t> idx;
  if (prim.indices >= 0) {
    idx = readIndices(doc, prim.indices);
    for (const uint32_t i : idx) {
      if (i >= pos.size()) {
        fail("accessor[" + std::to_string(prim.indices) + "] index " + std::to_string(i) +
             " out of range (" + std::to_string(pos.size()) + " vertices)");
      }
    }
  } else {
    idx.resize(pos.size());
    std::iota(idx.begin(), idx.end(), 0u);
  }
  const std::vector<uint32_t> tri = triangleList(idx, prim.mode);

  const bool flip = glm::determinant(glm::dmat3(world)) < 0.0;
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
  std::vector<glm::dvec3> p(pos.size());
  for (std::size_t i = 0; i < pos.size(); ++i) {
    p[i] = glm::dvec3(world * glm::dvec4(pos[i], 1.0));
    // Finite in the file, but the node transforms may carry it past float's
    // range, where the scene stores it (found by fuzz_gltf).
    if (!finite(glm::dvec3(glm::vec3(p[i])))) {
      fail("accessor[" + std::to_string(prim.position) + "] POSITION element " + std::to_string(i) +
           " is beyond the float range after the node transforms");
    }
  }

  const bool flat = nrm.empty();
  if (flat) ++report.flatNormalPrimitives;
  const uint32_t base = static_cast<uint32_t>(out.positions_world.size());
  std::vector<bool> normalSet(pos.size(), false);
  if (!flat) {
    out.positions_world.insert(out.positions_world.end(), p.begin(), p.end());
    for (std::size_t i = 0; i < nrm.size(); ++i) {
      const glm::dvec3 n = normalMatrix * glm::dvec3(nrm[i]);
      const double len = glm::length(n);
      normalSet[i] = std::isfinite(len) && len > 0.0;
      out.normals_world.push_back(normalSet[i] ? glm::vec3(n / len) : glm::vec3(0.0f));
    }
    if (!uv.empty()) out.uvs.insert(out.uvs.end(), uv.begin(), uv.end());
  }

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
  return true;
}

}  // namespace tofsim::scene::detail
