// IR against the reference path tracer on the glossy Cornell box
// (configs/scenes/cornell_box_glossy.gltf: a glossy dielectric floor of
// roughness 0.25, a rough-metal tall block of 0.35; render.materials: gltf)
// and, as the control, on the Lambertian one (and on it with a delayed wall,
// issue 41): steady and transient relative
// L1 of the total and of each component (direct, indirect, bounce 2 alone)
// for IR with 1 and 2 bounces against the reference with one interaction
// more. CPU backend, exact visibility, no geometry clamp, no BRDF clamp.
//
// Point pixels (pixel_footprint: false) against the reference's point
// filter: both then see the pixel centre's surface point, so the direct
// light agrees to float rounding and the figures measure the VPLs alone.
// With footprints against the box filter the box's edges would add their own
// ~0.24 transient L1 at this resolution (FootprintMatchesReferenceTest).

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>
#include <utility>

#include "reference/RenderReference.h"
#include "support/CpuRender.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/compare/VolumeComparison.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/physics/TemporalResponse.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::cpu {
namespace {

using namespace capture;

VolumeCollector renderIr(RenderJob job, int32_t bounces) {
  job.settings.indirect.bounces = bounces;
  return test::renderOnCpu(job).volume;
}

TransientVolume minus(const TransientVolume& a, const TransientVolume& b) {
  TransientVolume d = a;
  for (std::size_t i = 0; i < d.size(); ++i) d.values()[i] -= b.values()[i];
  return d;
}

struct L1 {
  double steady = 0.0;
  double transient = 0.0;
};

L1 relativeL1(const TransientVolume& a, const TransientVolume& b) {
  const compare::VolumeComparison c = compare::compareVolumes(a, b);
  return {c.steadyRelativeL1, c.transientRelativeL1};
}

// The compared volumes of one side: 1 and 2 bounces of IR, 2 and 3
// interactions of the reference.
struct Volumes {
  VolumeCollector one, two;
};

Volumes renderIrs(const RenderJob& job) { return {renderIr(job, 1), renderIr(job, 2)}; }

Volumes renderReferences(const RenderJob& job, int samples) {
  return {test::renderReference(job, 2, samples, reference::PixelFilter::Point),
          test::renderReference(job, 3, samples, reference::PixelFilter::Point)};
}

// Per component; bounce 2 alone is the difference of the two renders on each
// side (IR's bounce 1 does not depend on `bounces`, BounceComponentsTest).
struct Errors {
  L1 direct, total1, indirect1, total2, indirect2, bounce2;
};

Errors errors(const Volumes& a, const Volumes& b) {
  Errors e;
  e.direct = relativeL1(a.one.direct, b.one.direct);
  e.total1 = relativeL1(a.one.total(), b.one.total());
  e.indirect1 = relativeL1(a.one.indirect, b.one.indirect);
  e.total2 = relativeL1(a.two.total(), b.two.total());
  e.indirect2 = relativeL1(a.two.indirect, b.two.indirect);
  e.bounce2 =
      relativeL1(minus(a.two.indirect, a.one.indirect), minus(b.two.indirect, b.one.indirect));
  return e;
}

void print(const char* title, const Errors& e) {
  std::printf("%s (steady / transient relative L1)\n", title);
  const std::pair<const char*, const L1*> rows[] = {{"direct", &e.direct},
                                                    {"1 bounce: total", &e.total1},
                                                    {"1 bounce: indirect", &e.indirect1},
                                                    {"2 bounces: total", &e.total2},
                                                    {"2 bounces: indirect", &e.indirect2},
                                                    {"bounce 2 alone", &e.bounce2}};
  for (const auto& [name, l1] : rows) {
    std::printf("  %-22s %.4g / %.4g\n", name, l1->steady, l1->transient);
  }
}

RenderJob cornellJob(const scene::Scene& scene, MaterialModel materials) {
  RenderJob job = test::cornellBoxJob(scene, 24, 120, 0.05);  // 1.5 .. 7.5 m, 167 ps bins
  job.settings.materials = materials;
  job.settings.pixel_footprint = false;
  job.settings.indirect.rsm_resolution = 160;  // 25600 VPLs, as many rays for bounce 2
  job.settings.indirect.visibility = Visibility::Exact;
  job.settings.indirect.geometry_term_clamp_per_m2 = 0.0;
  return job;
}

constexpr int kReferencePaths = 8192;

using Bounds = Errors;  ///< upper bounds on each figure

void expectWithin(const Errors& e, const Bounds& b) {
  const std::pair<L1, L1> rows[] = {{e.direct, b.direct},       {e.total1, b.total1},
                                    {e.indirect1, b.indirect1}, {e.total2, b.total2},
                                    {e.indirect2, b.indirect2}, {e.bounce2, b.bounce2}};
  for (std::size_t i = 0; i < std::size(rows); ++i) {
    EXPECT_LT(rows[i].first.steady, rows[i].second.steady) << "row " << i;
    EXPECT_LT(rows[i].first.transient, rows[i].second.transient) << "row " << i;
  }
}

struct Measured {
  Errors ir;     ///< IR against the reference
  Errors noise;  ///< the reference with seed 2 against seed 1
};

Measured measure(const char* name, const RenderJob& job, const Volumes& ref) {
  RenderJob otherSeed = job;
  otherSeed.settings.seed = 2;
  const Measured m{errors(renderIrs(job), ref),
                   errors(renderReferences(otherSeed, kReferencePaths), ref)};
  print((std::string(name) + ", IR vs reference").c_str(), m.ir);
  print((std::string(name) + ", reference seed 2 vs seed 1").c_str(), m.noise);
  return m;
}

// Measured at commit time (steady / transient; 25600 VPLs, the reference at
// 8192 paths per pixel):
//                      IR vs reference    reference seed 2 vs 1
//   direct             3e-8 / 3e-8        0 / 0
//   1 bounce: total    0.024 / 0.031      0.007 / 0.014
//   1 bounce: indirect 0.145 / 0.187      0.041 / 0.083
//   2 bounces: total   0.028 / 0.049      0.009 / 0.024
//   2 bounces: indirect 0.117 / 0.208     0.040 / 0.100
//   bounce 2 alone     0.149 / 0.352      0.097 / 0.253
// IR's error is mostly its own VPL noise: it falls with the VPL count
// (indirect steady 0.29 with 2304 VPLs, 0.25 with 9216, 0.12 with 50176,
// against 4096 reference paths) at an energy within 1 % of the reference's.
// Bounds about 1.5x, above the reference's noise. The test can fail: IR
// with render.materials: lambertian against the same glossy reference gives
// 0.31 / 0.42 for 1 bounce's indirect light and 0.27 / 0.40 for 2 bounces'
// (its energy about 10 % low), above those bounds (checked below).
const Bounds kGlossyBounds{{1e-4, 1e-4},   {0.036, 0.047}, {0.22, 0.28},
                           {0.042, 0.074}, {0.18, 0.31},   {0.23, 0.53}};

TEST(GlossyCornellMatchesReferenceTest, GlossyBoxComponentsMatchTheReference) {
  const scene::Scene scene =
      scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box_glossy.gltf");
  const RenderJob job = cornellJob(scene, MaterialModel::Gltf);
  const Volumes ref = renderReferences(job, kReferencePaths);
  const Measured m = measure("glossy Cornell box", job, ref);
  expectWithin(m.ir, kGlossyBounds);
  expectWithin(m.noise, kGlossyBounds);
  RenderJob lambertian = job;
  lambertian.settings.materials = MaterialModel::Lambertian;
  const Errors wrong = errors(renderIrs(lambertian), ref);
  print("glossy Cornell box, IR with render.materials: lambertian vs the glossy reference", wrong);
  EXPECT_GT(wrong.indirect1.steady, kGlossyBounds.indirect1.steady);
  EXPECT_GT(wrong.indirect1.transient, kGlossyBounds.indirect1.transient);
  EXPECT_GT(wrong.indirect2.steady, kGlossyBounds.indirect2.steady);
  EXPECT_GT(wrong.indirect2.transient, kGlossyBounds.indirect2.transient);
}

// The control: the same job on the Lambertian box. Measured (steady /
// transient): IR vs reference direct 3e-8, 1 bounce total 0.0076 / 0.014,
// indirect 0.055 / 0.103; 2 bounces total 0.010 / 0.024, indirect 0.051 /
// 0.122, bounce 2 alone 0.089 / 0.251; the reference's seed-to-seed noise
// 0.017 / 0.067 (1 bounce's indirect), 0.015 / 0.071 (2 bounces'), 0.039 /
// 0.186 (bounce 2 alone). Glossy VPLs leave about 2.5x the Lambertian error
// at the same VPL count (their lobes make each VPL's light spikier).
const Bounds kLambertianBounds{{1e-4, 1e-4},   {0.012, 0.021}, {0.085, 0.15},
                               {0.016, 0.037}, {0.08, 0.18},   {0.14, 0.38}};

TEST(GlossyCornellMatchesReferenceTest, LambertianBoxComponentsMatchTheReference) {
  const scene::Scene scene = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  const RenderJob job = cornellJob(scene, MaterialModel::Lambertian);
  const Measured m = measure("Lambertian Cornell box", job, renderReferences(job, kReferencePaths));
  expectWithin(m.ir, kLambertianBounds);
  expectWithin(m.noise, kLambertianBounds);
}

// The Lambertian box with its red wall delayed (exponential, half the light
// delayed, a lifetime of 8 bins, 1.33 ns): IR's delayed response classes
// against the reference's delays sampled per vertex, within the bounds that
// hold without delays (kLambertianBounds), but for the direct light's
// transient. There the reference's arrival keeps its sub-bin time and IR's
// stage does not (a bin's light taken as uniform, temporal_response.md): the
// binned exponential differs by an L1 of 0.059 of the delayed light at 8
// bins (0.14 at 3), half the red wall's light is delayed and the wall holds
// about 4 % of the direct light (IR with the wall prompt: 0.036), so the
// bound is 0.003 plus 1.5x the reference's own noise (0.002). Measured
// before the merge (IR prompt; steady / transient): direct 7e-8 / 0.036,
// 1 bounce total 0.0027 / 0.045, 2 bounces total 0.0061 / 0.052, against
// bounds 0.021 and 0.037 (the undelayed box: 0.014 and 0.024).
// Needs IR's gathers to deposit the delayed classes (issue 41: the cpu41 and
// stage41 branches); before they are merged, IR renders the wall prompt and
// this test fails.
TEST(GlossyCornellMatchesReferenceTest, DelayedLambertianBoxComponentsMatchTheReference) {
  scene::Scene scene = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  bool found = false;
  for (scene::Material& m : scene.materials) {
    if (m.name != "red") continue;
    physics::ResponseKernel k;
    k.model = physics::ResponseModel::Exponential;
    k.fraction = 0.5;
    k.lifetime_s = 8.0 * 0.05 / kSpeedOfLight_m_per_s;
    m.scatteringDelay = k;
    found = true;
  }
  ASSERT_TRUE(found);
  const RenderJob job = cornellJob(scene, MaterialModel::Lambertian);
  const Volumes ref = renderReferences(job, kReferencePaths);
  const Measured m = measure("delayed Lambertian Cornell box", job, ref);
  Bounds bounds = kLambertianBounds;
  bounds.direct = {1e-4 + 1.5 * m.noise.direct.steady, 0.003 + 1.5 * m.noise.direct.transient};
  expectWithin(m.ir, bounds);
  bounds.direct = {1e-4 + m.noise.direct.steady, 1e-4 + m.noise.direct.transient};
  expectWithin(m.noise, bounds);
  // Not vacuous: the delays move more light in time than the bounds allow,
  // so IR rendering the wall prompt fails them.
  const scene::Scene promptScene =
      scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  const Volumes prompt =
      renderReferences(cornellJob(promptScene, MaterialModel::Lambertian), 1024);
  EXPECT_GT(relativeL1(prompt.two.total(), ref.two.total()).transient,
            kLambertianBounds.total2.transient);
}

}  // namespace
}  // namespace tofsim::cpu
