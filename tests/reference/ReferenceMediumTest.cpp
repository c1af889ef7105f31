// The reference path tracer in a homogeneous medium filling the scene
// (issue 42): a purely absorbing medium scales every bin, direct and
// indirect, by exp(-sigma_a x the bin's geometric path); the single-scattered
// return of a co-located light and camera is the lidar equation per bin
// (isotropic, Henyey-Greenstein, Rayleigh: p(pi)); a plane's return is the
// vacuum return x exp(-2 sigma_t r). Per-channel coefficients throughout (the
// spectral MIS of the free flights); tolerances are z-scores from the
// estimator's second moments (MediumClosedForm.h) and the sample count.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "MediumClosedForm.h"
#include "RenderReference.h"
#include "support/ClosedForm.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/reference/Equiangular.h"
#include "tofsim/util/Error.h"

namespace tofsim::reference {
namespace {

using namespace capture;

Medium medium(glm::vec3 sigmaA, glm::vec3 sigmaS, int phase = physics::PHASE_ISOTROPIC,
              float g = 0.0f) {
  Medium m;
  m.sigma_a_per_m = sigmaA;
  m.sigma_s_per_m = sigmaS;
  m.phase = phase;
  m.g = g;
  return m;
}

// Every bin and channel of `fog` lies between the vacuum value x
// exp(-sigma_a x) at the bin's longest and shortest geometric path x.
void expectAttenuatedByBinPath(const TransientVolume& vacuum, const TransientVolume& fog,
                               const TimeAxis& axis, glm::dvec3 sigmaA, const char* what) {
  int lit = 0, failures = 0;
  for (int y = 0; y < vacuum.height(); ++y) {
    for (int x = 0; x < vacuum.width(); ++x) {
      for (int b = 0; b < axis.bins; ++b) {
        // The bin's geometric path lengths: optical / eta.
        const double lo = axis.binStart_s(b) * kSpeedOfLight_m_per_s / axis.index_of_refraction;
        const double hi = axis.binStart_s(b + 1) * kSpeedOfLight_m_per_s / axis.index_of_refraction;
        for (int c = 0; c < 3; ++c) {
          const double v = vacuum.at(y, x, b, c), f = fog.at(y, x, b, c);
          if (v > 0.0) ++lit;
          const double upper = v * std::exp(-sigmaA[c] * lo) * (1.0 + 1e-5) + 1e-30;
          const double lower = v * std::exp(-sigmaA[c] * hi) * (1.0 - 1e-5);
          if (f > upper || f < lower) ++failures;
        }
      }
    }
  }
  EXPECT_GT(lit, 100) << what;
  EXPECT_EQ(failures, 0) << what;
}

TEST(ReferenceMediumTest, AbsorbingMediumScalesEveryBinByItsGeometricPath) {
  // Corner, three interactions, box filter: an absorber changes no draw
  // (flights are not sampled without scattering), so each path's
  // contribution is the vacuum one x exp(-sigma_a x its geometric length),
  // which lies between the bin's bounds: direct and indirect alike.
  test::CornerJob s(12);
  s.job.settings.time.index_of_refraction = 1.33;
  ReferenceSettings settings;
  settings.bounces = 3;
  settings.samples_per_pixel = 16;
  settings.threads = 2;
  const VolumeCollector vacuum = test::renderReference(s.job, settings);
  const glm::vec3 sigmaA(0.3f, 0.9f, 0.05f);
  s.job.settings.medium = medium(sigmaA, glm::vec3(0.0f));
  const VolumeCollector fog = test::renderReference(s.job, settings);
  expectAttenuatedByBinPath(vacuum.direct, fog.direct, s.job.settings.time, sigmaA, "direct");
  expectAttenuatedByBinPath(vacuum.indirect, fog.indirect, s.job.settings.time, sigmaA,
                            "indirect");
}

// A camera at `position` looking at `lookAt` with the light at its pinhole
// (the lidar equation's geometry), side x side pixels, and a time axis whose
// bin b holds the one-way geometric distances [s0 + b bin, s0 + (b + 1) bin)
// at index eta.
RenderJob monostaticJob(const scene::Scene& scene, glm::vec3 position, glm::vec3 lookAt,
                        float fovDeg, int32_t side, glm::vec3 intensity, double eta, double s0,
                        double bin, int32_t bins) {
  RenderJob job;
  job.scene = &scene;
  job.camera().position_world = position;
  job.camera().look_at_world = lookAt;
  job.camera().fov_y_deg = fovDeg;
  job.camera().width = job.camera().height = side;
  job.light.position_world = position;
  job.light.intensity_W_per_sr = intensity;
  const double perMetre = 2.0 * eta / kSpeedOfLight_m_per_s;
  job.settings.time = TimeAxis{s0 * perMetre, bin * perMetre, bins};
  job.settings.time.index_of_refraction = eta;
  return job;
}

// A camera with the light at its pinhole, looking away from everything (a
// small plane far behind it keeps the scene non-empty): only the medium
// returns light.
struct LidarJob {
  static constexpr double kEta = 1.25;
  static constexpr double kS0 = 0.5, kBin = 0.25;  // one-way geometric distance, m
  scene::Scene scene = test::makePlane(1.0f, glm::vec3(0.0f));
  RenderJob job = monostaticJob(scene, {0.0f, 0.0f, 50.0f}, {0.0f, 0.0f, 60.0f}, 10.0f, 4,
                                {2.0f, 1.0f, 3.0f}, kEta, kS0, kBin, 16);
};

ReferenceSettings singleScattering(int32_t samples) {
  ReferenceSettings s;
  s.pixel_filter = PixelFilter::Point;
  s.bounces = 1;
  s.samples_per_pixel = samples;
  s.threads = 2;
  return s;
}

// Sum over the bins of the image-mean's chi-square against the lidar
// equation of `truth` (pixels pooled: they all see the same medium), the
// three channels together through their covariance: one free flight serves
// all three (spectral MIS), so their estimates are one draw's and nearly
// proportional; counted as independent, each bin would count about three
// times. 3 degrees of freedom a bin.
double lidarChiSquare(const TransientVolume& v, const Medium& truth, double phaseBack,
                      const glm::dvec3& intensity, double pathsPerPixel) {
  const int pixels = v.width() * v.height();
  double chi2 = 0.0;
  for (int b = 0; b < v.bins(); ++b) {
    glm::dvec3 mean(0.0);
    for (int y = 0; y < v.height(); ++y)
      for (int x = 0; x < v.width(); ++x)
        for (int c = 0; c < 3; ++c) mean[c] += v.at(y, x, b, c) / pixels;
    const double s0 = LidarJob::kS0 + b * LidarJob::kBin;
    const test::ChannelMoments m =
        test::lidarReturnChannels(truth, phaseBack, intensity, s0, s0 + LidarJob::kBin);
    chi2 += m.chiSquare(mean, pathsPerPixel * pixels);
  }
  return chi2;
}

TEST(ReferenceMediumTest, SingleScatteringFollowsTheLidarEquationPerBin) {
  struct Case {
    int phase;
    float g;
  };
  constexpr int kPaths = 4096;
  const double df = 16 * 3;  // bins x channels, through the channels' covariance
  const double critical = df + 5.0 * std::sqrt(2.0 * df);  // chi-square, far tail
  for (const Case k : {Case{physics::PHASE_ISOTROPIC, 0.0f},
                       Case{physics::PHASE_HENYEY_GREENSTEIN, 0.5f},
                       Case{physics::PHASE_RAYLEIGH, 0.0f}}) {
    LidarJob s;
    const Medium m = medium({0.1f, 0.3f, 0.05f}, {0.3f, 0.2f, 0.5f}, k.phase, k.g);
    s.job.settings.medium = m;
    s.job.settings.seed = 17 + static_cast<uint64_t>(k.phase);  // independent cases
    const VolumeCollector out = test::renderReference(s.job, singleScattering(kPaths));
    const double back = physics::phaseFunction(k.phase, k.g, -1.0f);
    const glm::dvec3 intensity(s.job.light.intensity_W_per_sr);
    const double chi2 = lidarChiSquare(out.direct, m, back, intensity, kPaths);
    EXPECT_LT(chi2, critical) << k.phase;
    // Mis-parametrised truths are rejected by the same bins: sigma_t 10 %
    // off, or the isotropic p(pi) for an anisotropic lobe.
    Medium off = m;
    off.sigma_a_per_m *= 1.1f;
    off.sigma_s_per_m *= 1.1f;
    const double chi2Off = lidarChiSquare(out.direct, off, back, intensity, kPaths);
    EXPECT_GT(chi2Off, critical);
    std::printf("phase %d: chi-square %.1f (16 bins x 3 channels' covariance; critical %.1f), "
                "sigma_t +10%%: %.0f\n",
                k.phase, chi2, critical, chi2Off);
    if (k.phase != physics::PHASE_ISOTROPIC) {
      EXPECT_GT(lidarChiSquare(out.direct, m, 1.0 / (4.0 * M_PI), intensity, kPaths), critical);
    }
    for (int b = 0; b < out.indirect.bins(); ++b) EXPECT_EQ(out.indirect.at(0, 0, b, 0), 0.0f);
  }
}

TEST(ReferenceMediumTest, BistaticSingleScatteringIsTheIntegralAlongThePixelRay) {
  // The light 0.5 m beside the camera: every medium point on a pixel's ray
  // sends sigma_s p(theta) I T(t) T(d) / d^2 at path t + d, estimated by the
  // free flight and the equiangular point (MIS). Expected bins and second
  // moments by a fine quadrature along each pixel's ray.
  LidarJob s;
  s.job.light.position_world = s.job.camera().position_world + glm::vec3(0.5f, 0.0f, 0.0f);
  constexpr double kL0 = 1.0, kWidth = 0.25;  // total geometric path of bin 0, bin width
  s.job.settings.time = test::pathAxis(LidarJob::kEta, kL0, kWidth, 16);
  const Medium m = medium({0.1f, 0.3f, 0.05f}, {0.3f, 0.2f, 0.5f},
                          physics::PHASE_HENYEY_GREENSTEIN, 0.5f);
  s.job.settings.medium = m;
  constexpr int kPaths = 2048;
  const VolumeCollector out = test::renderReference(s.job, singleScattering(kPaths));
  const PrimaryRays rays(s.job.imager);
  const glm::dvec3 light(s.job.light.position_world);
  const glm::dvec3 sigmaT(m.sigmaT()), sigmaS(m.sigma_s_per_m);
  const glm::dvec3 intensity(s.job.light.intensity_W_per_sr);
  double chi2 = 0.0, chi2NoMis = 0.0;
  int dof = 0;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const PrimaryRay ray = rays.ray(x, y);
      const glm::dvec3 o(ray.origin), dir(ray.direction);
      const PhaseAngleTable angles(m.phase, m.g);
      const Equiangular towardsLight(o, dir, std::numeric_limits<double>::infinity(), light, angles);
      // Per bin, the three channels together (one free flight and one
      // equiangular point serve them, so their estimates are one draw's:
      // a chi-square through their covariance, 3 degrees of freedom a pixel
      // and bin): the mean, E[A A^T] + E[B B^T], E[A], E[B]; and the mean a
      // free flight alone would see without the equiangular share.
      std::vector<test::ChannelMoments> moments(16);
      std::vector<glm::dvec3> meanA(16), meanB(16);
      constexpr double kStep = 2e-5;
      for (double t = 0.5 * kStep; t < kL0 + 16 * kWidth; t += kStep) {
        const glm::dvec3 p = o + dir * t;
        const double d = glm::length(light - p);
        const int b = static_cast<int>(std::floor((t + d - kL0) / kWidth));
        if (b < 0 || b >= 16) continue;
        const double phase = physics::phaseFunction(
            m.phase, m.g, static_cast<float>(glm::dot((p - light) / d, -dir)));
        const glm::dvec3 f = sigmaS * glm::exp(-sigmaT * (t + d)) * intensity * (phase / (d * d));
        const double pa = test::mixturePdf(m, t), pb = towardsLight.pdf(t);
        const glm::dvec3 w = f / (pa + pb);
        moments[b].mean += f * kStep;
        moments[b].second += glm::outerProduct(w, w) * ((pa + pb) * kStep);
        meanA[b] += pa * w * kStep;
        meanB[b] += pb * w * kStep;
      }
      for (int b = 0; b < 16; ++b) {
        test::ChannelMoments& mb = moments[b];
        mb.second += glm::outerProduct(meanA[b], meanB[b]) + glm::outerProduct(meanB[b], meanA[b]);
        const glm::dvec3 v(out.direct.at(y, x, b, 0), out.direct.at(y, x, b, 1),
                           out.direct.at(y, x, b, 2));
        chi2 += mb.chiSquare(v, kPaths);
        // Counting only one strategy's share (no MIS) is rejected.
        chi2NoMis += mb.mahalanobis(v - meanA[b], kPaths);
        dof += 3;
      }
    }
  }
  const double critical = dof + 5.0 * std::sqrt(2.0 * dof);
  std::printf("bistatic: chi-square %.1f over %d pixel-bin-channels, their covariance (critical %.1f), "
              "free-flight share alone %.0f\n", chi2, dof, critical, chi2NoMis);
  EXPECT_LT(chi2, critical);
  EXPECT_GT(chi2NoMis, critical);
}

