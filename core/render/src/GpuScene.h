#pragma once
// The scene's triangles, normals, uvs and albedo textures uploaded once, and
// drawn per mesh with its material by any pass that rasterizes the scene.

#include <vector>

#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Framebuffer.h"
#include "tofsim/gl/Program.h"
#include "tofsim/gl/Texture.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::render {

class GpuScene {
 public:
  explicit GpuScene(const scene::Scene& scene);
  /// Whether a draw sets the material uniforms (uMaterial,
  /// uHasAlbedoTexture) and texture per mesh: only programs that declare them;
  /// SetGltf also the metallic-roughness ones (gbuffer.frag's GLTF_MATERIALS).
  enum class Materials { Set, SetGltf, Skip };
  /// Draws every mesh.
  void draw(const gl::Program& program, Materials materials) const;
  std::size_t bytes() const { return bytes_; }
  const scene::Scene& scene() const { return scene_; }

 private:
  void setMaterial(const gl::Program& program, int32_t index, bool gltf) const;
  struct DrawRange {
    GLsizei indexCount = 0;
    std::size_t indexOffsetBytes = 0;
    GLint baseVertex = 0;
    int32_t material = 0;
  };
  const scene::Scene& scene_;
  gl::VertexArray vertexArray_;
  gl::Buffer vertices_;
  gl::Buffer indices_;
  std::vector<gl::Texture> textures_;
  std::vector<DrawRange> ranges_;
  std::size_t bytes_ = 0;
};

}  // namespace tofsim::render
