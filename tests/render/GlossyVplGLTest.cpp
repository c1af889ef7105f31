// Glossy VPLs (render.materials: gltf) through each backend's gather alone
// (ir::IrBackend: prepareSurfaces, setVpls, gatherIndirect, readSegment):
// one VPL with a recorded incoming direction and material lights a glossy
// plane, and every pixel's steady indirect radiance equals
//   f_x(to the VPL, to the camera) f_vpl(incoming, to x) Phi cos_vpl cos_x / d^2
// with both BRDFs evaluated here in double (support/ExpectedGltfBrdf.h),
// within 1 %, on the GL and the CPU backend; with vpl_brdf_clamp the VPL's
// value is min(f_vpl, clamp) per channel. And the RSM's glossy VPLs: their
// incoming direction points at the light, their flux is the power the
// Lambertian VPL's albedo / pi divided out, their material is the surface's.

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "support/BackendScene.h"
#include "support/ClosedForm.h"
#include "support/ExpectedGltfBrdf.h"
#include "support/TestBackends.h"
#include "support/TestJobs.h"

namespace tofsim::render {
namespace {

using glm::dvec3;

std::unique_ptr<ir::IrBackend> makeBackend(test::TestBackend backend) {
  if (backend == test::TestBackend::Cpu) {
    return std::make_unique<cpu::CpuBackend>(cpu::CpuBackendOptions{2, true});
  }
  return std::make_unique<GlBackend>(test::glTestContext());
}

struct Case {
  float planeMetallic, planeRoughness;
  float vplMetallic, vplRoughness;
  double clamp_per_sr;
};

const Case kCases[] = {{0.0f, 0.3f, 1.0f, 0.3f, 0.0},
                       {1.0f, 0.6f, 0.0f, 0.6f, 0.0},
                       {0.5f, 1.0f, 0.5f, 0.3f, 0.0},
                       {0.0f, 0.6f, 1.0f, 1.0f, 0.0},
                       {0.0f, 0.3f, 1.0f, 0.3f, 2.0}};

// The plane (PlaneJob) under one VPL above it whose mirror direction meets
// the plane inside the view, so the VPL's highlight is in the image.
struct OneVplPlane : test::PlaneJob {
  ir::Vpl vpl;
  explicit OneVplPlane(const Case& c) {
    scene.materials.at(0).metallic = c.planeMetallic;
    scene.materials.at(0).roughness = c.planeRoughness;
    job.settings.materials = capture::MaterialModel::Gltf;
    job.settings.pixel_footprint = false;
    job.settings.indirect.visibility = capture::Visibility::Exact;
    job.settings.indirect.geometry_term_clamp_per_m2 = 0.0;
    job.settings.indirect.vpl_brdf_clamp_per_sr = c.clamp_per_sr;
    job.settings.time = TimeAxis{0.0, 0.01 / kSpeedOfLight_m_per_s, 1000};
    const glm::vec3 p(-0.3f, 0.2f, 0.7f);
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 0.1f, -1.0f));
    const glm::vec3 mirror = glm::normalize(glm::vec3(0.25f, 0.05f, 0.0f) - p);
    const glm::vec3 incoming = 2.0f * glm::dot(n, mirror) * n - mirror;
    vpl.positionPath = glm::vec4(p, 1.0f);
    vpl.normal = glm::vec4(n, 0.0f);
    vpl.flux = glm::vec4(0.8f, 0.5f, 0.3f, 0.0f);  // the power it received, W
    vpl.incoming = glm::vec4(incoming, 0.0f);
    vpl.vertex = physics::scatterVertex(physics::VERTEX_GLTF, {0.9f, 0.6f, 0.3f}, c.vplMetallic,
                                        c.vplRoughness);
  }
};

// The steady indirect image (rgb per pixel, row-major) of the VPL alone.
std::vector<double> gatherOne(ir::IrBackend& backend, const OneVplPlane& s) {
  const auto pixels = static_cast<std::size_t>(s.job.camera().width) * s.job.camera().height;
  const test::BackendScene prepared(backend, *s.job.scene);
  backend.prepareSurfaces(s.job);
  backend.setVpls({s.vpl});
  backend.allocate(pixels, 1);
  backend.buildVisibility(0, 1);
  backend.beginSegment(0, pixels);
  backend.gatherIndirect(0, 1);
  const int bins = s.job.settings.time.bins;
  std::vector<float> direct(pixels * bins * capture::kChannels), indirect(direct.size());
  AxisLoss offAxis;
  backend.readSegment(direct.data(), indirect.data(), offAxis);
  std::vector<double> steady(pixels * 3, 0.0);
  for (std::size_t p = 0; p < pixels; ++p) {
    for (int t = 0; t < bins; ++t) {
      for (int c = 0; c < 3; ++c) steady[p * 3 + c] += indirect[(p * bins + t) * 3 + c];
    }
  }
  return steady;
}

class GlossyVplGLTest : public test::BackendTest {};

