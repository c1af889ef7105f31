// Issue 43: a rolling scan's light beyond the direct echo (RollingScan.h,
// addRollingLight): the medium's backscatter (BeamBackscatter.h) and the
// multipath (MultipathWaveforms.h), each beam's against the scene at its
// own firing time.
//  - At rest, the rolling frame is the still frame to the byte: waveforms,
//    the backscatter's surface bins and the losses (in fog; with 2-bounce
//    multipath, seeded per beam as the still frame seeds it).
//  - Moving (the plate at 30 m/s; RollingPlate.h), each column of the
//    rolling frame is the still frame of the scene frozen at that column's
//    firing time (within float rounding of two BVHs), in fog and with the
//    multipath of the plate's corner with a still wall; the same frame with
//    the extra light traced at the turn's start (the effect off) misses
//    that by far; the plate's return in fog is at its firing-time range.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "RollingPlate.h"
#include "support/TempDir.h"
#include "tofsim/lidar/BeamBackscatter.h"
#include "tofsim/lidar/BeamPattern.h"
#include "tofsim/lidar/LidarReturns.h"
#include "tofsim/lidar/MultipathWaveforms.h"
#include "tofsim/physics/MediumPhysics.h"

namespace tofsim::lidar {
namespace {

using test::kRollRate_Hz;
using test::kRollStart_s;
using test::PlateAtTime;

capture::Medium fog() {
  capture::Medium m;
  m.sigma_s_per_m = glm::vec3(0.03f);
  m.sigma_a_per_m = glm::vec3(0.001f);
  m.phase = physics::PHASE_HENYEY_GREENSTEIN;
  m.g = 0.8f;
  return m;
}

MultipathSettings twoBounces() {
  MultipathSettings m;
  m.bounces = 2;
  m.spot_rays = 4;
  m.receiver_rays = 32;
  m.receiver_fov_rad = 0.6;  // the beams from 12 degrees on see the wall at x = 6 m
  m.vpls_per_bounce = 8;
  m.seed = 7;
  return m;
}

// A still frame of `scene`: the direct echoes, then the multipath and the
// backscatter as LidarRun adds them.
struct StillFrame {
  LidarWaveforms w;
  BeamSurfaces surfaces;
};
StillFrame stillFrame(const LidarSpec& spec, const MultipathSettings& m, const WaveformScene& scene) {
  StillFrame f{renderDirectWaveforms(spec, scene, test::rollingAxis(), 2, true), {}};
  addMultipathWaveforms(spec, m, scene, test::rollingAxis(), 2, f.w);
  f.surfaces = addBackscatter(spec, scene, test::rollingAxis(), 2, f.w);
  return f;
}

// Only the light a frame adds after its direct echoes (multipath,
// backscatter), on zero waveforms: of a still `scene`, or of a rolling scan
// of `animated` at each beam's firing time (or, heldExtra, all at the
// turn's start: the effect off).
StillFrame zeroFrame(const LidarSpec& spec) {
  StillFrame f;
  f.w.axis = test::rollingAxis();
  f.w.volume = TransientVolume(spec.azimuths(), spec.channels(), f.w.axis, {"intensity"});
  return f;
}
StillFrame stillExtra(const LidarSpec& spec, const MultipathSettings& m, const WaveformScene& scene) {
  StillFrame f = zeroFrame(spec);
  addMultipathWaveforms(spec, m, scene, f.w.axis, 2, f.w);
  f.surfaces = addBackscatter(spec, scene, f.w.axis, 2, f.w);
  return f;
}
StillFrame rollingExtra(const scene::AnimatedScene& animated, const capture::Medium& medium,
                        const LidarSpec& spec, const MultipathSettings& m, bool heldExtra) {
  PlateAtTime moving(animated, medium);
  const auto at = [&](double t) -> const WaveformScene& {
    return moving.at(heldExtra ? kRollStart_s : t);
  };
  StillFrame f = zeroFrame(spec);
  f.surfaces = addRollingLight(spec, m, at, f.w.axis, kRollStart_s, kRollRate_Hz, 2, f.w);
  return f;
}

// The largest difference of beam (ring, a)'s waveform between two frames,
// over the beam's peak in `want`.
double beamDifference(const LidarWaveforms& got, const LidarWaveforms& want, int32_t ring,
                      int32_t a) {
  const float* g = got.volume.data() + got.volume.index(ring, a, 0, 0);
  const float* w = want.volume.data() + want.volume.index(ring, a, 0, 0);
  double peak = 0.0, worst = 0.0;
  for (int32_t k = 0; k < got.axis.bins; ++k) {
    peak = std::max(peak, double(std::abs(w[k])));
    worst = std::max(worst, double(std::abs(g[k] - w[k])));
  }
  return peak > 0.0 ? worst / peak : worst;
}

class LidarRollingLightTest : public test::TempDirTest {};

TEST_F(LidarRollingLightTest, AtRestTheRollingFrameInFogWithMultipathIsTheStillFrame) {
  const scene::AnimatedScene animated = test::movingPlate(dir_, true);
  LidarSpec spec = test::rollingLidar();
  spec.elevations_deg = {-3.0, 0.0, 3.0};
  spec.backscatter.phase_at_pi_per_sr = 0.052;
  for (const MultipathSettings& m : {MultipathSettings{}, twoBounces()}) {
    PlateAtTime still(animated, fog());
    const StillFrame want = stillFrame(spec, m, still.at(kRollStart_s));
    PlateAtTime held(animated, fog());
    const auto at = [&](double) -> const WaveformScene& { return held.at(kRollStart_s); };
    LidarWaveforms got = renderRollingWaveforms(spec, at, test::rollingAxis(), kRollStart_s,
                                                kRollRate_Hz, 2, true);
    const BeamSurfaces surfaces =
        addRollingLight(spec, m, at, test::rollingAxis(), kRollStart_s, kRollRate_Hz, 2, got);
    ASSERT_EQ(got.volume.size(), want.w.volume.size());
    EXPECT_EQ(0, std::memcmp(got.volume.data(), want.w.volume.data(), got.volume.size() * 4));
    EXPECT_EQ(surfaces.raysPerBeam, want.surfaces.raysPerBeam);
    EXPECT_EQ(surfaces.bins, want.surfaces.bins);
    EXPECT_EQ(got.lost.before, want.w.lost.before);
    EXPECT_EQ(got.lost.after, want.w.lost.after);
    // The extra light is there: the fog's before the plate (bin 1000, 1.5
    // m), and the rolling frame differs from its direct echoes alone.
    EXPECT_GT(got.volume.at(1, 0, 1000, 0), 0.0f);
    const LidarWaveforms direct = renderRollingWaveforms(
        spec, at, test::rollingAxis(), kRollStart_s, kRollRate_Hz, 2, true);
    EXPECT_NE(0, std::memcmp(got.volume.data(), direct.volume.data(), got.volume.size() * 4));
  }
}

TEST_F(LidarRollingLightTest, InFogEachColumnIsTheStillFrameAtItsFiringTime) {
  const scene::AnimatedScene animated = test::movingPlate(dir_);
  LidarSpec spec = test::rollingLidar();
  spec.backscatter.phase_at_pi_per_sr = 0.052;
  const StillFrame rolling = rollingExtra(animated, fog(), spec, {}, false);
  const StillFrame held = rollingExtra(animated, fog(), spec, {}, true);
  double worst = 0.0, heldWorst = 0.0;
  int heldSurfaceMisses = 0;
  for (int32_t a = 0; a < spec.azimuths(); ++a) {
    PlateAtTime frozen(animated, fog());
    const StillFrame want =
        stillExtra(spec, {}, frozen.at(kRollStart_s + firingOffset_s(spec, a, kRollRate_Hz)));
    worst = std::max(worst, beamDifference(rolling.w, want.w, 0, a));
    heldWorst = std::max(heldWorst, beamDifference(held.w, want.w, 0, a));
    const auto R = static_cast<std::size_t>(want.surfaces.raysPerBeam);
    for (std::size_t i = a * R; i < (a + 1) * R; ++i) {  // each ray's surface where the plate was then
      EXPECT_NEAR(rolling.surfaces.bins[i], want.surfaces.bins[i], 1) << "azimuth " << a;
      heldSurfaceMisses += std::abs(held.surfaces.bins[i] - want.surfaces.bins[i]) > 1;
    }
  }
  EXPECT_LT(worst, 1e-6);
  // The effect off: the fog's light and the surfaces at the turn's start
  // (the fog from 11 m on is 0.5 % of its peak at the overlap).
  EXPECT_GT(heldWorst, 1e-3);
  EXPECT_GT(heldSurfaceMisses, 16 * 30);

  // The whole frame: the plate's return, through the fog, at its range at
  // the firing time.
  spec.returns.threshold = 1e-5;  // above the fog's bins, below the plate's
  PlateAtTime moving(animated, fog());
  const auto at = [&](double t) -> const WaveformScene& { return moving.at(t); };
  LidarWaveforms frame = renderRollingWaveforms(spec, at, test::rollingAxis(), kRollStart_s,
                                                kRollRate_Hz, 2, true);
  addRollingLight(spec, {}, at, frame.axis, kRollStart_s, kRollRate_Hz, 2, frame);
  EXPECT_GT(frame.volume.at(0, 0, 1000, 0), 0.0f);  // the fog at 1.5 m
  const LidarReturns r = lidarReturns(spec, frame, kRollRate_Hz);
  for (int32_t a = 0; a < spec.azimuths(); ++a) {
    const double t = kRollStart_s + firingOffset_s(spec, a, kRollRate_Hz);
    const double want = test::plateZ_m(t) / beamDirection(spec, 0, a).z;
    EXPECT_NEAR(r.range_m.at(0, a, 0), want, 0.01) << "azimuth " << a;
  }
}

TEST_F(LidarRollingLightTest, TheMultipathOfEachColumnIsTheStillFramesAtItsFiringTime) {
  const scene::AnimatedScene animated = test::movingPlate(dir_, true);
  const LidarSpec spec = test::rollingLidar();
  const MultipathSettings m = twoBounces();
  const StillFrame rolling = rollingExtra(animated, {}, spec, m, false);
  const StillFrame held = rollingExtra(animated, {}, spec, m, true);
  double worst = 0.0, heldWorst = 0.0, tail = 0.0;
  for (int32_t a = 0; a < spec.azimuths(); a += 4) {
    PlateAtTime frozen(animated);
    const StillFrame want =
        stillExtra(spec, m, frozen.at(kRollStart_s + firingOffset_s(spec, a, kRollRate_Hz)));
    worst = std::max(worst, beamDifference(rolling.w, want.w, 0, a));
    heldWorst = std::max(heldWorst, beamDifference(held.w, want.w, 0, a));
    for (int32_t k = 0; k < want.w.axis.bins; ++k) tail += want.w.volume.at(0, a, k, 0);
  }
  EXPECT_GT(tail, 0.0);  // the corner's multipath is there to follow
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(heldWorst, 0.1);  // the indirect tail traced at the turn's start
}

}  // namespace
}  // namespace tofsim::lidar
