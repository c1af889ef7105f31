// The VPLs' light scattered once by the medium into the camera rays (issue
// 42, item 4; core/physics/medium_vpl_scattering.md), through each backend's
// gather alone (ir::IrBackend: prepareSurfaces, setVpls, gatherIndirect,
// readSegment): hand-made VPLs (a Lambertian surface VPL, medium VPLs with an
// isotropic and a Henyey-Greenstein phase function) beside a camera ray that
// sees no surface, each bin of the indirect volume against the integral
//   sigma_s p(cos) I_vpl(u) / (r^2 + R^2) exp(-sigma_t (r + s)) ds
// over the bin's interval of s (path: the VPL's + r + s), computed here in
// double by dense Simpson rules, R = 1 / sqrt(render.indirect.geometry_clamp);
// the VPL's path shifts its light by whole bins; GL against CPU.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "support/AnalyticScenes.h"
#include "support/BackendScene.h"
#include "support/Simpson.h"
#include "support/TestBackends.h"
#include "tofsim/ir/MediumVpl.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::unique_ptr<ir::IrBackend> makeBackend(test::TestBackend backend) {
  if (backend == test::TestBackend::Cpu) {
    return std::make_unique<cpu::CpuBackend>(cpu::CpuBackendOptions{2, true});
  }
  return std::make_unique<GlBackend>(test::glTestContext());
}

using test::simpson;