TEST_P(GlossyVplGLTest, OneVplOnAPlaneIsBothBrdfsTimesPowerAndGeometryTerm) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(testing::Message()
                 << "plane " << c.planeMetallic << "/" << c.planeRoughness << ", VPL "
                 << c.vplMetallic << "/" << c.vplRoughness << ", clamp " << c.clamp_per_sr);
    const OneVplPlane s(c);
    const auto backend = makeBackend(GetParam());
    const std::vector<double> steady = gatherOne(*backend, s);
    const dvec3 eye(s.job.camera().position_world), x0(s.vpl.positionPath), nVpl(s.vpl.normal);
    const dvec3 incoming(s.vpl.incoming), vplBase(glm::vec3(s.vpl.vertex.color)), power(s.vpl.flux);
    const dvec3 planeBase(s.scene.materials[0].albedo), n(0, 0, 1);
    int failures = 0;
    double peak = 0.0;
    for (int y = 0; y < s.job.camera().height; ++y) {
      for (int x = 0; x < s.job.camera().width; ++x) {
        const dvec3 p = test::hitOnPlane(s.job.camera(), x, y);
        const double dist = glm::length(p - x0);
        const dvec3 d = (p - x0) / dist;
        dvec3 fVpl =
            test::expectedGltfBrdf(nVpl, incoming, d, vplBase, c.vplMetallic, c.vplRoughness);
        peak = std::max(peak, fVpl.r / (vplBase.r / 3.14159265358979323846));
        if (c.clamp_per_sr > 0.0) fVpl = glm::min(fVpl, dvec3(c.clamp_per_sr));
        const dvec3 fX = test::expectedGltfBrdf(n, -d, glm::normalize(eye - p), planeBase,
                                                c.planeMetallic, c.planeRoughness);
        const double g = glm::dot(nVpl, d) * -d.z / (dist * dist);
        const std::size_t i = static_cast<std::size_t>(y) * s.job.camera().width + x;
        for (int k = 0; k < 3; ++k) {
          const double expected = fX[k] * fVpl[k] * power[k] * g;
          if (std::abs(steady[i * 3 + k] - expected) <= 0.01 * expected + 1e-12) continue;
          if (++failures <= 5) {
            ADD_FAILURE() << "pixel " << x << "," << y << " channel " << k << ": "
                          << steady[i * 3 + k] << " vs " << expected;
          }
        }
      }
    }
    EXPECT_EQ(failures, 0);
    // The VPL's highlight is in view: the smooth metal's lobe is far above Lambertian.
    if (c.vplMetallic == 1.0f && c.vplRoughness == 0.3f) {
      EXPECT_GT(peak, 10.0);
    }
  }
}

// RSM VPLs under gltf are the Lambertian ones with the albedo / pi taken off
// their flux, plus the direction to the light and the surface's material.
TEST_P(GlossyVplGLTest, RsmVplsRecordTheDirectionToTheLightAndTheMaterial) {
  test::PlaneJob s;
  s.scene.materials.at(0).metallic = 0.25f;
  s.scene.materials.at(0).roughness = 0.4f;
  s.job.light.position_world = {0.8f, 0.2f, 1.0f};
  s.job.settings.indirect.rsm_resolution = 12;
  const auto vplsOf = [&](capture::MaterialModel m) {
    capture::RenderJob job = s.job;
    job.settings.materials = m;
    const auto backend = makeBackend(GetParam());
    const test::BackendScene prepared(*backend, *job.scene);
    backend->prepareSurfaces(job);
    return backend->generateVpls(job);
  };
  const auto lambertian = vplsOf(capture::MaterialModel::Lambertian);
  const auto glossy = vplsOf(capture::MaterialModel::Gltf);
  ASSERT_EQ(glossy.size(), lambertian.size());
  ASSERT_GT(glossy.size(), 100u);
  const glm::vec3 albedo = s.scene.materials[0].albedo;
  for (std::size_t k = 0; k < glossy.size(); ++k) {
    const ir::Vpl& g = glossy[k];
    const glm::vec3 toLight =
        glm::normalize(s.job.light.position_world - glm::vec3(g.positionPath));
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(g.incoming[i], toLight[i], 1e-5f) << "VPL " << k;
      const float power = lambertian[k].flux[i] * 3.14159265f / albedo[i];
      EXPECT_NEAR(g.flux[i], power, 1e-5f * power) << "VPL " << k;
      EXPECT_EQ(g.vertex.color[i], albedo[i]) << "VPL " << k;
      EXPECT_EQ(g.positionPath[i], lambertian[k].positionPath[i]) << "VPL " << k;
    }
    EXPECT_EQ(g.vertex.color.w, 0.25f);
    EXPECT_EQ(g.vertex.roughness, 0.4f);
    EXPECT_EQ(g.vertex.model, physics::VERTEX_GLTF);
    EXPECT_EQ(lambertian[k].incoming, glm::vec4(0.0f));
    EXPECT_EQ(lambertian[k].vertex.model, physics::VERTEX_LAMBERTIAN);
  }
}

TOFSIM_ON_BOTH_BACKENDS(GlossyVplGLTest);

}  // namespace
}  // namespace tofsim::render
