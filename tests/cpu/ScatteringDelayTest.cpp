// Scattering delays (issue 41) through the IR driver on the CPU backend,
// against closed forms at pixel centres (render.pixel_footprint: false):
// a plane whose material delays a share f by an exponential lifetime tau (the
// exact bin integrals of f exp(-(t - 2r/c)/tau)/tau after the arrival, within
// the stage's documented within-bin limit), a Gaussian delay (its mean shift
// and variance), a table kernel against the exponential it tabulates, and a
// corner whose wall alone is delayed: the floor's indirect light, all of it
// from the wall's VPLs, is the undelayed render's convolved with the kernel,
// its direct light keeps its bytes, the energy is kept, and the bounce
// volumes still add up to the indirect one exactly.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "support/TestJobs.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "RsmVpls.h"
#include "tofsim/ir/BounceVpls.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/physics/ResponseClassTable.h"
#include "tofsim/physics/TemporalResponse.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/util/Error.h"

namespace tofsim::cpu {
namespace {

using namespace capture;

// Every named component of the streamed segments, whole-image volumes
// (pixel, bin, channel).
struct Components : SegmentSink {
  explicit Components(std::size_t floatsPerPixel) : floatsPerPixel(floatsPerPixel) {}
  void consume(const Segment& segment) override {
    for (const SegmentComponent& c : segment.components) {
      std::vector<float>& v = volumes[std::string(c.name)];
      v.insert(v.end(), c.values, c.values + segment.pixelCount * floatsPerPixel);
    }
  }
  std::size_t floatsPerPixel;
  std::map<std::string, std::vector<float>> volumes;
};

struct Rendered {
  std::map<std::string, std::vector<float>> volumes;
  RenderResult result;
};

Rendered render(const RenderJob& job) {
  Components sink(static_cast<std::size_t>(job.settings.time.bins) * kChannels);
  Rendered out;
  out.result =
      ir::IrRenderer(std::make_unique<CpuBackend>(CpuBackendOptions{2, true})).render(job, sink);
  out.volumes = std::move(sink.volumes);
  return out;
}

physics::ResponseKernel exponential(double lifetime_s, double fraction) {
  physics::ResponseKernel k;
  k.model = physics::ResponseModel::Exponential;
  k.lifetime_s = lifetime_s;
  k.fraction = fraction;
  return k;
}

// (1/tau) exp(-t/tau) convolved with one bin's box, integrated over bin m
// after it (bins of 1): the stage's model of a point sample's delayed light.
double boxedExponential(double tau, int m) {
  if (m < 0) return 0.0;
  if (m == 0) return 1.0 - tau * (1.0 - std::exp(-1.0 / tau));
  return tau * (std::exp(1.0 / tau) - 1.0) * (std::exp(-m / tau) - std::exp(-(m + 1) / tau));
}

// The plane of PlaneJob, small, direct light only, at pixel centres.
struct DelayedPlane : test::PlaneJob {
  DelayedPlane() {
    job.camera().width = 8;
    job.camera().height = 6;
    job.settings.indirect.enabled = false;
    job.settings.pixel_footprint = false;
  }
  double binWidth_s() const { return job.settings.time.bin_width_s; }
};

// A pixel's only lit bin in an instant render and its energy per channel.
struct Arrival {
  int bin = -1;
  glm::dvec3 energy{0.0};
};

Arrival arrivalOf(const std::vector<float>& v, std::size_t pixel, int bins) {
  Arrival a;
  for (int n = 0; n < bins; ++n) {
    const float* h = &v[(pixel * bins + n) * kChannels];
    if (h[0] + h[1] + h[2] == 0.0f) continue;
    EXPECT_EQ(a.bin, -1) << "pixel " << pixel << ": a second lit bin " << n;
    a.bin = n;
    a.energy = glm::dvec3(h[0], h[1], h[2]);
  }
  return a;
}

TEST(ScatteringDelayTest, AnExponentialDelaysItsShareByTheLifetimesBinIntegrals) {
  DelayedPlane plane;
  const int bins = plane.job.settings.time.bins;
  const Rendered instant = render(plane.job);
  const double tau = 50.0, f = 0.6;  // tau in bins
  plane.scene.materials[0].scatteringDelay = exponential(tau * plane.binWidth_s(), f);
  const Rendered delayed = render(plane.job);
  const std::vector<float>& y = delayed.volumes.at("direct");
  const TimeAxis& axis = plane.job.settings.time;
  const int32_t width = plane.job.camera().width;
  double pastAxis = 0.0;
  for (std::size_t p = 0; p < 48; ++p) {
    SCOPED_TRACE("pixel " + std::to_string(p));
    const Arrival a = arrivalOf(instant.volumes.at("direct"), p, bins);
    ASSERT_GE(a.bin, 0);
    // The exact arrival (the light is at the camera: 2r), at fraction phi of its bin.
    const double r =
        instant.result.depth_m.at(static_cast<int32_t>(p) / width, static_cast<int32_t>(p) % width,
                                  0);
    const double t0 = (2.0 * r - axis.start_m()) / axis.bin_width_m();  // in bins
    ASSERT_EQ(static_cast<int>(std::floor(t0)), a.bin);
    const double phi = t0 - a.bin;
    // The stage keeps no sub-bin position: the exact integrals differ from
    // its bins by a factor tau (e^(1/tau) - 1) e^(-phi/tau) ~ 1 + (1/2 -
    // phi)/tau in the tail (temporal_response.md); the arrival bin's delayed
    // share by less than that times f E.
    const double limit = std::abs(phi - 0.5) / tau + 1.0 / (tau * tau);
    double total = 0.0;
    for (int n = a.bin; n < bins; ++n) {
      const int m = n - a.bin;
      const double u0 = std::max(0.0, n - t0), u1 = n + 1 - t0;  // bin n after the arrival
      const double exact = (m == 0 ? 1.0 - f : 0.0) + f * (std::exp(-u0 / tau) - std::exp(-u1 / tau));
      const double model = (m == 0 ? 1.0 - f : 0.0) + f * boxedExponential(tau, m);
      for (int c = 0; c < 3; ++c) {
        const double e = a.energy[c], got = y[(p * bins + n) * kChannels + c];
        total += got;
        ASSERT_NEAR(got, model * e, 2e-6 * e) << "bin " << n << " channel " << c;
        if (m == 0) {
          EXPECT_NEAR(got, exact * e, f * e * limit) << "arrival bin, phi " << phi;
        } else if (exact > 1e-6) {
          EXPECT_NEAR(got / (exact * e), 1.0, limit) << "bin " << n << ", phi " << phi;
        }
      }
    }
    for (int n = 0; n < a.bin; ++n) {
      EXPECT_EQ(y[(p * bins + n) * kChannels], 0.0f) << "bin " << n << " before the arrival";
    }
    // Energy kept: on the axis and past its end (the closed form of the
    // delayed share's tail past the last bin).
    const double e = a.energy[0] + a.energy[1] + a.energy[2];
    const double past = f * tau * std::expm1(1.0 / tau) * std::exp(-(bins - a.bin) / tau);
    EXPECT_NEAR(total + past * e, e, 1e-5 * e);
    pastAxis += past * e;
  }
  // The light past the axis is booked as the driver's off-axis light.
  EXPECT_NEAR(delayed.result.offAxis.after - instant.result.offAxis.after, pastAxis,
              1e-4 * pastAxis);
  EXPECT_GT(pastAxis, 0.0);
}

// Mean and variance in bin indices (bin n at n) of a pixel's histogram, and its energy.
struct Moments {
  double energy = 0.0, mean = 0.0, variance = 0.0;
};
Moments momentsOf(const std::vector<float>& v, std::size_t pixel, int bins) {
  Moments m;
  double s1 = 0.0, s2 = 0.0;
  for (int n = 0; n < bins; ++n) {
    const float* h = &v[(pixel * bins + n) * kChannels];
    const double e = double(h[0]) + h[1] + h[2];
    m.energy += e;
    s1 += e * n;
    s2 += e * double(n) * n;
  }
  m.mean = s1 / m.energy;
  m.variance = s2 / m.energy - m.mean * m.mean;
  return m;
}

TEST(ScatteringDelayTest, AGaussianDelayShiftsTheMeanByItsShareAndAddsItsVariance) {
  DelayedPlane plane;
  const int bins = plane.job.settings.time.bins;
  const Rendered instant = render(plane.job);
  const double mu = 40.0, sigma = 4.0, f = 0.5;  // bins
  physics::ResponseKernel k;
  k.model = physics::ResponseModel::Gaussian;
  k.mean_s = mu * plane.binWidth_s();
  k.sigma_s = sigma * plane.binWidth_s();
  k.fraction = f;
  plane.scene.materials[0].scatteringDelay = k;
  const Rendered delayed = render(plane.job);
  for (std::size_t p = 0; p < 48; ++p) {
    SCOPED_TRACE("pixel " + std::to_string(p));
    const Arrival a = arrivalOf(instant.volumes.at("direct"), p, bins);
    ASSERT_GE(a.bin, 0);
    const Moments m = momentsOf(delayed.volumes.at("direct"), p, bins);
    const double e = a.energy[0] + a.energy[1] + a.energy[2];
    EXPECT_NEAR(m.energy, e, 1e-5 * e);
    // The delayed share's mean is the arrival bin's plus mu exactly, its
    // variance sigma^2 + 1/6 bin^2 (the bin's box twice); a mixture with the
    // prompt share in the arrival bin.
    EXPECT_NEAR(m.mean, a.bin + f * mu, 1e-3);
    EXPECT_NEAR(m.variance, f * (sigma * sigma + 1.0 / 6.0) + f * (1.0 - f) * mu * mu, 1e-2);
    const float* arrival = &delayed.volumes.at("direct")[(p * bins + a.bin) * kChannels];
    EXPECT_NEAR(double(arrival[0]) + arrival[1] + arrival[2], (1.0 - f) * e, 1e-5 * e);
  }
}

TEST(ScatteringDelayTest, ATableOfAnExponentialRendersAsTheExponential) {
  DelayedPlane plane;
  const int bins = plane.job.settings.time.bins;
  const double tau = 50.0, f = 0.6, bin_s = plane.binWidth_s();
  const Rendered instant = render(plane.job);
  plane.scene.materials[0].scatteringDelay = exponential(tau * bin_s, f);
  const Rendered reference = render(plane.job);
  // Quarter-bin points out to 15 lifetimes: piecewise linear, the
  // exponential within h^2 / (8 tau^2) = 3e-6.
  physics::ResponseKernel table;
  table.model = physics::ResponseModel::Table;
  table.fraction = f;
  for (int j = 0; j <= static_cast<int>(15.0 * tau * 4.0); ++j) {
    const double u = 0.25 * j;
    table.tableDelay_s.push_back(u * bin_s);
    table.tableWeight.push_back(std::exp(-u / tau));
  }
  plane.scene.materials[0].scatteringDelay = table;
  const Rendered tabulated = render(plane.job);
  const std::vector<float>& a = reference.volumes.at("direct");
  const std::vector<float>& b = tabulated.volumes.at("direct");
  ASSERT_EQ(a.size(), b.size());
  double peak = 0.0;
  for (const float v : a) peak = std::max(peak, double(v));
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(double(b[i]) - a[i]) / (double(a[i]) + 1e-4 * peak));
  }
  EXPECT_LT(worst, 1e-3);
  // and that is the exponential's: the prompt share and tap 0 in the arrival bin.
  for (std::size_t p = 0; p < 48; ++p) {
    const Arrival at = arrivalOf(instant.volumes.at("direct"), p, bins);
    ASSERT_GE(at.bin, 0);
    const double e = at.energy[0] + at.energy[1] + at.energy[2];
    const float* y = &b[(p * bins + at.bin) * kChannels];
    EXPECT_NEAR(double(y[0]) + y[1] + y[2], (1.0 - f + f * boxedExponential(tau, 0)) * e, 1e-4 * e)
        << "pixel " << p;
  }
}