// The s in [lo, hi] where the increasing path(s) reaches q (bisection).
double solve(const std::function<double(double)>& path, double q, double lo, double hi) {
  if (q <= path(lo)) return lo;
  if (q >= path(hi)) return hi;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (path(mid) < q ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// One pixel looking along -z from the origin with a 1 degree field of view
// through a scattering medium; the only surface is a small quad behind the
// camera (the ray sees none). The light source is dark: the volume holds
// the VPLs' light only.
struct VplMediumScene {
  scene::Scene scene;
  capture::RenderJob job;
  VplMediumScene() {
    test::addQuad(scene, glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0, 0, -1), 0.2f, glm::vec3(0.5f));
    job.scene = &scene;
    job.camera().position_world = glm::vec3(0.0f);
    job.camera().look_at_world = glm::vec3(0.0f, 0.0f, -1.0f);
    job.camera().fov_y_deg = 1.0f;
    job.camera().width = job.camera().height = 1;
    job.light.position_world = glm::vec3(0.0f, 0.0f, 1.0f);
    job.light.intensity_W_per_sr = glm::vec3(0.0f);
    job.settings.indirect.enabled = true;
    job.settings.indirect.visibility = capture::Visibility::Exact;
    job.settings.indirect.geometry_term_clamp_per_m2 = 400.0;  // R = 5 cm
    job.settings.pixel_footprint = false;
    job.settings.medium.sigma_a_per_m = glm::vec3(0.05f, 0.1f, 0.0f);
    job.settings.medium.sigma_s_per_m = glm::vec3(0.2f, 0.1f, 0.05f);
    job.settings.time = TimeAxis{0.0, 0.05 / kSpeedOfLight_m_per_s, 160};
  }
};

// The indirect volume (bins x rgb) of `vpls` alone.
std::vector<float> gatherVpls(ir::IrBackend& backend, const VplMediumScene& s,
                              const std::vector<ir::Vpl>& vpls) {
  const test::BackendScene prepared(backend, *s.job.scene);
  backend.prepareSurfaces(s.job);
  backend.setVpls(vpls);
  backend.allocate(1, vpls.size());
  backend.buildVisibility(0, vpls.size());
  backend.beginSegment(0, 1);
  backend.gatherIndirect(0, vpls.size());
  const int bins = s.job.settings.time.bins;
  std::vector<float> direct(bins * capture::kChannels), indirect(direct.size());
  AxisLoss offAxis;
  backend.readSegment(direct.data(), indirect.data(), offAxis);
  return indirect;
}

// A surface VPL 12 cm beside the ray at 1.5 m, facing it
// (Lambertian: its flux is the cosine emitter's intensity, W/sr).
ir::Vpl surfaceVpl() {
  ir::Vpl v;
  v.positionPath = glm::vec4(0.12f, 0.03f, -1.5f, 0.4f);
  // Facing every point of the ray: no horizon on it (a horizon's kink in the
  // integrand is resolved to the nodes' spacing only, as a spot's rim).
  v.normal = glm::vec4(glm::normalize(glm::vec3(-1.0f, -0.2f, 0.0f)), 0.0f);
  v.flux = glm::vec4(0.8f, 0.5f, 0.3f, 0.0f);
  return v;
}

// A medium VPL at the same place whose light came from +x, tilted up.
ir::Vpl mediumVplAt(const VplMediumScene& s) {
  const capture::Medium& medium = s.job.settings.medium;
  return ir::mediumVpl(glm::vec3(0.12f, 0.03f, -1.5f), 0.4f, glm::vec3(0.8f, 0.5f, 0.3f),
                       glm::normalize(glm::vec3(1.0f, 0.3f, -0.2f)), medium, 0.0f);
}

// The VPL's intensity toward unit u (W/sr per channel), in double.
glm::dvec3 expectedIntensity(const ir::Vpl& v, const capture::Medium& medium, glm::dvec3 u) {
  const glm::dvec3 flux(v.flux);
  if (!ir::isMediumVpl(v)) return flux * std::max(glm::dot(glm::dvec3(v.normal), u), 0.0);
  const double cosTheta = glm::dot(-glm::dvec3(v.incoming), u), g = medium.g;
  const double phase = medium.phase == physics::PHASE_HENYEY_GREENSTEIN
                           ? (1 - g * g) / (4 * kPi * std::pow(1 + g * g - 2 * g * cosTheta, 1.5))
                           : 1.0 / (4 * kPi);
  return flux * glm::dvec3(medium.albedo()) * phase;
}

// Each bin's light of VPL `v` along the ray, in double.
std::vector<glm::dvec3> expectedBins(const VplMediumScene& s, const ir::Vpl& v) {
  const capture::Medium& medium = s.job.settings.medium;
  const glm::dvec3 at(v.positionPath);
  const double radius2 = 1.0 / s.job.settings.indirect.geometry_term_clamp_per_m2;
  const auto r = [&](double t) { return glm::length(glm::dvec3(0.0, 0.0, -t) - at); };
  const auto path = [&](double t) { return v.positionPath.w + r(t) + t; };
  const TimeAxis& axis = s.job.settings.time;
  std::vector<glm::dvec3> bins(axis.bins, glm::dvec3(0.0));
  for (int c = 0; c < 3; ++c) {
    const double sigmaT = medium.sigmaT()[c];
    const auto f = [&](double t) {
      const glm::dvec3 u = (glm::dvec3(0.0, 0.0, -t) - at) / r(t);  // the VPL's light's travel
      const double cosTheta = u.z;                                  // toward the camera (+z)
      const double g = medium.g;
      const double p = medium.phase == physics::PHASE_HENYEY_GREENSTEIN
                           ? (1 - g * g) / (4 * kPi * std::pow(1 + g * g - 2 * g * cosTheta, 1.5))
                           : 1.0 / (4 * kPi);
      return medium.sigma_s_per_m[c] * p * expectedIntensity(v, medium, u)[c] *
             std::exp(-sigmaT * (r(t) + t)) / (r(t) * r(t) + radius2);
    };
    for (int k = 0; k < axis.bins; ++k) {
      const double lo = axis.start_m() + k * axis.bin_width_m(), hi = lo + axis.bin_width_m();
      const double s0 = solve(path, lo, 0.0, 60.0), s1 = solve(path, hi, 0.0, 60.0);
      bins[k][c] = simpson(f, s0, s1, 400);
    }
  }
  return bins;
}

// Every bin within 5e-4 of itself (plus 1e-6 of the peak; measured: 6e-5 at
// most), and at least
// `tail` (bin, channel)s above 1e-4 of the peak compared.
void expectBins(const std::vector<float>& got, const std::vector<glm::dvec3>& expected,
                int tail) {
  double peak = 0.0;
  for (const glm::dvec3& e : expected) peak = std::max({peak, e.x, e.y, e.z});
  ASSERT_GT(peak, 0.0);
  int lit = 0;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    for (int c = 0; c < 3; ++c) {
      const double e = expected[k][c];
      EXPECT_NEAR(got[k * 3 + c], e, 5e-4 * e + 1e-6 * peak) << "bin " << k << " channel " << c;
      lit += e > 1e-4 * peak;
    }
  }
  EXPECT_GE(lit, tail);
}

class MediumVplGLTest : public test::BackendTest {};

TEST_P(MediumVplGLTest, SurfaceVplLightsTheRayAsTheDenseIntegral) {
  VplMediumScene s;
  const ir::Vpl v = surfaceVpl();
  const auto backend = makeBackend(GetParam());
  expectBins(gatherVpls(*backend, s, {v}), expectedBins(s, v), 150);
}

TEST_P(MediumVplGLTest, IsotropicMediumVplLightsTheRayAsTheDenseIntegral) {
  VplMediumScene s;
  const ir::Vpl v = mediumVplAt(s);
  const auto backend = makeBackend(GetParam());
  expectBins(gatherVpls(*backend, s, {v}), expectedBins(s, v), 180);
}

