// Given medium points on GL (issue 40, item 3): the samples a driver hands
// the backend (IrBackend::setSurfaces) carry their whole vertex into the
// gathers (their entries of the vertex table, SurfaceMaps::load), and a
// sample whose model is not the render's (VERTEX_MEDIUM in a Lambertian
// render) keeps the gathers from folding the model (gpu::gatherDefines). GL's
// volume equals the CPU backend's (tests/cpu/MediumPointTest.cpp's closed
// form) to float rounding. Before the vertex table, GL read a medium point as
// a Lambertian surface with a zero normal: it received nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "support/GivenSamplesGlBackend.h"
#include "support/GlTestContext.h"
#include "support/MediumPoints.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/render/GlBackend.h"

namespace tofsim::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

using test::GivenSamplesGlBackend;

capture::VolumeCollector render(const test::MediumPoints& m,
                                std::unique_ptr<ir::IrBackend> backend) {
  capture::VolumeCollector volume(static_cast<int32_t>(m.points.size()), 1, m.job.settings.time,
                                  capture::kChannels);
  ir::IrRenderer(std::move(backend)).render(m.job, volume);
  return volume;
}

capture::VolumeCollector collectCpu(const test::MediumPoints& m, const ir::SurfaceImage& given) {
  auto cpu = std::make_unique<cpu::CpuBackend>(cpu::CpuBackendOptions{2, true});
  cpu->setSurfaces(std::make_unique<ir::SurfaceImage>(given), nullptr);
  return render(m, std::move(cpu));
}

capture::VolumeCollector collectGl(const test::MediumPoints& m, const ir::SurfaceImage& given) {
  return render(m, std::make_unique<GivenSamplesGlBackend>(given));
}

TransientVolume renderCpu(const test::MediumPoints& m, const ir::SurfaceImage& given) {
  return collectCpu(m, given).total();
}

TransientVolume renderGl(const test::MediumPoints& m, const ir::SurfaceImage& given) {
  return collectGl(m, given).total();
}

// Every bin of both volumes agrees to float rounding (relative 1e-5 of the
// largest value); returns the GL volume's sum.
double expectSameVolumes(const TransientVolume& gl, const TransientVolume& cpu, int points) {
  const int bins = gl.bins();
  double largest = 0.0, sum = 0.0;
  for (int x = 0; x < points; ++x)
    for (int t = 0; t < bins; ++t)
      for (int c = 0; c < 3; ++c) largest = std::max(largest, double(cpu.at(0, x, t, c)));
  EXPECT_GT(largest, 0.0);
  for (int x = 0; x < points; ++x) {
    for (int t = 0; t < bins; ++t) {
      for (int c = 0; c < 3; ++c) {
        sum += gl.at(0, x, t, c);
        EXPECT_NEAR(gl.at(0, x, t, c), cpu.at(0, x, t, c), 1e-5 * largest)
            << "point " << x << ", bin " << t << ", channel " << c;
      }
    }
  }
  return sum;
}

TEST(MediumPointGLTest, GivenMediumPointsOnGlEqualTheCpus) {
  const test::MediumPoints m;
  const ir::SurfaceImage given = m.samples(physics::VERTEX_MEDIUM, glm::vec3(0.0f));
  const TransientVolume gl = renderGl(m, given);
  expectSameVolumes(gl, renderCpu(m, given), static_cast<int>(m.points.size()));
  // And the closed form: albedo / (4 pi) * I / r^2 at every point, every side.
  for (std::size_t p = 0; p < m.points.size(); ++p) {
    const double r = glm::length(m.job.light.position_world - m.points[p]);
    for (int c = 0; c < 3; ++c) {
      double all = 0.0;
      for (int t = 0; t < gl.bins(); ++t) all += gl.at(0, static_cast<int32_t>(p), t, c);
      const double expected =
          m.albedo[c] / (4.0 * kPi) * m.job.light.intensity_W_per_sr[c] / (r * r);
      EXPECT_NEAR(all, expected, 1e-5 * expected) << "point " << p << ", channel " << c;
    }
  }
}

TEST(MediumPointGLTest, MediumAndSurfaceSamplesInOneImageEachKeepTheirModel) {
  // Point 0 a Lambertian surface facing the light (cosine 1), points 1 and 2
  // medium points, in a Lambertian render: the gathers read each model.
  const test::MediumPoints m;
  const ir::SurfaceImage given =
      m.samples(0, glm::vec3(0, 0, 1),
                {physics::VERTEX_LAMBERTIAN, physics::VERTEX_MEDIUM, physics::VERTEX_MEDIUM});
  const TransientVolume gl = renderGl(m, given);
  expectSameVolumes(gl, renderCpu(m, given), static_cast<int>(m.points.size()));
  double surface = 0.0;
  for (int t = 0; t < gl.bins(); ++t) surface += gl.at(0, 0, t, 0);
  EXPECT_NEAR(surface, m.albedo[0] / kPi * m.job.light.intensity_W_per_sr[0], 1e-5);
}

TEST(MediumPointGLTest, MediumPointsReceiveTheVplsLightOnGlAsOnTheCpu) {
  // The quad below is lit and its VPLs face up at the points: GL's indirect
  // gather takes a medium point's receiver cosine as 1 (receiverCosine), as
  // the CPU's does. Read as a surface with a zero normal it would get nothing.
  test::MediumPoints m;
  m.job.settings.indirect.enabled = true;
  m.job.settings.indirect.visibility = capture::Visibility::Exact;
  m.job.settings.time.bins = 4000;  // the VPLs' paths reach about 16 m
  const ir::SurfaceImage given = m.samples(physics::VERTEX_MEDIUM, glm::vec3(0.0f));
  const TransientVolume gl = collectGl(m, given).indirect;
  const TransientVolume cpu = collectCpu(m, given).indirect;
  for (int32_t p = 0; p < static_cast<int32_t>(m.points.size()); ++p) {
    double onGl = 0.0, onCpu = 0.0;
    for (int t = 0; t < gl.bins(); ++t) {
      for (int c = 0; c < 3; ++c) {
        onGl += gl.at(0, p, t, c);
        onCpu += cpu.at(0, p, t, c);
      }
    }
    EXPECT_GT(onCpu, 0.0) << "point " << p;
    // The backends make their VPLs each their own way (GL's RSM, the CPU's
    // traced one), so their sums agree to the VPLs' sampling, not bit for bit.
    EXPECT_NEAR(onGl, onCpu, 0.02 * onCpu) << "point " << p;
  }
}

}  // namespace
}  // namespace tofsim::render
