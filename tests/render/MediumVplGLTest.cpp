// The VPLs' light scattered once by the medium into the camera rays (issue
// 42, item 4; core/physics/medium_vpl_scattering.md), through each backend's
// gather alone (ir::IrBackend: prepareSurfaces, setVpls, gatherIndirect,
// readSegment): hand-made VPLs (a Lambertian surface VPL, medium VPLs with an
// isotropic and a Henyey-Greenstein phase function) beside a camera ray that
// sees no surface, against the integral per bin
//   sigma_s p(cos) I_vpl(u) / (r^2 + R^2) exp(-sigma_t (r + s)) ds
// over the bin's interval of s (path: the VPL's + r + s), computed here in
// double by dense Simpson rules, R = 1 / sqrt(render.indirect.geometry_clamp).
// The pass samples each (ray, VPL) pair (two points of the angle at one
// offset u, each in the bin of its path; a roulette above
// MEDIUM_VPL_RAY_PAIRS VPLs): the pair's mean over u is the dense integral;
// a backend's sum over many copies of the VPL is within a few standard
// deviations of it (the pair's variance over u, computed here); the VPL's
// path shifts its light by whole bins; GL against CPU.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "CpuMediumRays.h"
#include "support/AnalyticScenes.h"
#include "support/BackendScene.h"
#include "support/Simpson.h"
#include "support/TestBackends.h"
#include "tofsim/ir/MediumRayVpls.h"
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

// One (ray, VPL) pair's sampled light per bin as a function of its offset u
// (the CPU pass's addSampledMediumRayLight, weight 1, the VPL's intensity
// this file's double one), over u in [0, 1) by a grid of kOffsets midpoints:
// per bin its mean and mean square, the same of the cumulative light (bins
// up to k), its largest light and the share of u that lights it. A bin's
// light is a step function of u where one of the two points crosses one of
// its ends: the grid's mean is off by at most half a step per crossing,
// 4 x (its largest light) / (2 kOffsets).
constexpr int kOffsets = 1 << 16;
struct PairMoments {
  std::vector<glm::dvec3> mean, meanSquare, cumulative, cumulativeSquare, largest;
  std::vector<double> lit;
};

PairMoments pairMoments(const VplMediumScene& s, const ir::Vpl& v) {
  const capture::RenderSettings& set = s.job.settings;
  const int bins = set.time.bins;
  const cpu::MediumAxis axis{static_cast<float>(set.time.start_m()) - v.positionPath.w,
                             static_cast<float>(set.time.bin_width_m()),
                             static_cast<float>(set.time.index_of_refraction), bins, false};
  const physics::MediumRay ray = physics::mediumEmitterRay(
      glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(v.positionPath),
      physics::mediumVplRadius(static_cast<float>(set.indirect.geometry_term_clamp_per_m2)),
      physics::MEDIUM_UNBOUNDED, 0.0f);
  const auto nodeLight = [&](const physics::MediumNode& n) {
    const glm::vec3 intensity(expectedIntensity(v, set.medium, glm::dvec3(n.fromLight)));
    return physics::mediumNodeRadiance(n, set.medium.sigma_s_per_m, set.medium.sigmaT(),
                                       set.medium.phase, set.medium.g, intensity, 1.0f);
  };
  const std::vector<glm::dvec3> zero(bins, glm::dvec3(0.0));
  PairMoments m{zero, zero, zero, zero, zero, std::vector<double>(bins, 0.0)};
  std::vector<float> light(static_cast<std::size_t>(bins) * 3);
  for (int i = 0; i < kOffsets; ++i) {
    std::fill(light.begin(), light.end(), 0.0f);
    physics::OffAxisSums lost;
    cpu::addSampledMediumRayLight(axis, ray, 1.0f, (i + 0.5f) / kOffsets, light.data(), lost,
                                  nodeLight);
    glm::dvec3 sum(0.0);
    for (int k = 0; k < bins; ++k) {
      const glm::dvec3 e(light[k * 3], light[k * 3 + 1], light[k * 3 + 2]);
      sum += e;
      m.mean[k] += e / double(kOffsets);
      m.meanSquare[k] += e * e / double(kOffsets);
      m.cumulative[k] += sum / double(kOffsets);
      m.cumulativeSquare[k] += sum * sum / double(kOffsets);
      m.largest[k] = glm::max(m.largest[k], e);
      m.lit[k] += e != glm::dvec3(0.0) ? 1.0 / kOffsets : 0.0;
    }
  }
  return m;
}

double peakOf(const std::vector<glm::dvec3>& bins) {
  double peak = 0.0;
  for (const glm::dvec3& e : bins) peak = std::max({peak, e.x, e.y, e.z});
  return peak;
}

// The three VPLs of the tests below, in their scenes.
struct VplCase {
  const char* name;
  VplMediumScene scene;
  ir::Vpl vpl;
  int tail;  ///< (bin, channel)s above 1e-4 of the peak at least
};

std::vector<VplCase> vplCases() {
  std::vector<VplCase> cases(3);
  cases[0].name = "surface";
  cases[0].vpl = surfaceVpl();
  cases[0].tail = 150;
  cases[1].name = "isotropic medium";
  cases[1].vpl = mediumVplAt(cases[1].scene);
  cases[1].tail = 180;
  cases[2].name = "Henyey-Greenstein medium";
  cases[2].scene.job.settings.medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
  cases[2].scene.job.settings.medium.g = 0.6f;
  cases[2].vpl = mediumVplAt(cases[2].scene);
  cases[2].tail = 50;
  return cases;
}

