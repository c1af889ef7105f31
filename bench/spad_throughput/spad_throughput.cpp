// Histogram bins per second of the SPAD model (sensors/src/Spad.cpp), the
// whole per-pixel work included (signal, resampling, pulse and jitter blur,
// sampling, the depth and intensity images), on a synthetic volume: one
// return per pixel at a bin that varies across the image, bright enough for
// pile-up at the brightest pixels (~10 % detections per cycle), 20 MHz of
// ambient light and 2 kHz of dark counts, as in configs/cornell_box.yaml.
// Each configuration runs on 1 and on `threads` threads; the counts must be
// byte-identical between them (checked and printed).
// Usage: tofsim_spad_throughput [side=128] [bins=1000] [cycles=100000] [threads=2]
//        [modes=both|synchronous|free-running] [crosstalk=0] [effects=none|device]
//        [engine=auto|exact|fast]
// crosstalk: crosstalk_probability to 4 neighbours, prompt (the streamed
// first-order path, SpadCrosstalk.h; with engine=exact the exact array
// driver, SpadArrayEvents.h, on one thread); 0: off.
// effects: device turns on the rest of a real device's effects (deviceEffects
// below: afterpulsing, a jitter tail, a fixed pattern with hot and dead
// pixels); none: today's ideal detector. engine: SpadParams::engine.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>
#include <thread>

#include "tofsim/sensors/Spad.h"

#include "../BenchArgs.h"

namespace {

using namespace tofsim;
using namespace tofsim::sensors;

TransientVolume syntheticVolume(int32_t side, int32_t bins) {
  TimeAxis axis;
  axis.start_s = 0.0;
  axis.bin_width_s = 10e-12;
  axis.bins = bins;
  TransientVolume v(side, side, axis, {"Y"});
  for (int32_t y = 0; y < side; ++y) {
    for (int32_t x = 0; x < side; ++x) {
      const int32_t t = bins / 5 + (x + 3 * y) % (bins / 2);
      // 0.02 .. 0.35 photons per pulse at the detector, before the PDE.
      v.at(y, x, t, 0) = 0.02f + 0.33f * static_cast<float>((x * 7 + y * 13) % 17) / 16.0f;
      v.at(y, x, t + 30, 0) = 0.01f;  // a weak second return
    }
  }
  return v;
}

// A device's effects besides crosstalk, at values of the order of the
// research note's (detector-models.md section 1): 3 % Bernoulli afterpulsing
// with a 2 ns and a 20 ns trap, a 5 % jitter tail of 100 ps, 10 % PDE
// spread, log-normal dark counts (sigma 0.7) with 1 % hot pixels at 50 kHz
// and 0.1 % dead pixels.
void deviceEffects(SpadParams& p) {
  p.afterpulse_probability = 0.03;
  p.afterpulse_delays_s = {2e-9, 20e-9};
  p.afterpulse_weights = {0.7, 0.3};
  p.jitter_tail_fraction = 0.05;
  p.jitter_tail_s = 100e-12;
  p.fpn_seed = 7;
  p.pde_spread = 0.1;
  p.dark_count_log_sigma = 0.7;
  p.hot_pixel_fraction = 0.01;
  p.hot_pixel_rate_per_s = 50e3;
  p.dead_pixel_fraction = 0.001;
}

SpadEngine engineNamed(const std::string& name) {
  if (name == "exact") return SpadEngine::Exact;
  if (name == "fast") return SpadEngine::Fast;
  return SpadEngine::Auto;
}

struct Timed {
  double seconds;     // wall clock
  double cpuSeconds;  // of the process, all threads (std::clock)
  std::vector<float> counts;
};

Timed run(const TransientVolume& v, const SpadParams& p, int threads) {
  StreamOptions options;
  options.seed = 1;
  options.threads = threads;
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpuStart = std::clock();
  const std::unique_ptr<SensorStream> stream = openSpad(p, shapeOf(v), options);
  stream->consume(wholeVolume(v));
  std::vector<SensorOutput> outs = stream->finish(nullptr);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
  return {s, cpu, std::move(outs[0].data)};
}

}  // namespace

int main(int argc, char** argv) {
  const int side = bench::arg(argc, argv, 1, 128);
  const int bins = bench::arg(argc, argv, 2, 1000);
  const long long cycles = bench::arg<long long>(argc, argv, 3, 100000);
  const int threads = bench::arg(argc, argv, 4, 2);
  const std::string modes = argc > 5 ? argv[5] : "both";
  const double crosstalk = bench::arg(argc, argv, 6, 0.0);
  const std::string effects = argc > 7 ? argv[7] : "none";
  const std::string engine = argc > 8 ? argv[8] : "auto";
  const TransientVolume v = syntheticVolume(side, bins);
  std::printf("spad %dx%d, %d bins, %lld cycles, crosstalk %g, effects %s, engine %s, %u cores\n",
              side, side, bins, cycles, crosstalk, effects.c_str(), engine.c_str(),
              std::thread::hardware_concurrency());
  std::printf(
      "| mode | threads | wall s | CPU s | M bins/s (wall) | M bins/s per CPU second | same "
      "bytes |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const SpadMode mode : {SpadMode::Synchronous, SpadMode::FreeRunning}) {
    const char* name = mode == SpadMode::Synchronous ? "synchronous" : "free-running";
    if (modes != "both" && modes != name) continue;
    SpadParams p;
    p.mode = mode;
    p.cycles = cycles;
    p.pde = 0.3;
    p.pulse_fwhm_s = 70e-12;
    p.jitter_fwhm_s = 50e-12;
    p.ambient_rate_per_s = 20e6;
    p.dark_count_rate_per_s = 2e3;
    p.dead_time_s = mode == SpadMode::FreeRunning ? 200e-12 : 0.0;
    p.crosstalk_probability = crosstalk;
    if (effects == "device") deviceEffects(p);
    p.engine = engineNamed(engine);
    const Timed one = run(v, p, 1);
    const Timed many = run(v, p, threads);
    const bool same =
        one.counts.size() == many.counts.size() &&
        std::memcmp(one.counts.data(), many.counts.data(), one.counts.size() * sizeof(float)) == 0;
    const double total = static_cast<double>(side) * side * bins;
    for (const auto& [n, r] : {std::pair{1, &one}, std::pair{threads, &many}}) {
      std::printf("| %s | %d | %.2f | %.2f | %.1f | %.1f | %s |\n", name, n, r->seconds,
                  r->cpuSeconds, total / r->seconds * 1e-6, total / r->cpuSeconds * 1e-6,
                  same ? "yes" : "NO");
    }
  }
  return 0;
}
