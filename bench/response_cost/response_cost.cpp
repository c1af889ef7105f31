// The temporal-response stage's cost (core/physics/temporal_response.md) on
// the CPU backend, in one run: whole renders of the corner scene (direct and
// indirect, side^2 pixels, 1000 bins, pixel footprint) without delays and
// with the wall's material delayed (the driver's classes: {wall}, {wall,
// wall}; whatever the gathers deposit into them), interleaved; then the stage
// alone with every pixel's rendered light (direct + indirect) in one delayed
// class, the worst case of issue 41's "every material delayed": an
// exponential lifetime (one tap and the tail), a Gaussian delay (an FIR of
// tens of taps) and the cascade of both (a class of two kernels), against
// the instant class's integration of the same pixels; and a narrow
// contribution's deposit into either class. Process CPU seconds (steadier than wall
// time on a shared machine); the best of `repeats`.
// Usage: tofsim_response_cost [threads=2] [side=128] [rsm=32] [repeats=3]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <vector>

#include "ResponseClasses.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "support/TestJobs.h"
#include "tofsim/physics/FootprintBuffer.h"
#include "tofsim/physics/TemporalResponse.h"

#include "../BenchArgs.h"

namespace {

using namespace tofsim;

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// One render's CPU seconds; its volumes in `light` (direct + indirect).
double renderSeconds(const capture::RenderJob& job, int threads, std::vector<float>* light) {
  capture::VolumeCollector volume(capture::imageWidth(job.imager), capture::imageHeight(job.imager),
                                  job.settings.time, capture::kChannels);
  auto backend = std::make_unique<cpu::CpuBackend>(cpu::CpuBackendOptions{threads, true});
  const double start = cpuSeconds();
  ir::IrRenderer(std::move(backend)).render(job, volume);
  const double seconds = cpuSeconds() - start;
  if (light != nullptr) {
    const std::vector<float>& d = volume.direct.values();
    const std::vector<float>& i = volume.indirect.values();
    light->resize(d.size());
    for (std::size_t k = 0; k < d.size(); ++k) (*light)[k] = d[k] + i[k];
  }
  return seconds;
}

// The difference buffer whose double prefix sum is `x` (bins x 3).
void differencesOf(const float* x, int32_t bins, double* diff) {
  for (int32_t n = 0; n < bins; ++n) {
    for (int c = 0; c < 3; ++c) {
      const auto at = [&](int32_t k) { return k < 0 ? 0.0 : static_cast<double>(x[k * 3 + c]); };
      diff[n * 3 + c] = at(n) - 2.0 * at(n - 1) + at(n - 2);
    }
  }
}

// CPU seconds of the stage over every pixel: `light` as one class's input
// (deposit = the buffer filled, untimed), through the cascade `stages`; or,
// with none, the instant class's integration of the same buffers.
double stageSeconds(const std::vector<float>& light, std::size_t pixels, int32_t bins,
                    const std::vector<physics::ResponseTaps>& stages) {
  std::vector<double> diff(static_cast<std::size_t>(bins) * 3), scratch(diff.size());
  std::vector<float> histogram(static_cast<std::size_t>(bins) * 3);
  double seconds = 0.0;
  for (std::size_t p = 0; p < pixels; ++p) {
    differencesOf(&light[p * bins * 3], bins, diff.data());
    const double start = cpuSeconds();
    if (!stages.empty()) {
      physics::applyResponse(diff.data(), scratch.data(), bins, 0, stages, histogram.data());
    } else {
      physics::integrateFootprint(diff.data(), bins, histogram.data());
    }
    seconds += cpuSeconds() - start;
  }
  return seconds;
}

// CPU seconds per contribution of `count` narrow kernels (a wall seen
// head-on: under 3 bins) into one pixel: the instant class's deposit
// (depositNarrow into the float histogram) or a delayed class's (depositWide
// into its difference buffer, however narrow: what issue 41's gathers pay).
double depositSeconds(int32_t bins, std::size_t count, bool delayed) {
  std::vector<float> histogram(static_cast<std::size_t>(bins) * 3, 0.0f);
  std::vector<double> diff(static_cast<std::size_t>(bins) * 3, 0.0);
  physics::OffAxisSums lost;
  const glm::vec3 energy(0.2f, 0.3f, 0.4f);
  const double start = cpuSeconds();
  for (std::size_t i = 0; i < count; ++i) {
    const float f = static_cast<float>(i % 977) / 977.0f;
    const glm::vec3 kernel(100.0f + 700.0f * f, 2.5f * f, 0.7f * f);
    if (delayed) {
      physics::depositWide(diff.data(), bins, kernel, energy, lost);
    } else {
      physics::depositNarrow(histogram.data(), bins, kernel, energy, lost);
    }
  }
  const double seconds = cpuSeconds() - start;
  volatile double sink = diff[300] + histogram[300];  // keep the work
  (void)sink;
  return seconds / static_cast<double>(count);
}

}  // namespace

