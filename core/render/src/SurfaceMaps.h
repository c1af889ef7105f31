#pragma once
// Rasterized surface attributes seen from one viewpoint: world position,
// facing normal, and the texel's scattering vertex as an index into a vertex
// table (the scene's materials', ir::materialVertices, then given samples')
// with what the material's textures give there: the base-colour texel and,
// where the glTF BRDF needs it, the metallic-roughness texel
// (physics::texturedVertex). The camera's G-buffer and the light's reflective
// shadow map are both SurfaceMaps.

#include <glm/glm.hpp>

#include "tofsim/gl/Framebuffer.h"
#include "tofsim/gl/Program.h"
#include "tofsim/gl/Texture.h"
#include "tofsim/physics/ScatterVertex.h"

namespace tofsim::render {

class GpuScene;
}  // namespace tofsim::render
namespace tofsim::ir {
struct SurfaceImage;
}  // namespace tofsim::ir
namespace tofsim::render {

struct SurfaceMaps {
  gl::Texture position;  ///< RGBA32F: xyz world, w = 1 on a surface
  gl::Texture normal;    ///< RGBA32F
  gl::Texture albedo;    ///< RGBA32F: rgb base-colour texel (1: none), a vertex index
  gl::Texture depth;     ///< DEPTH32F
  /// RG32F: metallic-roughness texel (1: none); only with
  /// withMetallicRoughness (else id 0).
  gl::Texture metallicRoughness;

  /// withMetallicRoughness: the camera G-buffer and the RSM of
  /// render.materials: gltf.
  SurfaceMaps(int width, int height, bool withMetallicRoughness = false);
  /// Rasterizes the scene with `viewProjection` from `viewpoint_world`.
  void render(const GpuScene& scene, const glm::mat4& viewProjection,
              const glm::vec3& viewpoint_world);
  /// Takes traced samples instead (an imager a rasterizer cannot draw):
  /// every pixel's samplesPerSide^2 samples, laid out as the gathers read a
  /// rasterized G-buffer (surface_samples.glsl: sample j N + i of pixel
  /// (x, y) at texel (x N + i, y N + j)). Sample k's vertex is entry
  /// firstVertex + k of the vertex table (samples.vertex appended to it).
  void load(const ir::SurfaceImage& samples, int32_t samplesPerSide, std::size_t firstVertex);

 private:
  gl::Framebuffer framebuffer_;
  gl::Program program_;
  bool withMetallicRoughness_;
};

/// Whether maps of surfaces whose vertices have `vertexModel`
/// (physics::VERTEX_*) carry the metallic-roughness texel: the glTF BRDF's.
inline bool mapsMetallicRoughness(int vertexModel) { return vertexModel == physics::VERTEX_GLTF; }

/// Near and far planes that enclose the scene's bounds seen from `eye`.
glm::vec2 depthRange(const glm::vec3& boundsMin, const glm::vec3& boundsMax, const glm::vec3& eye);

}  // namespace tofsim::render
