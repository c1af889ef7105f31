// The CPU backend against the GL one: volumes that agree, both rendered
// through the one IR driver, on the plane, the corner and the Cornell box,
// with point pixels and pixel footprints, one sample per pixel and 2 x 2, and
// 2 x 2 at the edges only (render.adaptive_pixel_samples); in a medium and
// through a region; the stages before them: CpuMatchesGlStagesGLTest.cpp.
// Needs a GL context (llvmpipe in CI).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "support/BackendScene.h"
#include "support/ClosedForm.h"
#include "support/GlTestContext.h"
#include "support/RegionTank.h"
#include "support/TestJobs.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/ir/SampledPixels.h"
#include "tofsim/render/GlBackend.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/Error.h"

namespace tofsim::cpu {
namespace {

// Relative L1 of two volumes over every (pixel, bin, channel).
double transientRelativeL1(const TransientVolume& a, const TransientVolume& b) {
  double diff = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff += std::abs(double(a.data()[i]) - b.data()[i]);
    norm += std::abs(double(b.data()[i]));
  }
  return diff / norm;
}

struct Rendered {
  capture::VolumeCollector volume;
  capture::RenderResult result;
};

Rendered renderOn(std::unique_ptr<ir::IrBackend> backend, const capture::RenderJob& job) {
  Rendered out{
      capture::VolumeCollector(capture::imageWidth(job.imager), capture::imageHeight(job.imager),
                               job.settings.time, capture::kChannels),
      {}};
  out.result = ir::IrRenderer(std::move(backend)).render(job, out.volume);
  return out;
}

// Stated tolerances (float, relative L1 against the GL volume): steady images
// `steadyTol`; whole transient volumes `transientTol`, looser because a path
// within rounding of a bin edge may land in the neighbouring bin on the other
// backend. The VPL count is discrete and must match exactly.
void expectSameVolumes(const capture::RenderJob& job, double steadyTol, double transientTol) {
  const Rendered gl = renderOn(std::make_unique<render::GlBackend>(test::glTestContext()), job);
  const Rendered cpu = renderOn(std::make_unique<CpuBackend>(CpuBackendOptions{2, true}), job);
  EXPECT_EQ(cpu.result.vpls, gl.result.vpls);
  EXPECT_EQ(cpu.result.sampledPixels, gl.result.sampledPixels);
  const struct {
    const char* name;
    const TransientVolume& cpu;
    const TransientVolume& gl;
  } parts[] = {{"direct", cpu.volume.direct, gl.volume.direct},
               {"indirect", cpu.volume.indirect, gl.volume.indirect}};
  for (const auto& part : parts) {
    double glSum = 0.0, cpuSum = 0.0;
    for (std::size_t i = 0; i < part.gl.size(); ++i) {
      glSum += part.gl.data()[i];
      cpuSum += part.cpu.data()[i];
    }
    if (glSum == 0.0) {  // e.g. a plane lights nothing of itself
      EXPECT_EQ(cpuSum, 0.0) << part.name;
      continue;
    }
    const double steady = test::relativeL1(steadyImage(part.cpu), steadyImage(part.gl));
    const double transient = transientRelativeL1(part.cpu, part.gl);
    std::printf("%s: steady relative L1 %.2e, transient %.2e\n", part.name, steady, transient);
    EXPECT_LT(steady, steadyTol) << part.name;
    EXPECT_LT(transient, transientTol) << part.name;
  }
}

// How a pixel is sampled: render.pixel_footprint and render.pixel_samples.
struct PixelModel {
  bool footprint;
  int32_t samples;
  const char* name;
};
constexpr PixelModel kPixelModels[] = {{false, 1, "point pixels"},
                                       {true, 1, "footprints"},
                                       {false, 2, "point pixels, 2 x 2 samples"},
                                       {true, 2, "footprints, 2 x 2 samples"}};

// expectSameVolumes under each pixel model. Point pixels put a whole
// contribution in one bin, so a path within rounding of a bin edge moves all
// of it: `pointTransientTol`. A footprint moves only a rounding-sized part of
// its mass with the edge (the bin integrals are continuous in the path), so
// its transient tolerance is the steady one.
void expectSameVolumesForEachPixelModel(capture::RenderJob job, double steadyTol,
                                        double pointTransientTol) {
  for (const PixelModel& model : kPixelModels) {
    SCOPED_TRACE(model.name);
    job.settings.pixel_footprint = model.footprint;
    job.settings.pixel_samples = model.samples;
    expectSameVolumes(job, steadyTol, model.footprint ? steadyTol : pointTransientTol);
  }
}

void expectSameCornerVolumes(capture::Visibility visibility) {
  test::CornerJob s(24);
  s.job.settings.indirect.visibility = visibility;
  s.job.settings.indirect.rsm_resolution = 16;
  s.job.settings.indirect.points_per_vpl = 500;
  s.job.settings.shadow_map_resolution = 512;
  expectSameVolumesForEachPixelModel(s.job, 1e-3, 1e-2);
}

TEST(CpuMatchesGlGLTest, CornerVolumesWithExactVisibility) {
  expectSameCornerVolumes(capture::Visibility::Exact);
}
TEST(CpuMatchesGlGLTest, CornerVolumesWithIsms) {
  expectSameCornerVolumes(capture::Visibility::Ism);
}

// Issue 42: a medium filling the scene attenuates every leg on both backends
// alike (an absorbing one, different per channel), with the tolerances of
// vacuum; a small image, with ISMs (llvmpipe's exact visibility is slow).
TEST(CpuMatchesGlGLTest, CornerVolumesInAnAbsorbingMedium) {
  test::CornerJob s(12);
  s.job.settings.indirect.visibility = capture::Visibility::Ism;
  s.job.settings.indirect.rsm_resolution = 16;
  s.job.settings.indirect.points_per_vpl = 500;
  s.job.settings.shadow_map_resolution = 512;
  s.job.settings.medium.sigma_a_per_m = glm::vec3(0.15f, 0.4f, 0.8f);
  expectSameVolumesForEachPixelModel(s.job, 1e-3, 1e-2);
}

// Issue 42's per-region media: an absorbing cube region (different per
// channel, index 1.33) in the corner, in the light's and the camera's way,
// attenuates and delays every leg on both backends alike (GL: region_legs.comp
// and the indirect gather's medium_regions.glsl; CPU: capture::MediumRegions),
// the footprints centred on the delayed paths, with the tolerances of vacuum
// under each pixel model and adaptive samples (measured: every relative L1
// below 2.8e-4); ISMs (llvmpipe's exact visibility is slow), a 10 x 10 image.
TEST(CpuMatchesGlGLTest, CornerVolumesThroughAnAbsorbingRegion) {
  test::CornerJob s(10);
  test::addBox(s.scene, "cube", {-0.4f, 0.2f, -0.6f}, {0.4f, 0.8f, 0.2f});
  s.scene.regions.push_back(*scene::takeRegionMesh(s.scene, "cube"));
  s.job.settings.indirect.visibility = capture::Visibility::Ism;
  s.job.settings.indirect.rsm_resolution = 16;
  s.job.settings.indirect.points_per_vpl = 500;
  s.job.settings.shadow_map_resolution = 512;
  s.job.settings.media.push_back({"cube", {}, 1.33});
  s.job.settings.media.back().medium.sigma_a_per_m = {1.5f, 0.8f, 0.3f};
  expectSameVolumesForEachPixelModel(s.job, 1e-3, 1e-2);
  // Adaptive samples: the masked-out pixels' centre samples have legs of
  // their own (region_legs.comp's records after the N x N ones).
  s.job.settings.pixel_samples = 2;
  s.job.settings.adaptive_pixel_samples = true;
  expectSameVolumes(s.job, 1e-3, 1e-3);
}

// Glossy VPLs and the BRDF on the camera side of their light agree as the
// diffuse ones do, with the same tolerances: exact visibility with and
// without the clamp, and ISMs (whose splat reads the glossy VPL layout).
TEST(CpuMatchesGlGLTest, GlossyCornerVolumes) {
  const struct {
    capture::Visibility visibility;
    double clamp;
  } variants[] = {{capture::Visibility::Exact, 0.0},
                  {capture::Visibility::Exact, 1.0},
                  {capture::Visibility::Ism, 0.0}};
  for (const auto& [visibility, clamp] : variants) {
    SCOPED_TRACE(testing::Message() << (visibility == capture::Visibility::Ism ? "ism" : "exact")
                                    << ", vpl_brdf_clamp " << clamp);
    test::CornerJob s = test::glossyCorner(24);
    s.job.settings.indirect.visibility = visibility;
    s.job.settings.indirect.points_per_vpl = 500;
    s.job.settings.indirect.rsm_resolution = 16;
    s.job.settings.indirect.vpl_brdf_clamp_per_sr = clamp;
    s.job.settings.shadow_map_resolution = 512;
    expectSameVolumesForEachPixelModel(s.job, 1e-3, 1e-2);
  }
}

// A point-set imager (a grid on the corner's floor seen from the camera's
// position): the GL backend gathers from the driver's traced samples, its
// footprints from the points' own surface steps (SURFACE_STEPS), and agrees
// with the CPU backend under every pixel model, both visibilities, without
// the last leg, and lit by a Lambertian (laser spot) light on the back wall.
TEST(CpuMatchesGlGLTest, PointSetOnTheCornerFloorVolumes) {
  test::CornerJob s(24);
  s.job.settings.indirect.rsm_resolution = 16;
  s.job.settings.indirect.points_per_vpl = 500;
  s.job.settings.shadow_map_resolution = 512;
  const glm::vec3 origin = s.job.camera().position_world;
  for (const bool lastLeg : {true, false}) {
    for (capture::Visibility v : {capture::Visibility::Exact, capture::Visibility::Ism}) {
      SCOPED_TRACE(testing::Message() << (v == capture::Visibility::Ism ? "ism" : "exact")
                                      << (lastLeg ? "" : ", no last leg"));
      s.job.imager = capture::gridOnPlanarMesh(s.scene, "quad0", 12, 10, origin, lastLeg);
      s.job.settings.indirect.visibility = v;
      // The ISMs round as the box's do (CornellBoxVolumes): measured 1.1e-3.
      expectSameVolumesForEachPixelModel(s.job, v == capture::Visibility::Ism ? 3e-3 : 1e-3, 1e-2);
    }
  }
  // As in an NLOS capture: the light is a spot on the floor the points lie
  // on, so they see none of it directly, only its VPLs on the back wall.
  SCOPED_TRACE("Lambertian light");
  s.job.imager = capture::gridOnPlanarMesh(s.scene, "quad0", 12, 10, origin);
  s.job.light.type = capture::Light::Type::Lambertian;
  s.job.light.position_world = {0.2f, 1e-5f, 0.3f};
  s.job.light.direction_world = {0.0f, 1.0f, 0.0f};
  s.job.settings.indirect.visibility = capture::Visibility::Exact;
  expectSameVolumesForEachPixelModel(s.job, 1e-3, 1e-2);
}

// A camera with a barrel-distorting lens on the corner: the GL backend
// gathers from the driver's traced samples and takes each pixel's own ray
// steps (PIXEL_RAY_STEPS), and agrees with the CPU backend under every pixel
// model with footprints (point pixels take the traced samples as a point set
// does), adaptive samples included.
TEST(CpuMatchesGlGLTest, LensCameraOnTheCornerVolumes) {
  test::CornerJob s(24);
  s.job.settings.indirect.rsm_resolution = 16;
  s.job.settings.indirect.points_per_vpl = 500;
  s.job.settings.shadow_map_resolution = 512;
  capture::Lens lens;
  lens.fx = lens.fy = 30.0;
  lens.cx = lens.cy = 11.5;
  lens.distortion = {-0.3, 0.08, 0.003, -0.002, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  s.job.camera().lens = lens;
  s.job.settings.pixel_footprint = true;
  for (const bool adaptive : {false, true}) {
    for (const int32_t samples : {1, 2}) {
      if (adaptive && samples == 1) continue;
      SCOPED_TRACE(testing::Message()
                   << samples << " x " << samples << " samples" << (adaptive ? ", adaptive" : ""));
      s.job.settings.pixel_samples = samples;
      s.job.settings.adaptive_pixel_samples = adaptive;
      expectSameVolumes(s.job, 1e-3, 1e-3);
    }
  }
}

// Thin-lens defocus (camera.aperture) is gathered by the CPU backend only:
// the GL backend's gathers end every camera leg on the camera's position, so
// the driver refuses it there with an error naming the key, rather than
// rendering a pinhole's times through an aperture's rays.
TEST(CpuMatchesGlGLTest, DefocusIsRefusedOnTheGlBackend) {
  test::CornerJob s(8);
  s.job.camera().aperture_m = 0.01f;
  s.job.camera().focus_distance_m = 1.5f;
  try {
    renderOn(std::make_unique<render::GlBackend>(test::glTestContext()), s.job);
    ADD_FAILURE() << "the GL backend rendered a defocused camera";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("camera.aperture"), std::string::npos) << what;
    EXPECT_NE(what.find("does not gather aperture samples"), std::string::npos) << what;
  }
}

TEST(CpuMatchesGlGLTest, PlaneVolumes) {
  test::PlaneJob s;
  s.job.camera().width = 32;
  s.job.camera().height = 32;
  s.job.settings.indirect.rsm_resolution = 16;
  s.job.settings.shadow_map_resolution = 512;
  expectSameVolumesForEachPixelModel(s.job, 1e-3, 1e-2);
}

TEST(CpuMatchesGlGLTest, CornellBoxVolumes) {
  const scene::Scene scene = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  for (capture::Visibility v : {capture::Visibility::Exact, capture::Visibility::Ism}) {
    capture::RenderJob job = test::cornellBoxJob(scene, 32, 300, 0.01);
    job.settings.shadow_map_resolution = 512;
    job.settings.indirect.rsm_resolution = 16;
    job.settings.indirect.ism_resolution = 32;
    job.settings.indirect.points_per_vpl = 1000;
    job.settings.indirect.visibility = v;
    SCOPED_TRACE(v == capture::Visibility::Ism ? "ism" : "exact");
    // The box's ISMs differ more than the corner's (measured 1.8e-2 steady):
    // both splat the same seeded points, but a point's paraboloid texel can
    // round differently and the pull-push spreads it.
    if (v == capture::Visibility::Ism) {
      expectSameVolumesForEachPixelModel(job, 3e-2, 3e-2);
    } else {
      expectSameVolumesForEachPixelModel(job, 1e-2, 1e-2);
    }
  }
}

// render.adaptive_pixel_samples: each backend's centre G-buffer picks the
// sampled pixels (ir::sampledPixels); they must agree, or a pixel would take
// one sample on one backend and N x N on the other.
void expectSameSampledPixels(const capture::RenderJob& job) {
  render::GlBackend gl(test::glTestContext());
  CpuBackend cpu({2, true});
  const test::BackendScene glScene(gl, *job.scene), cpuScene(cpu, *job.scene);
  const int32_t w = job.camera().width, h = job.camera().height;
  const std::vector<uint8_t> onCpu = ir::sampledPixels(cpu.prepareSurfaces(job), w, h);
  EXPECT_EQ(onCpu, ir::sampledPixels(gl.prepareSurfaces(job), w, h));
  EXPECT_GT(std::count(onCpu.begin(), onCpu.end(), 1), 0);
}

TEST(CpuMatchesGlGLTest, AdaptiveSamplesPickTheSamePixels) {
  expectSameSampledPixels(test::CornerJob(24).job);
  const scene::Scene scene = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  expectSameSampledPixels(test::cornellBoxJob(scene, 32, 300, 0.01));
}

// And the volumes agree as the uniform sampling's do (expectSameVolumes:
// exact visibility and ISMs, the footprint, 2 x 2 at the edges).
TEST(CpuMatchesGlGLTest, CornerAndCornellBoxVolumesWithAdaptiveSamples) {
  test::CornerJob corner(24);
  corner.job.settings.indirect.rsm_resolution = 16;
  corner.job.settings.indirect.points_per_vpl = 500;
  corner.job.settings.shadow_map_resolution = 512;
  const scene::Scene scene = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  capture::RenderJob box = test::cornellBoxJob(scene, 32, 300, 0.01);
  box.settings.shadow_map_resolution = 512;
  box.settings.indirect.rsm_resolution = 16;
  box.settings.indirect.ism_resolution = 32;
  box.settings.indirect.points_per_vpl = 1000;
  for (capture::Visibility v : {capture::Visibility::Exact, capture::Visibility::Ism}) {
    SCOPED_TRACE(v == capture::Visibility::Ism ? "ism" : "exact");
    for (capture::RenderJob* job : {&corner.job, &box}) {
      job->settings.indirect.visibility = v;
      job->settings.pixel_samples = 2;
      job->settings.adaptive_pixel_samples = true;
    }
    expectSameVolumes(corner.job, 1e-3, 1e-3);
    // The box's ISMs: as CornellBoxVolumes.
    const double boxTol = v == capture::Visibility::Ism ? 3e-2 : 1e-2;
    expectSameVolumes(box, boxTol, boxTol);
  }
}

// Issue 42, item 4: a fog-filled corner (a scattering medium, different per
// channel, Henyey-Greenstein): the light's medium VPLs and a later bounce
// through the medium (medium children, and children of medium parents) on
// both backends alike: a medium VPL's side (vplEmitterCosine), its phase
// function (GL: whole VPL records, no model folding) and its exact
// visibility among ISMs, with the tolerances of vacuum.
TEST(CpuMatchesGlGLTest, CornerVolumesInAScatteringMedium) {
  test::CornerJob s(8);
  s.job.settings.indirect.visibility = capture::Visibility::Ism;
  s.job.settings.indirect.rsm_resolution = 8;
  s.job.settings.indirect.points_per_vpl = 500;
  s.job.settings.indirect.medium_vpls = 64;
  s.job.settings.indirect.bounces = 2;
  s.job.settings.indirect.vpls_per_bounce = 64;
  s.job.settings.shadow_map_resolution = 512;
  s.job.settings.medium.sigma_a_per_m = glm::vec3(0.05f, 0.1f, 0.2f);
  s.job.settings.medium.sigma_s_per_m = glm::vec3(0.6f, 0.4f, 0.3f);
  s.job.settings.medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
  s.job.settings.medium.g = 0.5f;
  // The medium VPLs and their light at the corner's walls; the VPLs' light
  // in the camera rays has its own GL = CPU test (MediumVplAgreementGLTest),
  // and here would take 40 s of the suite's time.
  s.job.settings.indirect.medium_camera_rays = false;
  expectSameVolumesForEachPixelModel(s.job, 1e-3, 1e-2);
}

}  // namespace
}  // namespace tofsim::cpu