// A corner (floor y = 0, wall z = 0) seen from above the floor: every pixel
// sees the floor, whose indirect light all comes from the wall's VPLs (the
// floor's own cannot light it).
struct FloorView {
  scene::Scene scene = test::makeCorner(glm::vec3(0.7f, 0.6f, 0.5f), glm::vec3(0.3f, 0.8f, 0.4f));
  RenderJob job;
  FloorView() {
    job.scene = &scene;
    job.camera().position_world = {0.0f, 1.5f, 2.5f};
    job.camera().look_at_world = {0.0f, 0.0f, 1.2f};
    job.camera().fov_y_deg = 30.0f;
    job.camera().width = job.camera().height = 12;
    job.light.position_world = {0.3f, 1.2f, 1.0f};
    job.light.intensity_W_per_sr = glm::vec3(3.0f);
    job.settings.time = TimeAxis{0.0, 0.01 / kSpeedOfLight_m_per_s, 1000};
    job.settings.pixel_footprint = false;
    job.settings.indirect.rsm_resolution = 32;
    job.settings.indirect.visibility = Visibility::Exact;
  }
};

bool sameBytes(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// y = the stage's exponential filter of x (`times` times), per pixel and
// channel, in double (the tail past 30 lifetimes dropped).
std::vector<double> convolved(const std::vector<float>& x, int bins, double tau, double f,
                              int times) {
  std::vector<double> taps(static_cast<std::size_t>(30.0 * tau));
  for (std::size_t j = 0; j < taps.size(); ++j) {
    taps[j] = f * boxedExponential(tau, static_cast<int>(j));
  }
  std::vector<double> in(x.begin(), x.end()), out(x.size());
  for (int t = 0; t < times; ++t) {
    for (std::size_t i = 0; i < in.size(); ++i) out[i] = (1.0 - f) * in[i];
    for (std::size_t p = 0; p < x.size() / (bins * kChannels); ++p) {
      for (int m = 0; m < bins; ++m) {
        for (int c = 0; c < 3; ++c) {
          const double v = in[(p * bins + m) * kChannels + c];
          if (v == 0.0) continue;
          const int last = std::min<int>(bins, m + static_cast<int>(taps.size()));
          for (int n = m; n < last; ++n) out[(p * bins + n) * kChannels + c] += taps[n - m] * v;
        }
      }
    }
    in = out;
  }
  return out;
}

void expectConvolved(const std::vector<float>& got, const std::vector<double>& expected,
                     int bins) {
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t p = 0; p < got.size() / (bins * kChannels); ++p) {
    double energy = 0.0, gotEnergy = 0.0;
    for (int i = 0; i < bins * kChannels; ++i) {
      energy += expected[p * bins * kChannels + i];
      gotEnergy += got[p * bins * kChannels + i];
    }
    ASSERT_GT(energy, 0.0) << "pixel " << p << " has indirect light";
    EXPECT_NEAR(gotEnergy, energy, 1e-5 * energy) << "pixel " << p;
    for (int i = 0; i < bins * kChannels; ++i) {
      const double e = expected[p * bins * kChannels + i];
      ASSERT_NEAR(got[p * bins * kChannels + i], e, 1e-4 * std::abs(e) + 1e-6 * energy)
          << "pixel " << p << " bin " << i / kChannels;
    }
  }
}

