// IR (CPU backend, exact visibility) against the reference path tracer on a
// hidden scene where one hidden surface shadows another: an L-shaped letter
// of three squares in front of a patch, as seen from the relay wall. Both
// render the third bounce (wall -> hidden -> wall) only.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "HiddenPatch.h"
#include "tofsim/pipeline/NlosRender.h"

namespace tofsim::pipeline {
namespace {

constexpr float kLetterZ = 0.3f, kLetterCell = 0.1f, kLetterAlbedo = 0.7f;
constexpr float kBackZ = 0.5f, kBackSide = 0.3f, kBackAlbedo = 0.8f;

// The wall ("quad0", as hiddenPatch's), then the letter and / or the patch
// behind it, all facing the wall.
scene::Scene hiddenLetter(bool letter, bool patch) {
  scene::Scene s;
  tofsim::test::addQuad(s, glm::vec3(0.0f), glm::vec3(0, 0, 1), 1.0f, glm::vec3(test::kWallAlbedo));
  if (letter) {
    for (const glm::vec2 c :
         {glm::vec2(-0.05f, 0.05f), glm::vec2(-0.05f, -0.05f), glm::vec2(0.05f, -0.05f)}) {
      tofsim::test::addQuad(s, glm::vec3(c, kLetterZ), glm::vec3(0, 0, -1), kLetterCell,
                            glm::vec3(kLetterAlbedo));
    }
  }
  if (patch) {
    tofsim::test::addQuad(s, glm::vec3(0.05f, 0.05f, kBackZ), glm::vec3(0, 0, -1), kBackSide,
                          glm::vec3(kBackAlbedo));
  }
  return s;
}

config::RunConfig occlusionConfig(bool reference) {
  config::RunConfig c = test::nlosConfig(config::NlosScan::Confocal, 512);
  c.nlos->sensor_grid = {4, 4};
  // Beside the wall and nearer it than the letter: no line of sight to a
  // wall point crosses a hidden surface.
  c.nlos->sensor_origin = {-0.8f, 0.0f, 0.2f};
  c.nlos->laser_origin = {-0.8f, 0.1f, 0.2f};
  if (reference) {
    c.renderer = config::RendererKind::Reference;
    c.reference.bounces = 2;
    c.reference.samples_per_pixel = 1 << 20;
    c.reference.threads = 2;
  }
  return c;
}

// H summed over time (one value per point), or rebinned to `bins` bins of
// the original per point (3 x 1 cm = 100 ps).
std::vector<double> rebinned(const NlosVolume& v, int32_t bins) {
  const std::size_t points = v.H.size() / v.axis.bins;
  const int32_t out = (v.axis.bins + bins - 1) / bins;
  std::vector<double> r(static_cast<std::size_t>(out) * points, 0.0);
  for (int32_t t = 0; t < v.axis.bins; ++t) {
    for (std::size_t p = 0; p < points; ++p) r[(t / bins) * points + p] += v.H[t * points + p];
  }
  return r;
}

double relativeL1(const std::vector<double>& a, const std::vector<double>& reference) {
  double diff = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff += std::abs(a[i] - reference[i]);
    sum += std::abs(reference[i]);
  }
  return diff / sum;
}

std::vector<double> plus(std::vector<double> a, const std::vector<double>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) a[i] += b[i];
  return a;
}

TEST(NlosOcclusionTest, IrMatchesTheReferenceWhereTheLetterShadowsThePatch) {
  const scene::Scene both = hiddenLetter(true, true);
  const NlosVolume ref = test::render(occlusionConfig(true), both);
  const NlosVolume ir = test::render(occlusionConfig(false), both);
  const int32_t steady = ref.axis.bins, transient = 3;
  const double steadyL1 = relativeL1(rebinned(ir, steady), rebinned(ref, steady));
  const double transientL1 = relativeL1(rebinned(ir, transient), rebinned(ref, transient));
  // Without occlusion between the hidden surfaces H would be the letter's
  // alone plus the patch's alone.
  const NlosVolume letter = test::render(occlusionConfig(false), hiddenLetter(true, false));
  const NlosVolume patch = test::render(occlusionConfig(false), hiddenLetter(false, true));
  const double unoccludedSteadyL1 =
      relativeL1(plus(rebinned(letter, steady), rebinned(patch, steady)), rebinned(ref, steady));
  const double unoccludedTransientL1 = relativeL1(
      plus(rebinned(letter, transient), rebinned(patch, transient)), rebinned(ref, transient));
  RecordProperty("steady_l1", std::to_string(steadyL1));
  RecordProperty("transient_l1", std::to_string(transientL1));
  // Measured over seeds 1-9: steady 0.34-0.60 %, transient (100 ps bins)
  // 1.22-1.49 %, the reference's noise with IR's RSM on top; the bounds are
  // 2.5 and 2 times the worst.
  constexpr double kSteadyBound = 0.015, kTransientBound = 0.03;
  EXPECT_LT(steadyL1, kSteadyBound);
  EXPECT_LT(transientL1, kTransientBound);
  // The letter hides 13 % of the patch-and-letter light (measured: steady
  // L1 13.0-13.2 %, transient 13.9-14.1 % between the sum of the two alone
  // and the reference): IR without occlusion between hidden surfaces would
  // miss both bounds over 4 times.
  EXPECT_GT(unoccludedSteadyL1, 3 * kSteadyBound);
  EXPECT_GT(unoccludedTransientL1, 3 * kTransientBound);
}

}  // namespace
}  // namespace tofsim::pipeline