int main(int argc, char** argv) {
  const int threads = bench::arg(argc, argv, 1, 2);
  const int side = bench::arg(argc, argv, 2, 128);
  const int rsm = bench::arg(argc, argv, 3, 32);
  const int repeats = bench::arg(argc, argv, 4, 3);
  test::CornerJob corner(side);
  corner.job.settings.indirect.rsm_resolution = rsm;
  corner.job.settings.pixel_footprint = true;
  const int32_t bins = corner.job.settings.time.bins;
  const double binWidth_s = corner.job.settings.time.bin_width_s;
  physics::ResponseKernel exponential;  // a fluorophore
  exponential.lifetime_s = 2.5e-9;
  exponential.fraction = 0.6;
  physics::ResponseKernel gaussian;  // a subsurface delay
  gaussian.model = physics::ResponseModel::Gaussian;
  gaussian.mean_s = 50e-12;
  gaussian.sigma_s = 20e-12;
  std::printf("corner %dx%d, rsm %d, %d bins of %.1f ps, %d threads, best of %d\n", side, side,
              rsm, bins, binWidth_s * 1e12, threads, repeats);

  double none = 1e30, wallDelayed = 1e30;
  std::vector<float> light;
  test::CornerJob delayedWall(side);
  delayedWall.job.settings = corner.job.settings;
  delayedWall.scene.materials[1].scatteringDelay = exponential;
  for (int r = 0; r < repeats; ++r) {
    none = std::min(none, renderSeconds(corner.job, threads, r == 0 ? &light : nullptr));
    wallDelayed = std::min(wallDelayed, renderSeconds(delayedWall.job, threads, nullptr));
  }
  std::printf("\n| render (CPU s) | no delay | the wall delayed | ratio |\n"
              "|---|---|---|---|\n| corner | %.3f | %.3f | %.3f |\n",
              none, wallDelayed, wallDelayed / none);

  const std::size_t pixels = static_cast<std::size_t>(side) * side;
  const physics::ResponseTaps expTaps = physics::responseTaps(exponential, binWidth_s);
  const physics::ResponseTaps gaussTaps = physics::responseTaps(gaussian, binWidth_s);
  double instant = 1e30, exp = 1e30, gauss = 1e30, both = 1e30;
  for (int r = 0; r < repeats; ++r) {
    instant = std::min(instant, stageSeconds(light, pixels, bins, {}));
    exp = std::min(exp, stageSeconds(light, pixels, bins, {expTaps}));
    gauss = std::min(gauss, stageSeconds(light, pixels, bins, {gaussTaps}));
    both = std::min(both, stageSeconds(light, pixels, bins, {expTaps, gaussTaps}));
  }
  std::printf(
      "\nEvery pixel's light in one class, the stage alone (CPU s, %zu pixels):\n\n"
      "| pass | taps | CPU s | per pixel, us | / instant integration | / render |\n"
      "|---|---|---|---|---|---|\n"
      "| instant integration | - | %.4f | %.2f | 1.00 | %.3f |\n"
      "| exponential 2.5 ns | %zu + tail | %.4f | %.2f | %.2f | %.3f |\n"
      "| Gaussian 50 +- 20 ps | %zu | %.4f | %.2f | %.2f | %.3f |\n"
      "| cascade: exponential, Gaussian | %zu + tail, %zu | %.4f | %.2f | %.2f | %.3f |\n",
      pixels, instant, instant / pixels * 1e6, instant / none, expTaps.taps.size(), exp,
      exp / pixels * 1e6, exp / instant, exp / none, gaussTaps.taps.size(), gauss,
      gauss / pixels * 1e6, gauss / instant, gauss / none, expTaps.taps.size(),
      gaussTaps.taps.size(), both, both / pixels * 1e6, both / instant, both / none);
  const std::size_t contributions = 4000000;
  double narrow = 1e30, wide = 1e30;
  for (int r = 0; r < repeats; ++r) {
    narrow = std::min(narrow, depositSeconds(bins, contributions, false));
    wide = std::min(wide, depositSeconds(bins, contributions, true));
  }
  std::printf(
      "\nA narrow contribution's deposit (ns, scalar; the indirect gather vectorises the "
      "instant one):\n\n| class | ns | ratio |\n|---|---|---|\n"
      "| instant (depositNarrow) | %.1f | 1.00 |\n| delayed (depositWide) | %.1f | %.2f |\n",
      narrow * 1e9, wide * 1e9, wide / narrow);
  return 0;
}
