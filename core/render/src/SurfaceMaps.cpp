#include "SurfaceMaps.h"

#include <algorithm>
#include <cmath>

#include "GpuContract.h"
#include "GpuScene.h"
#include "tofsim/gl/Check.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/util/Error.h"

namespace tofsim::render {

namespace {
std::vector<std::pair<std::string, std::string>> gbufferDefines(bool withMetallicRoughness) {
  if (!withMetallicRoughness) return {};
  return {{"GLTF_MATERIALS", "1"}};
}
}  // namespace

SurfaceMaps::SurfaceMaps(int width, int height, bool withMetallicRoughness)
    : position(gl::Texture::create2D(GL_RGBA32F, width, height)),
      normal(gl::Texture::create2D(GL_RGBA32F, width, height)),
      albedo(gl::Texture::create2D(GL_RGBA32F, width, height)),
      depth(gl::Texture::create2D(GL_DEPTH_COMPONENT32F, width, height)),
      metallicRoughness(withMetallicRoughness ? gl::Texture::create2D(GL_RG32F, width, height)
                                              : gl::Texture()),
      program_(gpu::makeProgram(
          {{GL_VERTEX_SHADER, "gbuffer.vert"}, {GL_FRAGMENT_SHADER, "gbuffer.frag"}},
          gbufferDefines(withMetallicRoughness))),
      withMetallicRoughness_(withMetallicRoughness) {
  framebuffer_.attachColor(gpu::kOutPosition, position);
  framebuffer_.attachColor(gpu::kOutNormal, normal);
  framebuffer_.attachColor(gpu::kOutAlbedo, albedo);
  if (withMetallicRoughness)
    framebuffer_.attachColor(gpu::kOutMetallicRoughness, metallicRoughness);
  framebuffer_.attachDepth(depth);
  framebuffer_.finish("SurfaceMaps framebuffer");
}

void SurfaceMaps::render(const GpuScene& scene, const glm::mat4& viewProjection,
                         const glm::vec3& viewpoint_world) {
  framebuffer_.bind();
  glViewport(0, 0, position.width(), position.height());
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const GLint colours = withMetallicRoughness_ ? 4 : 3;
  for (GLint i = 0; i < colours; ++i)
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, i, zero);
  const float one = 1.0f;
  glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &one);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // surfaces are two-sided
  program_.use();
  program_.set("uViewProjection", viewProjection);
  program_.set("uViewpoint_world", viewpoint_world);
  scene.draw(program_,
             withMetallicRoughness_ ? GpuScene::Materials::SetGltf : GpuScene::Materials::Set);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  TOFSIM_GL_CHECK("SurfaceMaps::render");
}

void SurfaceMaps::load(const ir::SurfaceImage& samples, int32_t samplesPerSide,
                       std::size_t firstVertex) {
  const int32_t n = samplesPerSide;
  TOFSIM_CHECK(position.width() == samples.width * n && position.height() == samples.height * n);
  const auto texels = static_cast<std::size_t>(position.width()) * position.height();
  // The index travels as a float: exact below 2^24.
  if (firstVertex + samples.vertex.size() > (std::size_t{1} << 24)) {
    throw InputError("the GL backend's G-buffer indexes at most 2^24 given samples (" +
                     std::to_string(samples.vertex.size()) + " given); use render.backend: cpu");
  }
  std::vector<glm::vec4> positions(texels), normals(texels), albedos(texels);
  std::vector<glm::vec2> metallicRoughnesses(withMetallicRoughness_ ? texels : 0,
                                             glm::vec2(1.0f));
  for (int32_t y = 0; y < samples.height; ++y) {
    for (int32_t x = 0; x < samples.width; ++x) {
      const auto pixel = static_cast<std::size_t>(y) * samples.width + x;
      TOFSIM_CHECK_EQ(samples.side[pixel], n);
      for (int32_t s = 0; s < n * n; ++s) {
        const std::size_t from = samples.firstSample[pixel] + static_cast<std::size_t>(s);
        const auto to = static_cast<std::size_t>(y * n + s / n) * position.width() +
                        static_cast<std::size_t>(x * n + s % n);
        positions[to] = samples.position[from];
        normals[to] = samples.normal[from];
        // The sample's whole vertex is its table entry: texels of 1.
        albedos[to] = glm::vec4(glm::vec3(1.0f), static_cast<float>(firstVertex + from));
      }
    }
  }
  position.upload2D(GL_RGBA, GL_FLOAT, positions.data());
  normal.upload2D(GL_RGBA, GL_FLOAT, normals.data());
  albedo.upload2D(GL_RGBA, GL_FLOAT, albedos.data());
  if (withMetallicRoughness_)
    metallicRoughness.upload2D(GL_RG, GL_FLOAT, metallicRoughnesses.data());
  TOFSIM_GL_CHECK("SurfaceMaps::load");
}

glm::vec2 depthRange(const glm::vec3& lo, const glm::vec3& hi, const glm::vec3& eye) {
  float farthest = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                      (corner & 4) ? hi.z : lo.z);
    farthest = std::max(farthest, glm::length(p - eye));
  }
  const float far = std::max(farthest * 1.01f, 1e-3f);
  // Depth resolution at the far plane is about far^2/near * 6e-8, i.e. 0.06% of far.
  return {std::max(far * 1e-4f, 1e-5f), far};
}

}  // namespace tofsim::render
