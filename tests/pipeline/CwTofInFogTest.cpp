// CW-ToF in fog (issue 42, item 6): a plane at range r faces a co-located
// camera and point light in a scattering medium. The CW-ToF sensor's phase of
// the render's direct light (the surface's return and the medium's single
// scattering along the pixel's ray, on the CPU backend) against the closed
// form the test computes itself: the phasor sum of
//   surface:     (rho / pi) I / r^2 exp(-2 sigma_t r) e^{i w 2r/c}
//   backscatter: the integral over s in [s0, r] of the lidar equation's
//                sigma_s p(pi) I exp(-2 sigma_t s) / s^2 times e^{i w 2s/c}
// (w = 2 pi f). The axis starts at 2 s0 of optical path: a co-located point
// light's backscatter grows as 1/s toward the lens (the render bounds it by
// the emitter's 1 mm radius; a camera's overlap function would), so both the
// render and the closed form leave out s < s0. The backscatter pulls the
// depth toward the camera, more the more the medium scatters.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "support/AnalyticScenes.h"
#include "support/CpuRender.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::pipeline {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kC = kSpeedOfLight_m_per_s;
constexpr double kF_Hz = 20e6;       // one frequency: 7.5 m unambiguous, no unwrapping
constexpr double kS0_m = 0.5;        // the axis's first depth
constexpr double kBin_m = 0.02;      // optical path per bin: 1 cm of depth
constexpr int32_t kBins = 300;       // paths 1 .. 7 m
constexpr float kRange_m = 3.005f;   // the plane's return at the centre of bin 250
constexpr float kAlbedo = 0.5f;
constexpr double kSigmaA = 0.01;     // 1/m
constexpr double kRenderAccuracy = 1e-3;  // per bin: MediumDirectGLTest's bound on the lidar equation

struct Fog {
  double sigmaS;
  double sigmaT() const { return kSigmaA + sigmaS; }
};

capture::RenderJob planeInFog(const scene::Scene& scene, Fog fog) {
  capture::RenderJob job;
  job.scene = &scene;
  job.camera().position_world = glm::vec3(0.0f);
  job.camera().look_at_world = glm::vec3(0.0f, 0.0f, -1.0f);
  job.camera().fov_y_deg = 1.0f;
  job.camera().width = job.camera().height = 1;
  job.light.position_world = glm::vec3(0.0f);
  job.light.intensity_W_per_sr = glm::vec3(1.0f);
  job.settings.indirect.enabled = false;  // the direct light: surface and single scattering
  job.settings.pixel_footprint = false;   // closed forms at the pixel centre
  job.settings.medium.sigma_a_per_m = glm::vec3(static_cast<float>(kSigmaA));
  job.settings.medium.sigma_s_per_m = glm::vec3(static_cast<float>(fog.sigmaS));
  job.settings.time = TimeAxis{2 * kS0_m / kC, kBin_m / kC, kBins};
  return job;
}

// Composite Simpson's rule of f on [a, b] with n (even) intervals.
template <typename F>
auto simpson(F f, double a, double b, int n = 20000) {
  const double h = (b - a) / n;
  auto sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += f(a + i * h) * (i % 2 == 1 ? 4.0 : 2.0);
  return sum * (h / 3.0);
}

struct ClosedForm {
  std::complex<double> phasor;  // surface + backscatter
  double magnitudes;            // |surface| + the backscatter's energy
  double backscatter;           // the backscatter's energy
  double depth_m;               // the phasor's depth
};

ClosedForm closedForm(Fog fog) {
  const double w = 2 * kPi * kF_Hz, r = kRange_m;
  const auto at = [&](double s) { return std::polar(1.0, w * 2 * s / kC); };
  const double surface = kAlbedo / kPi / (r * r) * std::exp(-2 * fog.sigmaT() * r);
  const double scale = fog.sigmaS / (4 * kPi);  // p(pi) of an isotropic medium, I = 1
  const auto density = [&](double s) { return scale * std::exp(-2 * fog.sigmaT() * s) / (s * s); };
  ClosedForm out;
  out.backscatter = simpson(density, kS0_m, r);
  out.phasor = surface * at(r) +
               simpson([&](double s) { return density(s) * at(s); }, kS0_m, r);
  out.magnitudes = surface + out.backscatter;
  double phase = std::arg(out.phasor);
  if (phase < 0) phase += 2 * kPi;
  out.depth_m = kC * phase / (2 * w);
  return out;
}

// The sensor's noise-free depth of the render's one pixel (channel 0).
double renderedDepth_m(Fog fog) {
  const scene::Scene scene = [] {
    scene::Scene s;
    test::addQuad(s, glm::vec3(0.0f, 0.0f, -kRange_m), glm::vec3(0, 0, 1), 4.0f,
                  glm::vec3(kAlbedo));
    return s;
  }();
  const capture::RenderJob job = planeInFog(scene, fog);
  const test::CpuRender render = test::renderOnCpu(job);
  std::vector<double> signal(kBins);
  for (int32_t k = 0; k < kBins; ++k) signal[k] = render.volume.direct.at(0, 0, k, 0);
  sensors::CwTofParams params;
  params.frequencies_Hz = {kF_Hz};
  const std::vector<double> phases = sensors::noiseFreePhases(params, job.settings.time, signal);
  return job.settings.time.depthPerSecond_m_per_s() * phases[0] / (2 * kPi * kF_Hz);
}

// The depth error the render may make: its bins within kRenderAccuracy
// (a phasor error of at most that times the sum of magnitudes), and the
// sensor's reading of each bin as light spread evenly over it (the
// backscatter's centroid within a bin of depth width d is off the bin's
// centre by at most d^2 / 12 times its density's relative slope, 2 / s0 +
// 2 sigma_t), as phase over the phasor's magnitude, in metres.
double tolerance_m(Fog fog, const ClosedForm& truth) {
  const double w = 2 * kPi * kF_Hz, d = kBin_m / 2;
  const double centroid_m = d * d / 12 * (2 / kS0_m + 2 * fog.sigmaT());
  const double phasorError =
      kRenderAccuracy * truth.magnitudes + w * 2 * centroid_m / kC * truth.backscatter;
  return kC / (2 * w) * phasorError / std::abs(truth.phasor);
}

TEST(CwTofInFogTest, VacuumDepthIsTheRange) {
  EXPECT_NEAR(renderedDepth_m(Fog{0.0}) - kRange_m, 0.0, 1e-4);
}

// sigma_s = 0.02, 0.05, 0.1 /m (visibilities of about 130, 65 and 35 m):
// the depth of surface + backscatter within the tolerance of the closed
// form's (1.4 .. 1.9 mm), the bias toward the camera (the closed form's is
// 18, 50 and 105 cm) far outside it and growing with sigma_s.
TEST(CwTofInFogTest, BackscatterPullsTheDepthTowardTheCameraAsTheClosedForm) {
  double previousBias = 0.0;
  for (const double sigmaS : {0.02, 0.05, 0.1}) {
    const Fog fog{sigmaS};
    const ClosedForm truth = closedForm(fog);
    const double tolerance = tolerance_m(fog, truth);
    const double depth = renderedDepth_m(fog);
    EXPECT_NEAR(depth, truth.depth_m, tolerance) << "sigma_s " << sigmaS;
    const double bias = depth - kRange_m;
    EXPECT_LT(bias, previousBias - 10 * tolerance) << "sigma_s " << sigmaS;
    previousBias = bias;
  }
}

}  // namespace
}  // namespace tofsim::pipeline
