// pipeline::PsfSegments: the lens's PSF on every time bin of every
// component of a render, before any consumer. Alone: each component is
// optics::applyPsf of the gathered volume, the total direct + indirect
// again, the segments as they came. Through renderCapture (CPU backend, a
// small plane seen head-on): each bin's light is kept (the kernel stays in
// the image), the values are the sharp render's convolved to the bit, an
// identity PSF changes no byte, a consumer before the PSF gets the sharp
// light, and a volume over render.memory_budget is an error at camera.psf
// before rendering.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "support/AnalyticScenes.h"
#include "support/TempDir.h"
#include "tofsim/optics/PsfConvolution.h"
#include "tofsim/pipeline/FiniteSegments.h"
#include "tofsim/pipeline/PsfSegments.h"
#include "tofsim/pipeline/RenderCapture.h"

namespace tofsim::pipeline {
namespace {

// Every component's whole volume, and the segments' boundaries.
struct Collect : capture::SegmentSink {
  std::size_t perPixel;
  std::map<std::string, std::vector<float>> volumes;
  std::vector<std::pair<std::size_t, std::size_t>> segments;
  explicit Collect(std::size_t floatsPerPixel) : perPixel(floatsPerPixel) {}
  void consume(const capture::Segment& s) override {
    segments.emplace_back(s.firstPixel, s.pixelCount);
    for (const auto& c : s.components) {
      std::vector<float>& v = volumes[std::string(c.name)];
      v.insert(v.end(), c.values, c.values + s.pixelCount * perPixel);
    }
  }
};

const optics::PsfKernel& kernel() {
  static const optics::PsfKernel k =
      optics::PsfKernel::parametric({0.6, 0.1, optics::HaloProfile::Gaussian, 1.5});
  return k;
}

TEST(PsfSegmentsTest, ConvolvesEachComponentAndSendsTheSegmentsOn) {
  constexpr int w = 6, h = 5, bins = 4;
  constexpr std::size_t perPixel = bins * capture::kChannels, floats = w * h * perPixel;
  std::vector<float> direct(floats), indirect(floats), bounce1(floats), total(floats);
  for (std::size_t i = 0; i < floats; ++i) {
    direct[i] = float((i * 37) % 11) * 0.1f;
    bounce1[i] = float((i * 13) % 7) * 0.01f;
    indirect[i] = bounce1[i] * 1.5f;
    total[i] = direct[i] + indirect[i];
  }
  Collect out(perPixel);
  PsfSegments psf(out, w, h, bins, kernel(), 2);
  for (const auto& [first, count] : {std::pair<std::size_t, std::size_t>{0, 7}, {7, 16}, {23, 7}}) {
    const std::size_t o = first * perPixel;
    psf.consume({first,
                 count,
                 {{capture::kDirect, direct.data() + o},
                  {capture::kIndirect, indirect.data() + o},
                  {kTotal, total.data() + o},
                  {capture::bounceComponent(1), bounce1.data() + o}}});
    if (first == 0) {
      EXPECT_TRUE(out.segments.empty());  // nothing before the last pixel
    }
  }
  EXPECT_EQ(out.segments,
            (std::vector<std::pair<std::size_t, std::size_t>>{{0, 7}, {7, 16}, {23, 7}}));
  const optics::PlaneLayout layout{w, h, perPixel, 1};
  const std::map<std::string, const std::vector<float>*> sent = {
      {"direct", &direct}, {"indirect", &indirect}, {"bounce1", &bounce1}};
  for (const auto& [name, values] : sent) {
    std::vector<float> expected = *values;
    optics::applyPsf(kernel(), expected.data(), perPixel, layout);
    EXPECT_NE(expected, *values) << name;  // the kernel changes it
    EXPECT_EQ(out.volumes.at(name), expected) << name;
  }
  const std::vector<float>& d = out.volumes.at("direct");
  const std::vector<float>& in = out.volumes.at("indirect");
  const std::vector<float>& t = out.volumes.at("total");
  for (std::size_t i = 0; i < floats; ++i) ASSERT_EQ(t[i], d[i] + in[i]) << i;
}

constexpr int kSize = 24, kBins = 64;

class RenderCapturePsfTest : public test::TempDirTest {
 protected:
  config::RunConfig config(const std::string& extraCamera, const std::string& render = "") {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    const std::string yaml =
        "scene: scene.gltf\n"
        "camera: {position: [0, 0, 2], look_at: [0, 0, 0], fov_y: 40 deg, resolution: [24, "
        "24]" +
        extraCamera +
        "}\n"
        "light: {attach_to_camera: true, intensity: 5}\n"
        "time: {start: 13.2 ns, bin_width: 10 ps, bins: 64}\n"
        "render: {backend: cpu, threads: 2, indirect: {enabled: false}" +
        render + "}\n";
    return config::loadRunConfigText(yaml, dir_ / "c.yaml");
  }
  // What the outputs see, and (before) what a consumer of the light before
  // the PSF sees.
  Collect render(const config::RunConfig& c, Collect* before = nullptr) {
    const scene::Scene plane = test::makePlane(0.3f);
    const capture::RenderJob job = prepareCapture(c, plane);
    Collect out(kBins * capture::kChannels);
    Progress progress("render", true);
    CaptureConsumers consumers{{&out}, {}, {}};
    if (before) consumers.beforePsf.push_back(before);
    renderCapture(c, job, gl::EglPlatform::Auto, consumers, progress);
    return out;
  }
};

TEST_F(RenderCapturePsfTest, KeepsEachBinsLightAndConvolvesTheSharpRender) {
  const Collect sharp = render(config(""));
  const Collect identity = render(config(", psf: {}"));
  const config::RunConfig blurredConfig =
      config(", psf: {core_sigma: 0.6, halo_weight: 0.1, halo_radius: 1.5}");
  Collect beforePsf(kBins * capture::kChannels);
  const Collect blurred = render(blurredConfig, &beforePsf);
  EXPECT_EQ(beforePsf.volumes, sharp.volumes);  // a sensor applying the PSF itself
  // A PSF that is a delta: the gather and the re-sent segments change no byte.
  for (const char* name : {"direct", "indirect", "total"}) {
    EXPECT_EQ(identity.volumes.at(name), sharp.volumes.at(name)) << name;
  }
  const std::vector<float>& s = sharp.volumes.at("total");
  const std::vector<float>& b = blurred.volumes.at("total");
  // The plane's pixels lie at least the kernel's radius inside the image.
  const int r = blurredConfig.camera.psf->kernel.radiusX();
  ASSERT_EQ(r, 8);
  const std::size_t perPixel = kBins * capture::kChannels;
  int lit = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      double light = 0.0;
      for (std::size_t i = 0; i < perPixel; ++i) light += s[(y * kSize + x) * perPixel + i];
      if (light == 0.0) continue;
      ++lit;
      ASSERT_TRUE(x >= r && x < kSize - r && y >= r && y < kSize - r) << x << ", " << y;
    }
  }
  EXPECT_GT(lit, 9);
  // Each bin and channel keeps its light (float values: 1e-6 relative).
  double worst = 0.0, moved = 0.0;
  int litBins = 0;
  for (std::size_t plane = 0; plane < perPixel; ++plane) {
    double before = 0.0, after = 0.0;
    for (int p = 0; p < kSize * kSize; ++p) {
      before += s[p * perPixel + plane];
      after += b[p * perPixel + plane];
      moved += std::abs(b[p * perPixel + plane] - s[p * perPixel + plane]);
    }
    if (before == 0.0) continue;
    ++litBins;
    worst = std::max(worst, std::abs(after - before) / before);
  }
  std::printf("%d lit bins x channels: worst relative change of a bin's light %.2e\n", litBins,
              worst);
  EXPECT_GT(litBins, 3);
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(moved, 0.05 * std::accumulate(s.begin(), s.end(), 0.0));  // the kernel moved light
  // The values are the sharp render's, convolved bin by bin.
  std::vector<float> direct = sharp.volumes.at("direct"), indirect = sharp.volumes.at("indirect");
  const optics::PlaneLayout layout{kSize, kSize, perPixel, 1};
  optics::applyPsf(blurredConfig.camera.psf->kernel, direct.data(), perPixel, layout);
  optics::applyPsf(blurredConfig.camera.psf->kernel, indirect.data(), perPixel, layout);
  EXPECT_EQ(blurred.volumes.at("direct"), direct);
  for (std::size_t i = 0; i < b.size(); ++i) ASSERT_EQ(b[i], direct[i] + indirect[i]) << i;
}

