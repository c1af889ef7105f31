#include "LightShadowMap.h"

#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "GpuContract.h"
#include "GpuScene.h"
#include "SurfaceMaps.h"
#include "tofsim/gl/Check.h"

namespace tofsim::render {

LightShadowMap::LightShadowMap(int resolution, const glm::vec3& light, const glm::vec3& lo,
                               const glm::vec3& hi)
    : resolution_(resolution),
      light_world_(light),
      distance_(gl::Texture::create2DArray(GL_R32F, resolution, resolution, 6)),
      depth_(gl::Texture::create2DArray(GL_DEPTH_COMPONENT32F, resolution, resolution, 6)),
      program_(gpu::makeProgram(
          {{GL_VERTEX_SHADER, "gbuffer.vert"}, {GL_FRAGMENT_SHADER, "distance.frag"}})) {
  // Face order +X, -X, +Y, -Y, +Z, -Z matches cubeFace() in light.glsl.
  const glm::vec3 forward[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  const glm::vec3 up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  const glm::vec2 range = depthRange(lo, hi, light);
  const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, range.x, range.y);
  for (int face = 0; face < 6; ++face) {
    viewProjection_[face] = projection * glm::lookAt(light, light + forward[face], up[face]);
  }
}

void LightShadowMap::render(const GpuScene& scene) {
  program_.use();
  program_.set("uViewpoint_world", light_world_);
  glViewport(0, 0, resolution_, resolution_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  for (int face = 0; face < 6; ++face) {
    gl::Framebuffer framebuffer;
    framebuffer.attachColor(gpu::kOutPosition, distance_, face);
    framebuffer.attachDepth(depth_, face);
    framebuffer.finish("light shadow map face");
    framebuffer.bind();
    // Empty directions hold +inf: nothing there can cast a shadow.
    const float far[4] = {INFINITY, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, far);
    const float one = 1.0f;
    glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &one);
    program_.set("uViewProjection", viewProjection_[face]);
    scene.draw(program_, GpuScene::Materials::Skip);  // distance.frag has none
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  TOFSIM_GL_CHECK("LightShadowMap::render");
}

void LightShadowMap::bind(const gl::Program& program) const {
  for (int face = 0; face < 6; ++face) {
    const std::string name = "uShadowViewProjection[" + std::to_string(face) + "]";
    program.set(name.c_str(), viewProjection_[face]);
  }
  program.set("uShadowResolution", resolution_);
  distance_.bindUnit(gpu::kShadowMap);
}

std::size_t LightShadowMap::bytes() const {
  return static_cast<std::size_t>(resolution_) * resolution_ * 6 * 8;
}

}  // namespace tofsim::render
