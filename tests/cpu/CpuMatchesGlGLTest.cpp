// The CPU backend against the GL one on the plane and the corner: the same
// G-buffer and VPLs (exactly in what is discrete: which pixels see a surface,
// how many VPLs, in which order; within float tolerance in the values), and
// volumes that agree. Needs a GL context (llvmpipe in CI).

#include <gtest/gtest.h>

#include <cmath>

#include "GpuScene.h"
#include "SurfaceImage.h"
#include "SurfaceMaps.h"
#include "Vpls.h"
#include "cpu/CpuRender.h"
#include "support/ClosedForm.h"
#include "support/GlTestContext.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/reference/RayScene.h"
#include "tofsim/render/TransientRenderer.h"

namespace tofsim::cpu {
namespace {

void viewBounds(const capture::RenderJob& job, glm::vec3& lo, glm::vec3& hi) {
  const scene::Bounds b = job.scene->bounds();
  lo = glm::min(glm::min(b.min, job.camera.position_world), job.light.position_world);
  hi = glm::max(glm::max(b.max, job.camera.position_world), job.light.position_world);
}

std::vector<float> download(const gl::Texture& t, std::size_t texels) {
  std::vector<float> v(texels * 4);
  t.download(GL_RGBA, GL_FLOAT, v.size() * sizeof(float), v.data());
  return v;
}

// Rasterized and ray-traced points on the same triangle differ by float
// rounding only: 1e-5 of the scene's size; normals and albedo to 1e-5.
void expectSameGBuffer(const capture::RenderJob& job) {
  test::glTestContext();
  render::GpuScene gpuScene(*job.scene);
  glm::vec3 lo, hi;
  viewBounds(job, lo, hi);
  render::SurfaceMaps gl(job.camera.width, job.camera.height);
  const glm::vec2 range = render::depthRange(lo, hi, job.camera.position_world);
  gl.render(gpuScene, job.camera.projection(range.x, range.y) * job.camera.view(),
            job.camera.position_world);
  const std::size_t pixels = static_cast<std::size_t>(job.camera.width) * job.camera.height;
  const auto position = download(gl.position, pixels);
  const auto normal = download(gl.normal, pixels);
  const auto albedo = download(gl.albedo, pixels);
  const reference::RayScene rays(*job.scene, 1);
  const SurfaceImage cpu = traceSurfaces(rays, job.camera, 2);
  const float tol = 1e-5f * glm::length(hi - lo);
  std::size_t surfaces = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    ASSERT_EQ(cpu.position[i].w, position[4 * i + 3]) << "pixel " << i;
    if (cpu.position[i].w == 0.0f) continue;
    ++surfaces;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(cpu.position[i][k], position[4 * i + k], tol) << "pixel " << i;
      EXPECT_NEAR(cpu.normal[i][k], normal[4 * i + k], 1e-5f) << "pixel " << i;
      EXPECT_NEAR(cpu.albedo[i][k], albedo[4 * i + k], 1e-5f) << "pixel " << i;
    }
  }
  EXPECT_GT(surfaces, pixels / 2);
}

TEST(CpuMatchesGlGLTest, GBufferOnThePlane) { expectSameGBuffer(test::PlaneJob().job); }
TEST(CpuMatchesGlGLTest, GBufferOnTheCorner) { expectSameGBuffer(test::CornerJob(32).job); }

// Same count and order; positions and paths to 1e-5 of the scene, flux to
// 2e-4 relative: both evaluate the same texel formula, but in a spot's falloff
// the profile's slope amplifies the rounding of the hit point (measured 6e-5).
void expectSameVpls(const capture::RenderJob& job) {
  test::glTestContext();
  render::GpuScene gpuScene(*job.scene);
  glm::vec3 lo, hi;
  viewBounds(job, lo, hi);
  const capture::IndirectSettings& s = job.settings.indirect;
  const auto gl = render::generateVpls(gpuScene, job.light, s.rsm_resolution,
                                       job.settings.index_of_refraction, lo, hi);
  CpuBackend backend({2, true});
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
    }
    EXPECT_NEAR(cpu[k].positionPath.w, gl[k].positionPath.w, tol) << "VPL " << k;
  }
}

TEST(CpuMatchesGlGLTest, VplsOfAPointLightOnTheCorner) {
  test::CornerJob s(16);
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

// Whole volumes: the steady images of the direct and indirect components.
void expectSameVolumes(capture::Visibility visibility, double tolerance) {
  test::CornerJob s(24);
  s.job.settings.indirect.visibility = visibility;
  s.job.settings.indirect.rsm_resolution = 16;
  s.job.settings.indirect.points_per_vpl = 500;
  s.job.settings.shadow_map_resolution = 512;
  capture::VolumeCollector gl(s.job.camera.width, s.job.camera.height, s.job.settings.time, 3);
  render::TransientRenderer(test::glTestContext()).render(s.job, gl);
  const test::CpuRender cpu = test::renderOnCpu(s.job, {2, true});
  EXPECT_LT(test::relativeL1(steadyImage(cpu.volume.direct), steadyImage(gl.direct)), tolerance);
  EXPECT_LT(test::relativeL1(steadyImage(cpu.volume.indirect), steadyImage(gl.indirect)),
            tolerance);
}

TEST(CpuMatchesGlGLTest, CornerVolumesWithExactVisibility) {
  expectSameVolumes(capture::Visibility::Exact, 1e-3);
}
TEST(CpuMatchesGlGLTest, CornerVolumesWithIsms) {
  expectSameVolumes(capture::Visibility::Ism, 1e-3);
}

}  // namespace
}  // namespace tofsim::cpu