class DelayedWallTest : public ::testing::TestWithParam<bool> {};

TEST_P(DelayedWallTest, TheFloorsIndirectLightIsTheUndelayedConvolvedWithTheWallsKernel) {
  FloorView view;
  view.job.settings.pixel_footprint = GetParam();
  const int bins = view.job.settings.time.bins;
  const double tau = 20.0, f = 0.7;
  const Rendered instant = render(view.job);
  view.scene.materials[1].scatteringDelay =
      exponential(tau * view.job.settings.time.bin_width_s, f);
  const Rendered delayed = render(view.job);
  for (std::size_t p = 0; p < 144; ++p) {
    ASSERT_GT(instant.result.depth_m.at(static_cast<int32_t>(p / 12), static_cast<int32_t>(p % 12), 0),
              0.0f);
  }
  EXPECT_TRUE(sameBytes(delayed.volumes.at("direct"), instant.volumes.at("direct")));
  expectConvolved(delayed.volumes.at("indirect"),
                  convolved(instant.volumes.at("indirect"), bins, tau, f, 1), bins);
}

INSTANTIATE_TEST_SUITE_P(PointSamplesAndFootprint, DelayedWallTest, ::testing::Bool());

TEST(ScatteringDelayTest, BounceVolumesOfADelayedWallStillAddUpToTheIndirectOne) {
  FloorView view;
  const int bins = view.job.settings.time.bins;
  const double tau = 20.0, f = 0.7;
  const Rendered instant = render(view.job);  // one bounce
  view.job.settings.indirect.bounces = 2;
  view.job.settings.indirect.vpls_per_bounce = 500;
  view.scene.materials[1].scatteringDelay =
      exponential(tau * view.job.settings.time.bin_width_s, f);
  const Rendered r = render(view.job);
  // Bounce 1 is the wall VPLs' light, delayed by the wall's kernel.
  expectConvolved(r.volumes.at("bounce1"), convolved(instant.volumes.at("indirect"), bins, tau, f, 1),
                  bins);
  const std::vector<float>& b1 = r.volumes.at("bounce1");
  const std::vector<float>& b2 = r.volumes.at("bounce2");
  std::vector<float> sum(b1.size());
  for (std::size_t i = 0; i < sum.size(); ++i) sum[i] = b1[i] + b2[i];
  EXPECT_TRUE(sameBytes(sum, r.volumes.at("indirect")));
  double second = 0.0;
  for (const float v : b2) second += v;
  EXPECT_GT(second, 0.0);
}

