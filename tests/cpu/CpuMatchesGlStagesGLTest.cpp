// The CPU backend against the GL one before the gather: the same G-buffer
// (pixel centres and N x N sub-pixel samples) and VPLs (exactly in what is
// discrete: which pixels see a surface, how many VPLs, in which order; within
// float tolerance in the values). The volumes: CpuMatchesGlGLTest.cpp.
// Needs a GL context (llvmpipe in CI).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "GpuScene.h"
#include "SurfaceMaps.h"
#include "Vpls.h"
#include "support/BackendScene.h"
#include "support/ClosedForm.h"
#include "support/GlTestContext.h"
#include "support/TestJobs.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/render/GlBackend.h"

namespace tofsim::cpu {
namespace {

void viewBounds(const capture::RenderJob& job, glm::vec3& lo, glm::vec3& hi) {
  const scene::Bounds b = job.scene->bounds();
  lo = glm::min(glm::min(b.min, job.camera().position_world), job.light.position_world);
  hi = glm::max(glm::max(b.max, job.camera().position_world), job.light.position_world);
}

std::vector<float> download(const gl::Texture& t, std::size_t texels) {
  std::vector<float> v(texels * 4);
  t.download(GL_RGBA, GL_FLOAT, v.size() * sizeof(float), v.data());
  return v;
}

// Rasterized and ray-traced points on the same triangle differ by float
// rounding only: 1e-5 of the scene's size; normals and albedo to 1e-5. With
// `samples` per side, the GL backend's G-buffer is the same view rasterized
// at (width N) x (height N) (surface_samples.glsl): its texel (x N + i, y N +
// j) must be the CPU's sample j N + i of pixel (x, y).
void expectSameGBuffer(const capture::RenderJob& job, int32_t samples = 1) {
  test::glTestContext();
  render::GpuScene gpuScene(*job.scene);
  glm::vec3 lo, hi;
  viewBounds(job, lo, hi);
  const int32_t width = job.camera().width * samples, height = job.camera().height * samples;
  render::SurfaceMaps gl(width, height);
  const glm::vec2 range = render::depthRange(lo, hi, job.camera().position_world);
  gl.render(gpuScene, job.camera().projection(range.x, range.y) * job.camera().view(),
            job.camera().position_world);
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  const auto position = download(gl.position, pixels);
  const auto normal = download(gl.normal, pixels);
  const auto albedo = download(gl.albedo, pixels);
  const rays::RayScene rays(*job.scene, 1);
  const ir::SurfaceImage cpu = ir::traceSurfaces(rays, job.camera(), 2, samples);
  const float tol = 1e-5f * glm::length(hi - lo);
  // GL's texels name their vertex in the scene's table (surface_samples.glsl).
  const std::vector<physics::ScatterVertex> materials =
      ir::materialVertices(*job.scene, physics::VERTEX_LAMBERTIAN);
  std::size_t surfaces = 0;
  for (std::size_t t = 0; t < pixels; ++t) {
    const std::size_t tx = t % width, ty = t / width;
    const std::size_t pixel = (ty / samples) * job.camera().width + tx / samples;
    const std::size_t i = pixel * samples * samples + (ty % samples) * samples + tx % samples;
    ASSERT_EQ(cpu.position[i].w, position[4 * t + 3]) << "sample " << i;
    if (cpu.position[i].w == 0.0f) continue;
    ++surfaces;
    const physics::ScatterVertex glVertex = physics::texturedVertex(
        materials.at(static_cast<std::size_t>(albedo[4 * t + 3])),
        glm::vec3(albedo[4 * t], albedo[4 * t + 1], albedo[4 * t + 2]), glm::vec2(1.0f));
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(cpu.position[i][k], position[4 * t + k], tol) << "sample " << i;
      EXPECT_NEAR(cpu.normal[i][k], normal[4 * t + k], 1e-5f) << "sample " << i;
      EXPECT_NEAR(cpu.vertex[i].color[k], glVertex.color[k], 1e-5f) << "sample " << i;
    }
  }
  EXPECT_GT(surfaces, pixels / 2);
}

TEST(CpuMatchesGlGLTest, GBufferOnThePlane) { expectSameGBuffer(test::PlaneJob().job); }
TEST(CpuMatchesGlGLTest, GBufferOnTheCorner) { expectSameGBuffer(test::CornerJob(32).job); }
TEST(CpuMatchesGlGLTest, SubPixelGBufferOnTheCorner) {
  expectSameGBuffer(test::CornerJob(16).job, 3);
}

// Same count and order; positions and paths to 1e-5 of the scene, flux to
// 2e-4 relative: both evaluate the same texel formula, but in a spot's falloff
// the profile's slope amplifies the rounding of the hit point (measured 6e-5).
void expectSameVpls(const capture::RenderJob& job) {
  test::glTestContext();
  render::GpuScene gpuScene(*job.scene);
  glm::vec3 lo, hi;
  viewBounds(job, lo, hi);
  const capture::IndirectSettings& s = job.settings.indirect;
  const auto gl = render::generateVpls(gpuScene, job.light, s.rsm_resolution, s.rsm_edge_samples,
                                       job.settings.time.index_of_refraction, lo, hi,
                                       ir::vertexModelOf(job.settings.materials));
  CpuBackend backend({2, true});
  const test::BackendScene prepared(backend, *job.scene);
  backend.prepareSurfaces(job);
  const auto cpu = backend.generateVpls(job);
  ASSERT_EQ(cpu.size(), gl.size());
  ASSERT_GT(cpu.size(), 0u);
  const float tol = 1e-5f * glm::length(hi - lo);
  for (std::size_t k = 0; k < cpu.size(); ++k) {
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(cpu[k].positionPath[i], gl[k].positionPath[i], tol) << "VPL " << k;
      EXPECT_NEAR(cpu[k].normal[i], gl[k].normal[i], 1e-5f) << "VPL " << k;
      EXPECT_NEAR(cpu[k].flux[i], gl[k].flux[i], 2e-4f * gl[k].flux[i]) << "VPL " << k;
      // render.materials: gltf: the direction to the light (0 otherwise).
      EXPECT_NEAR(cpu[k].incoming[i], gl[k].incoming[i], 1e-5f) << "VPL " << k;
    }
    // The vertex: base colour and metallic, roughness, model.
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(cpu[k].vertex.color[i], gl[k].vertex.color[i], 1e-5f) << "VPL " << k;
    }
    EXPECT_NEAR(cpu[k].vertex.roughness, gl[k].vertex.roughness, 1e-6f) << "VPL " << k;
    EXPECT_EQ(cpu[k].vertex.model, gl[k].vertex.model) << "VPL " << k;
    EXPECT_EQ(cpu[k].incoming.w, 0.0f) << "VPL " << k;
    EXPECT_NEAR(cpu[k].positionPath.w, gl[k].positionPath.w, tol) << "VPL " << k;
  }
}

TEST(CpuMatchesGlGLTest, VplsOfAPointLightOnTheCorner) {
  test::CornerJob s(16);
  s.job.settings.indirect.rsm_resolution = 16;
  expectSameVpls(s.job);
}

TEST(CpuMatchesGlGLTest, GlossyVplsOfAPointLightOnTheCorner) {
  test::CornerJob s = test::glossyCorner(16);
  s.job.settings.indirect.rsm_resolution = 16;
  expectSameVpls(s.job);
}

TEST(CpuMatchesGlGLTest, VplsOfASpotOnThePlane) {
  test::PlaneJob s;
  s.job.light.type = capture::Light::Type::Spot;
  s.job.light.direction_world = glm::normalize(glm::vec3(0.1f, 0.0f, -1.0f));
  s.job.light.cone_half_angle_deg = 30.0f;
  s.job.light.cone_falloff_deg = 10.0f;
  s.job.settings.indirect.rsm_resolution = 24;
  expectSameVpls(s.job);
}

}  // namespace
}  // namespace tofsim::cpu