TEST_P(MediumVplGLTest, HenyeyGreensteinMediumVplLightsTheRayAsTheDenseIntegral) {
  VplMediumScene s;
  s.job.settings.medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
  s.job.settings.medium.g = 0.6f;
  const ir::Vpl v = mediumVplAt(s);
  const auto backend = makeBackend(GetParam());
  expectBins(gatherVpls(*backend, s, {v}), expectedBins(s, v), 50);
}

// The VPL's own path delays its light: 0.5 m more (10 bins) moves every bin
// by 10, the light itself unchanged.
TEST_P(MediumVplGLTest, TheVplPathShiftsItsLightByWholeBins) {
  VplMediumScene s;
  ir::Vpl v = surfaceVpl();
  const auto backend = makeBackend(GetParam());
  const std::vector<float> early = gatherVpls(*backend, s, {v});
  v.positionPath.w += 0.5f;
  const std::vector<float> late = gatherVpls(*backend, s, {v});
  float peak = 0.0f;
  for (float e : early) peak = std::max(peak, e);
  ASSERT_GT(peak, 0.0f);
  for (int k = 0; k < 10; ++k) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(late[k * 3 + c], 0.0f) << "bin " << k;
  }
  for (int k = 10; k < s.job.settings.time.bins; ++k) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(late[k * 3 + c], early[(k - 10) * 3 + c], 1e-4f * peak) << "bin " << k;
    }
  }
}

TOFSIM_ON_BOTH_BACKENDS(MediumVplGLTest);

// GL against CPU: 4 x 4 pixels of 2 x 2 samples, a plane that ends some of
// the rays (and takes the VPLs' light itself), a glTF surface VPL and a
// Henyey-Greenstein medium VPL on a ray's path, exact visibility: each
// pixel's bins agree to 2e-3 of its largest.
TEST(MediumVplAgreementGLTest, GlMatchesCpu) {
  VplMediumScene s;
  test::addQuad(s.scene, glm::vec3(0.15f, 0.0f, -2.5f), glm::vec3(0, 0, 1), 0.3f, glm::vec3(0.6f));
  s.job.camera().width = s.job.camera().height = 4;
  s.job.camera().fov_y_deg = 12.0f;
  s.job.settings.pixel_samples = 2;
  s.job.settings.medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
  s.job.settings.medium.g = 0.7f;
  ir::Vpl medium = mediumVplAt(s);
  medium.positionPath = glm::vec4(-0.05f, 0.02f, -1.2f, 0.3f);  // on a pixel's rays
  // A glTF render and a glTF surface VPL (the glTF gathers' VPL records).
  s.job.settings.materials = capture::MaterialModel::Gltf;
  ir::Vpl surface = surfaceVpl();
  surface.incoming = glm::vec4(glm::normalize(glm::vec3(-0.3f, 0.2f, 1.0f)), 0.0f);
  surface.vertex = physics::scatterVertex(physics::VERTEX_GLTF, {0.9f, 0.6f, 0.3f}, 0.0f, 0.5f);
  const std::vector<ir::Vpl> vpls = {surface, medium};
  const auto gl = makeBackend(test::TestBackend::Gl), cpu = makeBackend(test::TestBackend::Cpu);
  const std::size_t pixels = 16;
  const int bins = s.job.settings.time.bins;
  std::vector<std::vector<float>> out;
  for (ir::IrBackend* backend : {gl.get(), cpu.get()}) {
    const test::BackendScene prepared(*backend, *s.job.scene);
    backend->prepareSurfaces(s.job);
    backend->setVpls(vpls);
    backend->allocate(pixels, vpls.size());
    backend->buildVisibility(0, vpls.size());
    backend->beginSegment(0, pixels);
    backend->gatherIndirect(0, vpls.size());
    std::vector<float> direct(pixels * bins * 3), indirect(direct.size());
    AxisLoss offAxis;
    backend->readSegment(direct.data(), indirect.data(), offAxis);
    out.push_back(indirect);
  }
  int lit = 0;
  for (std::size_t p = 0; p < pixels; ++p) {
    for (int c = 0; c < 3; ++c) {
      float peak = 0.0f;
      for (int k = 0; k < bins; ++k) peak = std::max(peak, out[1][(p * bins + k) * 3 + c]);
      lit += peak > 0.0f;
      for (int k = 0; k < bins; ++k) {
        const std::size_t i = (p * bins + k) * 3 + c;
        EXPECT_NEAR(out[0][i], out[1][i], 2e-3f * peak) << "pixel " << p << " bin " << k;
      }
    }
  }
  EXPECT_EQ(lit, 3 * 16);
}

}  // namespace
}  // namespace tofsim::render
