// Capture sequences (`sequence:`) through runRender on the CPU backend: a
// plane at d(t) = d0 + v t along the camera's axis (a glTF translation
// channel, LINEAR). Each frame's first surface and direct arrival are at
// d(t_k) and 2 d(t_k) / c; a CW-ToF camera whose raws are taken one after
// another (integration_time) gives the N-step estimator's closed-form motion
// phase, sum over raws of A_n cos(phi_n - theta_n) with each raw's own
// distance; a one-frame sequence of a still pose with integration_time 0 is
// the static render byte for byte; an interrupted sequence resumes at the
// missing frame with the same bytes; bad sequences are located errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "MovingPlaneTest.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/RenderRun.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {
namespace {

using namespace test_sequence;
using SequenceRunTest = MovingPlaneTest;

TEST_F(SequenceRunTest, EachFrameSeesThePlaneAtItsOwnTime) {
  const double v = 1.0;
  writeScene(v);
  const fs::path out = run(config("sequence: {times: [0 s, 0.5 s, 1 s]}\n", kTime), "seq");
  const io::NpyArray depths = io::readNpy(out / "depth_sequence.npy");
  ASSERT_EQ(depths.shape, (io::NpyShape{3, 8, 8}));
  for (int k = 0; k < 3; ++k) {
    const double d = (kD0 + v * 0.5 * k) * kOffAxis;
    const fs::path frame = out / ("frame_0000" + std::to_string(k));
    const io::NpyArray transient = io::readNpy(frame / "transient.npy");  // (H, W, T, C)
    const std::size_t T = transient.shape.at(2), C = transient.shape.at(3);
    std::size_t peak = 0;
    for (std::size_t t = 0; t < T; ++t) {
      if (transient.data[(kCentre * T + t) * C] > transient.data[(kCentre * T + peak) * C])
        peak = t;
    }
    const auto expected = static_cast<std::size_t>(std::floor((2.0 * d / kC - 13e-9) / 10e-12));
    EXPECT_EQ(peak, expected) << "frame " << k;
    EXPECT_NEAR(depths.data[k * 64 + kCentre], d, 1e-5) << "frame " << k;
    EXPECT_EQ(bytesOf(frame / "depth.npy").substr(128),
              std::string(reinterpret_cast<const char*>(depths.data.data() + k * 64), 64 * 4));
  }
}

const std::string kCwTof =
    "{type: cwtof, name: cwtof, frequencies: [\"20 MHz\"], phase_steps: 4, waveform: sine, "
    "channel_weights: [1, 1, 1], source_scale: 10000, ambient: 100, shot_noise: false, "
    "read_noise: 0";

TEST_F(SequenceRunTest, StillOneFrameSequenceIsTheStaticRenderByteForByte) {
  writeScene(0.0);
  const config::RunConfig still = config("sequence: {times: [0.25 s]}\n", kTime, kCwTof + "}");
  const fs::path seq = run(still, "seq");
  config::RunConfig staticConfig = still;
  staticConfig.sequence.reset();
  const fs::path one = run(staticConfig, "static");
  for (const char* f : {"transient.npy", "depth.npy", "sensors/cwtof/cwtof_raw.npy",
                        "sensors/cwtof/cwtof_phase.npy"}) {
    const std::string a = bytesOf(seq / "frame_00000" / f);
    EXPECT_FALSE(a.empty()) << f;
    EXPECT_EQ(a, bytesOf(one / f)) << f;
  }
  // Raws taken at once move nothing: no motion error to write.
  EXPECT_FALSE(fs::exists(seq / "frame_00000/sensors/cwtof/cwtof_motion_error.exr"));
}

// Raw n (capture position n) integrates over [n T, (n + 1) T) and is sampled
// at its middle, t_n = (n + 1/2) T: the pixel's ray meets the plane at r_n =
// (d0 + v t_n) kOffAxis. With C_n = E_n (1 + cos(phi_n - theta_n)) + ambient,
// E_n ~ 1 / r_n^2 (a co-located point light), phi_n = 4 pi f r_n / c,
// theta_n = 2 pi n / N, the N-step estimator's phase is
// atan2(sum C_n sin theta_n, sum C_n cos theta_n): the DC part moves with the
// plane too and does not cancel.
TEST_F(SequenceRunTest, CwTofRawsTakenInTurnGiveTheClosedFormMotionPhase) {
  const double v = 10.0, T = 1e-3, f = 20e6;
  writeScene(v);
  const std::string time = "{start: 13.2 ns, bin_width: 1 ps, bins: 500}";
  const fs::path out = run(
      config("sequence: {times: [0 s]}\n", time, kCwTof + ", integration_time: 1 ms}"), "moving");
  const io::NpyArray phase = io::readNpy(out / "frame_00000/sensors/cwtof/cwtof_phase.npy");
  double s = 0.0, c = 0.0;
  for (int n = 0; n < 4; ++n) {
    const double r = (kD0 + v * (n + 0.5) * T) * kOffAxis, theta = 2.0 * std::numbers::pi * n / 4.0;
    const double C = (1.0 + std::cos(4.0 * std::numbers::pi * f * r / kC - theta)) / (r * r);
    s += C * std::sin(theta);
    c += C * std::cos(theta);
  }
  double expected = std::atan2(s, c);
  if (expected < 0.0) expected += 2.0 * std::numbers::pi;
  const double still = 4.0 * std::numbers::pi * f * kD0 * kOffAxis / kC;  // held at t = 0
  const double got = phase.data.at(kCentre);

  EXPECT_NEAR(got, expected, 1e-4);
  // The motion moves the phase by 25 times the tolerance: the test fails
  // when the raws are all taken at the frame's time.
  EXPECT_GT(std::fabs(expected - still), 25e-4);
  // cwtof_motion_error: the depth of that phase - the still plane's.
  const double perRad = kC / (4.0 * std::numbers::pi * f);  // metres of depth per radian
  const Image motion = io::readExr(out / "frame_00000/sensors/cwtof/cwtof_motion_error.exr");
  EXPECT_NEAR(motion.data.at(kCentre), (expected - still) * perRad, 1e-4 * perRad);
  // The ground truth is the frame's own time: the plane at d0.
  EXPECT_NEAR(io::readNpy(out / "frame_00000/depth.npy").data.at(kCentre), kD0 * kOffAxis, 1e-5);
}

TEST_F(SequenceRunTest, AnInterruptedSequenceResumesWithTheSameBytes) {
  writeScene(1.0);
  const config::RunConfig c = config("sequence: {rate: 2 Hz, count: 3}\n", kTime, kCwTof + "}");
  const fs::path out = run(c, "seq");
  const std::string frame1 = bytesOf(out / "frame_00001/sensors/cwtof/cwtof_raw.npy");
  const auto kept = fs::last_write_time(out / "frame_00000/frame.json");
  fs::remove_all(out / "frame_00001");
  run(c, "seq");
  EXPECT_EQ(bytesOf(out / "frame_00001/sensors/cwtof/cwtof_raw.npy"), frame1);
  EXPECT_EQ(fs::last_write_time(out / "frame_00000/frame.json"), kept);  // not rendered again
  // Another frame's noise draws from its own seed: frames differ in noise.
  config::RunConfig noisy = c;
  std::get<sensors::CwTofParams>(noisy.sensors[0].params).shot_noise = true;
  const fs::path n = run(noisy, "noisy");
  const io::NpyArray a = io::readNpy(n / "frame_00000/sensors/cwtof/cwtof_raw.npy");
  const io::NpyArray b = io::readNpy(n / "frame_00002/sensors/cwtof/cwtof_raw.npy");
  EXPECT_NE(a.data, b.data);
}

TEST_F(SequenceRunTest, BadSequencesAreLocatedErrors) {
  writeScene(1.0);
  const auto has = [](const std::string& e, const std::string& part) {
    return e.find(part) != std::string::npos;
  };
  std::string e = errorOf("sequence: {rate: 30 Hz, count: 0}\n");
  EXPECT_TRUE(has(e, "c.yaml:7") && has(e, "sequence.count")) << e;
  e = errorOf("sequence: {times: [0 s, 0.5 s, 0.5 s]}\n");
  EXPECT_TRUE(has(e, "c.yaml:7") && has(e, "must increase")) << e;
  e = errorOf("sequence: {times: []}\n");
  EXPECT_TRUE(has(e, "c.yaml:7") && has(e, "at least one frame")) << e;
  e = errorOf("sequence: {rate: 30 Hz}\n");
  EXPECT_TRUE(has(e, "c.yaml:7") && has(e, "needs `rate` and `count`")) << e;
  e = errorOf("sequence: {times: [0 s, 2 s]}\n");
  EXPECT_TRUE(has(e, "c.yaml:7") && has(e, "frame 1 at 2") && has(e, "outside")) << e;
  e = errorOf("sequence: {times: [0 s], rate: 3 Hz}\n");
  EXPECT_TRUE(has(e, "sequence.rate") && has(e, "not with `times`")) << e;
  // Issue 39: a rate of 1e-300 Hz printed a frame time of 300 digits; frame
  // times are bounded (+-1e9 s) and said in readable units.
  e = errorOf("sequence: {rate: 1e-300 Hz, count: 2}\n");
  EXPECT_TRUE(has(e, "sequence.rate") && has(e, "1e+300 s") && has(e, "+-1e+09 s")) << e;
  EXPECT_LT(e.size(), 300u) << e;
  // Issue 39: sequence.mp4 is made of steady images; without them (this
  // config has output.steady: false) asking for it is an error, not silence.
  e = errorOf("sequence: {times: [0 s], video: true}\n");
  EXPECT_TRUE(has(e, "c.yaml:7") && has(e, "sequence.video") && has(e, "output.steady")) << e;
  // A scene without animations has nothing to play.
  test::writeText(dir_ / "plane.gltf", test::AnimatedGltf().json(R"([{"mesh": 0}])", "[0]"));
  e = errorOf("sequence: {times: [0 s]}\n");
  EXPECT_TRUE(has(e, "c.yaml:7") && has(e, "no animation")) << e;
}

}  // namespace
}  // namespace tofsim::pipeline
