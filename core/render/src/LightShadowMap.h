#pragma once
// Distance from the light to the nearest surface in every direction: a cube
// map stored as six layers of a 2D array texture, so that the gather shader
// picks the face and texel with exactly the matrices used to render it (see
// visibleFromLight in shaders/light.glsl).

#include <array>
#include <glm/glm.hpp>

#include "tofsim/gl/Framebuffer.h"
#include "tofsim/gl/Program.h"
#include "tofsim/gl/Texture.h"

namespace tofsim::render {

class GpuScene;

class LightShadowMap {
 public:
  LightShadowMap(int resolution, const glm::vec3& light_world, const glm::vec3& boundsMin,
                 const glm::vec3& boundsMax);
  void render(const GpuScene& scene);
  /// Sets the uShadow* uniforms of light.glsl and binds the map to its unit.
  void bind(const gl::Program& program) const;

  int resolution() const { return resolution_; }
  std::size_t bytes() const;

 private:
  int resolution_;
  glm::vec3 light_world_;
  std::array<glm::mat4, 6> viewProjection_;
  gl::Texture distance_;
  gl::Texture depth_;
  gl::Program program_;
};

}  // namespace tofsim::render