// The sampled pair is unbiased: its mean over the offset is each bin's
// dense integral, within the grid's error (PairMoments) plus 2e-4 of itself
// (float rounding) and 1e-6 of the peak. Fails with R = 1 mm (each case).
TEST(MediumVplSampledPairTest, ItsMeanOverTheOffsetIsTheDenseIntegral) {
  for (const VplCase& c : vplCases()) {
    const std::vector<glm::dvec3> expected = expectedBins(c.scene, c.vpl);
    const PairMoments m = pairMoments(c.scene, c.vpl);
    const double peak = peakOf(expected);
    ASSERT_GT(peak, 0.0);
    int lit = 0;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      for (int ch = 0; ch < 3; ++ch) {
        const double e = expected[k][ch];
        EXPECT_NEAR(m.mean[k][ch], e, 2.0 * m.largest[k][ch] / kOffsets + 2e-4 * e + 1e-6 * peak)
            << c.name << " bin " << k << " channel " << ch;
        lit += e > 1e-4 * peak;
      }
    }
    EXPECT_GE(lit, c.tail) << c.name;
  }
}

// A backend's light of `copies` copies of `v` (each of 1 / copies of its
// flux: each pair its own draws) against the dense integral, within 5
// standard deviations of the copies' mean (a kept pair's light over u,
// weighed 1 / q: variance (E[c^2] / q - E[c]^2) / copies) plus the grid's
// error, 2e-4 of itself and 1e-6 of the peak: the cumulative light up to
// every bin (each point counts in every sum from its bin on: the whole
// distribution along the ray), and each bin that at least 25 kept copies
// light on average (below, a bin's few points are not near normal; the
// 512 points spread over ~160 bins leave `minBins` such, near the VPL).
// With at most MEDIUM_VPL_RAY_PAIRS copies every pair is kept (q = 1);
// above, q is the roulette's for this ray.
void expectCopiesAsTheIntegral(test::TestBackend backend, const VplCase& c, int copies,
                               int minBins) {
  ir::Vpl v = c.vpl;
  v.flux = glm::vec4(glm::vec3(v.flux) / float(copies), v.flux.w);
  const std::vector<ir::Vpl> vpls(copies, v);
  const glm::vec3 extent = c.scene.scene.bounds().max - c.scene.scene.bounds().min;
  const float threshold = ir::mediumRayThreshold(vpls, std::max(glm::length(extent), 1e-6f));
  const physics::MediumRay ray = physics::mediumEmitterRay(
      glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(v.positionPath),
      physics::mediumVplRadius(
          static_cast<float>(c.scene.job.settings.indirect.geometry_term_clamp_per_m2)),
      physics::MEDIUM_UNBOUNDED, 0.0f);
  const double q = physics::mediumRayVplSurvival(
      physics::mediumRayVplEstimate(
          ray, physics::mediumRayVplImportance(glm::vec3(v.flux), glm::vec3(v.normal))),
      threshold);
  EXPECT_EQ(q == 1.0, copies <= physics::MEDIUM_VPL_RAY_PAIRS) << "q " << q;
  const auto b = makeBackend(backend);
  const std::vector<float> got = gatherVpls(*b, c.scene, vpls);
  const std::vector<glm::dvec3> expected = expectedBins(c.scene, c.vpl);
  const PairMoments m = pairMoments(c.scene, c.vpl);
  const double peak = peakOf(expected);
  const auto allowance = [&](double e, double mean, double meanSquare, double largest) {
    const double variance = std::max(meanSquare / q - mean * mean, 0.0) / copies;
    return 5.0 * std::sqrt(variance) + 2.0 * largest / kOffsets + 2e-4 * e + 1e-6 * peak;
  };
  glm::dvec3 expectedSum(0.0), gotSum(0.0), largestPoint(0.0);
  for (const glm::dvec3& e : m.largest) largestPoint = glm::max(largestPoint, e);
  int compared = 0;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const bool dense = m.lit[k] * q * copies >= 25.0;
    compared += dense;
    for (int ch = 0; ch < 3; ++ch) {
      const double e = expected[k][ch];
      expectedSum[ch] += e;
      gotSum[ch] += got[k * 3 + ch];
      EXPECT_NEAR(gotSum[ch], expectedSum[ch],
                  allowance(expectedSum[ch], m.cumulative[k][ch], m.cumulativeSquare[k][ch],
                            2.0 * largestPoint[ch]))  // the sum steps where a point leaves it
          << c.name << " up to bin " << k << " channel " << ch;
      if (!dense) continue;
      EXPECT_NEAR(got[k * 3 + ch], e,
                  allowance(e, m.mean[k][ch], m.meanSquare[k][ch], m.largest[k][ch]))
          << c.name << " bin " << k << " channel " << ch;
    }
  }
  EXPECT_GE(compared, minBins) << c.name;
}

class MediumVplGLTest : public test::BackendTest {};

TEST_P(MediumVplGLTest, SurfaceVplLightsTheRayAsTheDenseIntegral) {
  expectCopiesAsTheIntegral(GetParam(), vplCases()[0], 256, 4);
}

TEST_P(MediumVplGLTest, IsotropicMediumVplLightsTheRayAsTheDenseIntegral) {
  expectCopiesAsTheIntegral(GetParam(), vplCases()[1], 256, 4);
}

TEST_P(MediumVplGLTest, HenyeyGreensteinMediumVplLightsTheRayAsTheDenseIntegral) {
  expectCopiesAsTheIntegral(GetParam(), vplCases()[2], 256, 4);
}

// Above MEDIUM_VPL_RAY_PAIRS VPLs the roulette keeps a share of the pairs,
// weighed by its inverse: still the integral.
TEST_P(MediumVplGLTest, TheRouletteKeepsTheIntegral) {
  expectCopiesAsTheIntegral(GetParam(), vplCases()[1], 8192, 3);
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