// Every VPL's class (flux.w): a first-bounce VPL's is its surface's kernel, a
// later one's its parent's then its own surface's. With the wall alone
// delayed (base kernel 1; neither plane lights itself, so a child's parent
// is on the other plane): bounce 1 on the wall {1}, on the floor {}; bounce
// 2 all {1} (floor children of wall parents, wall children of floor
// parents); bounce 3 on the floor {1}, on the wall {1, 1}.
TEST(ScatteringDelayTest, EachVplsClassIsItsParentsThenItsSurfaces) {
  FloorView view;
  view.scene.materials[1].scatteringDelay = exponential(1e-10, 0.5);
  const physics::ResponseClassTable table =
      physics::ResponseClassTable::build(ir::materialResponses(view.scene).kernels, 3);
  ASSERT_EQ(table.classCount(), 4u);  // {}, {1}, {1, 1}, {1, 1, 1}
  const rays::RayScene rays(view.scene, 1);
  std::vector<ir::Vpl> first =
      traceRsmVpls(rays, view.job.light, 16, 1, 1.0, physics::VERTEX_LAMBERTIAN, 1, std::nullopt,
                   &table);
  view.job.settings.indirect.bounces = 3;
  view.job.settings.indirect.vpls_per_bounce = 400;
  const ir::BouncedVpls b = ir::withLaterBounces(view.job, rays, first, &table);
  const float expected[3][2] = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 2.0f}};  // [bounce][on wall]
  for (int32_t k = 1; k <= 3; ++k) {
    std::size_t onWall = 0;
    for (std::size_t i = b.firstOfBounce[k - 1]; i < b.firstOfBounce[k]; ++i) {
      const bool wall = b.vpls[i].normal.z > 0.5f;
      onWall += wall;
      EXPECT_EQ(b.vpls[i].flux.w, expected[k - 1][wall]) << "bounce " << k << ", VPL " << i;
    }
    EXPECT_GT(onWall, 0u) << "bounce " << k;
    EXPECT_LT(onWall, b.countOf(k)) << "bounce " << k;
  }
}

