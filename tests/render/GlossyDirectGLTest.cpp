// Closed form of the glTF BRDF in the direct light (render.materials: gltf):
// a glossy plane (a dielectric, a metal, a half-metal; roughness 0.3, 0.6,
// 1.0) under a point light away from the camera, so the highlight is in view.
// Every pixel's steady radiance equals f(l, v) I cos_l / r^2 with f evaluated
// here from the formula of issue 16 (in double, not the shared header), on
// both IR backends and in the reference path tracer (one ray per pixel
// centre). The Lambertian default keeps its bytes (the shipped Cornell box).

#include <gtest/gtest.h>

#include <cmath>

#include "reference/RenderReference.h"
#include "support/ClosedForm.h"
#include "support/ExpectedGltfBrdf.h"
#include "support/TestBackends.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::render {
namespace {

using glm::dvec3;

constexpr double kPi = 3.14159265358979323846;

struct Glossy {
  float metallic;
  float roughness;
};

// The plane job with its light moved off the camera: the mirror point of the
// light, (0.48, 0.12, 0), lies inside the view.
struct GlossyPlane : test::PlaneJob {
  explicit GlossyPlane(const Glossy& g) {
    scene.materials.at(0).metallic = g.metallic;
    scene.materials.at(0).roughness = g.roughness;
    job.light.position_world = {0.8f, 0.2f, 1.0f};
    job.settings.materials = capture::MaterialModel::Gltf;
    job.settings.pixel_footprint = false;
    job.settings.indirect.enabled = false;
    job.settings.time = TimeAxis{0.0, 0.01 / kSpeedOfLight_m_per_s, 1000};
  }
};

const Glossy kCases[] = {{0.0f, 0.3f}, {0.0f, 0.6f}, {0.0f, 1.0f}, {1.0f, 0.3f}, {1.0f, 0.6f},
                         {1.0f, 1.0f}, {0.5f, 0.3f}, {0.5f, 0.6f}, {0.5f, 1.0f}};

// Every pixel of `steady` against the closed form, within 1%; returns the
// largest ratio of a pixel's radiance to the Lambertian one (the highlight)
// and counts the pixels off by more than 1% in `failures`.
double expectClosedForm(const GlossyPlane& s, const Glossy& g, const Image& steady, int& failures) {
  const dvec3 light(s.job.light.position_world), eye(s.job.camera().position_world);
  const dvec3 base(s.scene.materials[0].albedo), intensity(s.job.light.intensity_W_per_sr);
  const dvec3 n(0, 0, 1);
  double peak = 0.0;
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const dvec3 p = test::hitOnPlane(s.job.camera(), x, y);
      const double r = glm::length(light - p);
      const dvec3 l = (light - p) / r, v = glm::normalize(eye - p);
      const dvec3 f = test::expectedGltfBrdf(n, l, v, base, g.metallic, g.roughness);
      for (int c = 0; c < 3; ++c) {
        const double expected = f[c] * intensity[c] * l.z / (r * r);
        if (std::abs(steady.at(y, x, c) - expected) <= 0.01 * expected) continue;
        if (++failures <= 5) {
          ADD_FAILURE() << "pixel " << x << "," << y << " channel " << c << ": "
                        << steady.at(y, x, c) << " vs " << expected << " (metallic " << g.metallic
                        << ", roughness " << g.roughness << ")";
        }
      }
      peak = std::max(peak, f.g / (base.g / kPi));
    }
  }
  return peak;
}

class GlossyDirectGLTest : public test::BackendTest {};

TEST_P(GlossyDirectGLTest, SteadyRadianceIsTheBrdfTimesIntensityCosineOverDistanceSquared) {
  for (const Glossy& g : kCases) {
    GlossyPlane s(g);
    capture::VolumeCollector out(s.job.camera().width, s.job.camera().height, s.job.settings.time,
                                 3);
    renderer()->render(s.job, out);
    int failures = 0;
    const double peak = expectClosedForm(s, g, steadyImage(out.direct), failures);
    EXPECT_EQ(failures, 0) << "metallic " << g.metallic << ", roughness " << g.roughness;
    // The highlight is in view: the smoothest metal's peak is far above Lambertian.
    if (g.metallic == 1.0f && g.roughness == 0.3f) {
      EXPECT_GT(peak, 2.0);
    }
  }
}

TOFSIM_ON_BOTH_BACKENDS(GlossyDirectGLTest);

TEST(GlossyDirectReferenceTest, PixelCentreRadianceIsTheClosedForm) {
  reference::ReferenceSettings settings;
  settings.bounces = 1;
  settings.samples_per_pixel = 1;
  settings.pixel_filter = reference::PixelFilter::Point;
  settings.threads = 2;
  for (const Glossy& g : kCases) {
    GlossyPlane s(g);
    const capture::VolumeCollector out = test::renderReference(s.job, settings);
    int failures = 0;
    expectClosedForm(s, g, steadyImage(out.direct), failures);
    EXPECT_EQ(failures, 0) << "metallic " << g.metallic << ", roughness " << g.roughness;
  }
}

// The default (render.materials: lambertian) is the renderer of before: the
// glTF path leaves it alone, so the shipped Cornell box (metallic 0,
// roughness 1: not Lambertian under the BRDF) keeps its bytes, while gltf
// does change it, direct and indirect.
TEST_P(GlossyDirectGLTest, CornellBoxKeepsItsBytesUnderTheLambertianDefault) {
  const scene::Scene box =
      scene::loadGltf(std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/cornell_box.gltf");
  capture::RenderJob job = test::cornellBoxJob(box, 24, 200, 0.02);
  job.settings.indirect.rsm_resolution = 4;
  job.settings.indirect.points_per_vpl = 100;
  job.settings.shadow_map_resolution = 128;
  ASSERT_EQ(job.settings.materials, capture::MaterialModel::Lambertian);
  const auto render = [&](const capture::RenderJob& j) {
    capture::VolumeCollector out(j.camera().width, j.camera().height, j.settings.time, 3);
    renderer()->render(j, out);
    return out;
  };
  const capture::VolumeCollector lambertian = render(job);
  capture::RenderJob gltf = job;
  gltf.settings.materials = capture::MaterialModel::Gltf;
  const capture::VolumeCollector glossy = render(gltf);
  // gltf changes both: the direct light and (glossy VPLs, tests/render/GlossyVplGLTest.cpp) the
  // indirect.
  EXPECT_NE(lambertian.indirect.values(), glossy.indirect.values());
  EXPECT_NE(lambertian.direct.values(), glossy.direct.values());
}

}  // namespace
}  // namespace tofsim::render