TEST(ReferenceMediumTest, PlaneReturnIsTheVacuumReturnTimesTwoWayTransmittance) {
  // A plane 2 m below a camera with the light at its pinhole; the plane's
  // bin holds its attenuated return plus the lidar return of the medium
  // in front of it within the bin.
  scene::Scene plane = test::makePlane(6.0f, glm::vec3(0.5f, 0.4f, 0.3f));
  constexpr double kS0 = 1.0, kBin = 0.02;
  RenderJob job = monostaticJob(plane, {0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 20.0f, 8,
                                {2.0f, 1.0f, 0.5f}, 1.2, kS0, kBin, 100);
  constexpr int kPaths = 4000;
  const VolumeCollector vacuum = test::renderReference(job, singleScattering(1));
  const Medium m = medium({0.05f, 0.1f, 0.2f}, {0.15f, 0.3f, 0.05f});
  job.settings.medium = m;
  const VolumeCollector fog = test::renderReference(job, singleScattering(kPaths));
  const glm::dvec3 intensity(job.light.intensity_W_per_sr);
  const double back = 1.0 / (4.0 * M_PI);
  int checked = 0;
  double worst = 0.0;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const double r = glm::length(test::hitOnPlane(job.camera(), x, y) -
                                   glm::dvec3(job.camera().position_world));
      const int b = test::peakBin(vacuum.direct, y, x);
      const double s0 = kS0 + b * kBin;
      ASSERT_TRUE(r >= s0 - 1e-6 && r <= s0 + kBin + 1e-6) << x << "," << y;
      for (int c = 0; c < 3; ++c) {
        test::Moments expected = test::surfaceReturn(m, c, vacuum.direct.at(y, x, b, c), r);
        expected += test::lidarReturn(m, c, back, intensity[c], s0, std::min(r, s0 + kBin));
        const double z = (fog.direct.at(y, x, b, c) - expected.mean) / expected.standardError(kPaths);
        worst = std::max(worst, std::fabs(z));
        EXPECT_LT(std::fabs(z), 5.0) << x << "," << y << " channel " << c;
        // Without the medium the return would be the vacuum one: far off.
        EXPECT_GT(std::fabs(vacuum.direct.at(y, x, b, c) - expected.mean),
                  10.0 * expected.standardError(kPaths));
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 8 * 8 * 3);
  std::printf("plane return: worst |z| %.2f over %d pixel channels\n", worst, checked);
}

TEST(ReferenceMediumTest, SameBytesAcrossThreadsAndSegments) {
  test::CornerJob s(8);
  s.job.settings.medium =
      medium({0.05f, 0.1f, 0.02f}, {0.4f, 0.3f, 0.5f}, physics::PHASE_HENYEY_GREENSTEIN, 0.7f);
  ReferenceSettings settings;
  settings.bounces = 3;
  settings.samples_per_pixel = 8;
  settings.threads = 1;
  const VolumeCollector one = test::renderReference(s.job, settings);
  settings.threads = 2;
  s.job.settings.memory_budget_bytes = 8 * 1000 * 3 * 4 * 2;  // one row per segment
  const VolumeCollector two = test::renderReference(s.job, settings);
  EXPECT_EQ(one.direct.values(), two.direct.values());
  EXPECT_EQ(one.indirect.values(), two.indirect.values());
  EXPECT_GT(test::energy(one.indirect), 0.0);
}

TEST(ReferenceMediumTest, RefusesAMediumItCannotSample) {
  test::PlaneJob s;
  s.job.camera().width = s.job.camera().height = 2;
  s.job.settings.medium = medium({0.1f, 0.1f, 0.1f}, {0.1f, 0.1f, 0.1f},
                                 physics::PHASE_HENYEY_GREENSTEIN, 1.0f);
  EXPECT_THROW(test::renderReference(s.job, singleScattering(1)), InputError);
  s.job.settings.medium = medium({0.1f, -0.2f, 0.1f}, {0.1f, 0.1f, 0.1f});
  EXPECT_THROW(test::renderReference(s.job, singleScattering(1)), InputError);
  s.job.settings.medium = medium({0.1f, 0.1f, 0.1f}, {0.1f, 0.1f, 0.1f}, 7);
  EXPECT_THROW(test::renderReference(s.job, singleScattering(1)), InputError);
}

}  // namespace
}  // namespace tofsim::reference