// Over 64 classes the render stops with an InputError that names the setting.
TEST(ScatteringDelayTest, TooManyResponseClassesAreAnInputError) {
  DelayedPlane plane;
  plane.job.settings.indirect.enabled = true;
  for (int i = 0; i < 10; ++i) {
    scene::Material m = plane.scene.materials[0];
    m.name = "delayed" + std::to_string(i);
    m.scatteringDelay = exponential((i + 1) * 1e-10, 0.5);
    plane.scene.materials.push_back(m);
  }
  try {
    render(plane.job);  // 1 + 10 + 55 classes on paths of two delayed vertices
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("render.indirect.bounces"), std::string::npos) << e.what();
  }
}

// Two delayed vertices on a path: the floor and the wall share one kernel and
// the camera sees the wall, whose indirect light all comes from the floor's
// VPLs (class {k, k}): the undelayed render's convolved with the kernel
// twice; its direct light (class {k}) once. Needs the cascade stage of
// issue 41 (stage41): with the interim one-stage-per-class path
// (physics::singleStages) a class of two members is filtered once.
TEST(ScatteringDelayTest, TwoDelayedVerticesOnAPathConvolveTheKernelWithItself) {
  FloorView view;
  view.job.camera().position_world = {0.0f, 1.2f, 2.0f};
  view.job.camera().look_at_world = {0.0f, 1.2f, 0.0f};
  const int bins = view.job.settings.time.bins;
  const double tau = 20.0, f = 0.7;
  const Rendered instant = render(view.job);
  const physics::ResponseKernel k = exponential(tau * view.job.settings.time.bin_width_s, f);
  view.scene.materials[0].scatteringDelay = k;
  view.scene.materials[1].scatteringDelay = k;
  const Rendered delayed = render(view.job);
  expectConvolved(delayed.volumes.at("direct"),
                  convolved(instant.volumes.at("direct"), bins, tau, f, 1), bins);
  expectConvolved(delayed.volumes.at("indirect"),
                  convolved(instant.volumes.at("indirect"), bins, tau, f, 2), bins);
}

}  // namespace
}  // namespace tofsim::cpu
