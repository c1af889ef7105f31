// NLOS captures on the GL backend: the driver traces the wall points (a
// point-set imager a rasterizer cannot draw) and the GL gathers read them in
// place of a rasterized G-buffer, lit by the Lambertian laser spot. Checked
// against the hidden patch's closed form and against the CPU backend, with
// and without the last legs counted. (NLOS points are point samples; a point
// set's surface footprints are checked in tests/cpu/CpuMatchesGlGLTest.cpp.)

#include <gtest/gtest.h>

#include <cmath>

#include "nlos/DelayedWall.h"
#include "nlos/HiddenPatch.h"

namespace tofsim::pipeline {
namespace {

using namespace test;  // the hidden patch, its config and closed form

NlosVolume renderOn(config::RunConfig c, config::IrBackendKind backend, const scene::Scene& s) {
  c.backend = backend;
  return renderNlosScan(c, s, planNlosScan(c, s));
}

// Relative L1 distance of two H volumes and the largest per-point energy ratio
// off 1.
struct Agreement {
  double l1 = 0.0, worstEnergy = 0.0;
};
Agreement agreement(const NlosVolume& a, const NlosVolume& b) {
  EXPECT_EQ(a.shape, b.shape);
  double diff = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < a.H.size(); ++i) {
    diff += std::abs(double(a.H[i]) - b.H[i]);
    sum += std::abs(double(a.H[i]));
  }
  Agreement r;
  r.l1 = diff / sum;
  const std::size_t points = a.H.size() / a.axis.bins;
  for (std::size_t p = 0; p < points; ++p) {
    r.worstEnergy =
        std::max(r.worstEnergy, std::abs(measured(b, p).energy / measured(a, p).energy - 1.0));
  }
  return r;
}

TEST(NlosGlBackendGLTest, ConfocalPatchFollowsTheClosedFormAndTheCpuBackend) {
  const scene::Scene s = hiddenPatch();
  const config::RunConfig c = nlosConfig(config::NlosScan::Confocal, 256);
  const NlosVolume gl = renderOn(c, config::IrBackendKind::Gl, s);
  EXPECT_EQ(gl.backend, "gl");
  const NlosScanGeometry scan = planNlosScan(c, s);
  for (std::size_t p = 0; p < 9; ++p) {
    const Expected e = closedForm(scan.sensorPoints[p]);
    const Measured m = measured(gl, p);
    EXPECT_NEAR(m.energy / e.energy, 1.0, 0.02) << "point " << p;
    EXPECT_NEAR(m.meanPath_m, e.meanPath_m, 0.005) << "point " << p;  // half a bin
  }
  const Agreement a = agreement(renderOn(c, config::IrBackendKind::Cpu, s), gl);
  EXPECT_LT(a.l1, 1e-4);
  EXPECT_LT(a.worstEnergy, 1e-4);
}

// A single laser position lighting a 4 x 3 sensor grid, with the legs to the
// laser and sensor origins in the path (the GL gathers' uCameraUnwarp is the
// CPU's dropLastLeg_, which a point set's last_leg_counts sets).
TEST(NlosGlBackendGLTest, SingleScanWithCountedLegsIsTheCpuBackends) {
  const scene::Scene s = hiddenPatch();
  config::RunConfig c = nlosConfig(config::NlosScan::Single, 128);
  c.nlos->sensor_grid = {4, 3};
  c.render.time.bins = 400;
  c.nlos->account_first_and_last_bounces = true;
  const NlosVolume cpu = renderOn(c, config::IrBackendKind::Cpu, s);
  const NlosVolume gl = renderOn(c, config::IrBackendKind::Gl, s);
  const Agreement a = agreement(cpu, gl);
  EXPECT_LT(a.l1, 1e-4);
  EXPECT_LT(a.worstEnergy, 1e-4);
}

// A relay wall with a scattering delay: GL's RSM VPLs start from the spot's
// class (the table's row 0 is the wall's kernel), so a hidden patch's
// return meets the wall's kernel twice, as on the CPU backend: the mean
// arrival moves by 2 f tau, each histogram is GL's undelayed one through
// the kernel twice, and GL agrees with the CPU as without delays.
TEST(NlosGlBackendGLTest, ADelayedRelayWallDelaysAHiddenPatchTwiceAsOnTheCpu) {
  const config::RunConfig c = nlosConfig(config::NlosScan::Confocal, 64);
  const NlosVolume instant = renderOn(c, config::IrBackendKind::Gl, hiddenPatch());
  const scene::Scene s = hiddenPatchBehindADelayedWall();
  const NlosVolume gl = renderOn(c, config::IrBackendKind::Gl, s);
  for (std::size_t p = 0; p < 9; ++p) {
    SCOPED_TRACE("point " + std::to_string(p));
    const Measured a = measured(instant, p), b = measured(gl, p);
    EXPECT_NEAR(b.meanPath_m - a.meanPath_m, 2.0 * kWallFraction * kWallLifetime_m, 1e-4);
    EXPECT_NEAR(b.energy / a.energy, 1.0, 1e-5);
    EXPECT_LT(worstRelativeBin(gl, p, throughTheWall(instant, p, 2)), 1e-5);
  }
  const Agreement a = agreement(renderOn(c, config::IrBackendKind::Cpu, s), gl);
  EXPECT_LT(a.l1, 1e-4);
  EXPECT_LT(a.worstEnergy, 1e-4);
}

}  // namespace
}  // namespace tofsim::pipeline
