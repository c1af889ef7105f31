// Issue 42: how fast the reference path tracer renders a fog box and how
// noisy it is for its time. A closed 2 m box of Lambertian walls (albedo
// 0.6), a point light and the camera inside, filled with fog (sigma_s 1/m,
// sigma_a 0.02/m, Henyey-Greenstein g 0.8, then isotropic), 32 x 32 pixels, 64 bins of 0.2 m
// optical path, 4 vertices per path (surface or medium). Each sample count
// renders twice (seeds 1, 2): relative noise = RMS(a - b) / sqrt(2) / RMS of
// their mean, over all bins and channels (the transient) and over the steady
// image's pixels; noise x sqrt(seconds) is the constant of 1 / sqrt(time).
//
//   build/bench/tofsim_reference_fog_box [threads]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "support/AnalyticScenes.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/volume/PhysicalConstants.h"

using namespace tofsim;

namespace {

double relativeNoise(const std::vector<float>& a, const std::vector<float>& b) {
  double diff = 0.0, mean = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff += (static_cast<double>(a[i]) - b[i]) * (static_cast<double>(a[i]) - b[i]);
    const double m = 0.5 * (static_cast<double>(a[i]) + b[i]);
    mean += m * m;
  }
  return std::sqrt(diff / 2.0 / mean);
}

std::vector<float> steady(const TransientVolume& v) {
  std::vector<float> out(static_cast<std::size_t>(v.width()) * v.height(), 0.0f);
  for (int y = 0; y < v.height(); ++y)
    for (int x = 0; x < v.width(); ++x)
      for (int t = 0; t < v.bins(); ++t)
        for (int c = 0; c < 3; ++c) out[static_cast<std::size_t>(y) * v.width() + x] += v.at(y, x, t, c);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const int threads = argc > 1 ? std::atoi(argv[1]) : 0;
  scene::Scene box = test::makeClosedBox(2.0f, glm::vec3(0.6f));
  capture::RenderJob job;
  job.scene = &box;
  job.camera().position_world = {0.0f, 0.0f, 0.9f};
  job.camera().look_at_world = {0.0f, 0.0f, -1.0f};
  job.camera().fov_y_deg = 60.0f;
  job.camera().width = job.camera().height = 32;
  job.light.position_world = {0.3f, 0.2f, 0.5f};
  job.light.intensity_W_per_sr = glm::vec3(1.0f);
  job.settings.time = TimeAxis{0.0, 0.2 / kSpeedOfLight_m_per_s, 64};
  job.settings.medium.sigma_s_per_m = glm::vec3(1.0f);
  job.settings.medium.sigma_a_per_m = glm::vec3(0.02f);
  job.settings.medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
  for (const float g : {0.8f, 0.0f}) {
  job.settings.medium.g = g;
  std::printf("fog box 32x32, 64 bins, 4 vertices per path, g %.1f, threads %d\n", g, threads);
  std::printf("%6s %9s %16s %14s %20s %16s\n", "paths", "seconds", "transient noise",
              "steady noise", "transient x sqrt(s)", "max / mean pixel");
  for (const int paths : {16, 64, 256, 1024}) {
    reference::ReferenceSettings settings;
    settings.bounces = 4;
    settings.samples_per_pixel = paths;
    settings.threads = threads;
    std::vector<float> total[2];
    std::vector<float> still[2];
    double seconds = 0.0;
    for (int run = 0; run < 2; ++run) {
      job.settings.seed = static_cast<uint64_t>(run + 1);
      capture::VolumeCollector out(32, 32, job.settings.time, 3);
      const auto start = std::chrono::steady_clock::now();
      reference::ReferenceRenderer(settings).render(job, out);
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const TransientVolume t = out.total();
      total[run] = t.values();
      still[run] = steady(t);
    }
    seconds /= 2.0;
    double sum = 0.0, brightest = 0.0;  // of the first run's steady image
    for (const float v : still[0]) {
      sum += v;
      brightest = std::max(brightest, static_cast<double>(v));
    }
    const double noise = relativeNoise(total[0], total[1]);
    std::printf("%6d %9.2f %16.4f %14.4f %20.4f %16.1f\n", paths, seconds, noise,
                relativeNoise(still[0], still[1]), noise * std::sqrt(seconds),
                brightest / (sum / still[0].size()));
  }
  }
  return 0;
}