TEST_F(RenderCapturePsfTest, AVolumeOverTheMemoryBudgetIsALocatedError) {
  // Direct and indirect, 48 x 48 x 64 bins x 3 floats: 3.4 MiB, over the
  // smallest budget render.memory_budget takes.
  std::ofstream(dir_ / "scene.gltf") << "{}";
  const config::RunConfig c = config::loadRunConfigText(
      "scene: scene.gltf\ncamera:\n  resolution: [48, 48]\n  psf: {core_sigma: 1}\nlight: {}\n"
      "time: {bins: 64}\nrender: {backend: cpu, memory_budget: 1 MiB}\n",
      dir_ / "c.yaml");
  const scene::Scene plane = test::makePlane(0.3f);
  const capture::RenderJob job = prepareCapture(c, plane);
  Collect out(64 * capture::kChannels);
  Progress progress("render", true);
  try {
    renderCapture(c, job, gl::EglPlatform::Auto, {{&out}, {}}, progress);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("c.yaml:4"), std::string::npos) << m;
    EXPECT_NE(m.find("camera.psf"), std::string::npos) << m;
    EXPECT_NE(m.find("3.4 MiB, more than render.memory_budget (1.0 MiB)"), std::string::npos) << m;
  }
  EXPECT_TRUE(out.segments.empty());  // before rendering
}

}  // namespace
}  // namespace tofsim::pipeline
