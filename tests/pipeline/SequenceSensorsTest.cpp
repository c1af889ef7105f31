// Sensors over time in a capture sequence, and its motion ground truth, on
// the moving plane of MovingPlaneTest.h (d(t) = d0 + v t along the axis):
// - a SPAD whose cycles spread over exposure_time sees the plane at every
//   distance it takes within the exposure: the counts' mean arrival and
//   spread are those of the exposure's samples (arrivals 2 d(t_m) / c,
//   weighted by the 1 / d^2 falloff), not the frame time's single peak;
// - a scanning streak camera (row_time) records row i at i row_time: each
//   row's streak shows the plane where it was at its own time;
// - scene flow and optical flow to the next frame: the plane's point moves
//   by (0, 0, -v dt), and its image towards the centre by the ratio of
//   depths, (x - c)(d0 / d1 - 1) pixels;
// - each frame's bytes are the same across threads and memory budgets.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "MovingPlaneTest.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"

namespace tofsim::pipeline {
namespace {

using namespace test_sequence;
using SequenceSensorsTest = MovingPlaneTest;

struct Moments {
  double total = 0.0, mean_s = 0.0, sd_s = 0.0;
};

// Of a histogram on the axis start + (i + 1/2) width.
Moments momentsOf(const float* h, std::size_t bins, double start_s, double width_s,
                  std::size_t stride = 1) {
  Moments m;
  double s1 = 0.0, s2 = 0.0;
  for (std::size_t i = 0; i < bins; ++i) {
    const double t = start_s + (i + 0.5) * width_s, w = h[i * stride];
    m.total += w;
    s1 += w * t;
    s2 += w * t * t;
  }
  m.mean_s = s1 / m.total;
  m.sd_s = std::sqrt(std::max(0.0, s2 / m.total - m.mean_s * m.mean_s));
  return m;
}

const std::string kSpad =
    "{type: spad, name: spad, mode: free_running, cycles: 100000, pde: 1, "
    "channel_weights: [1, 1, 1], source_scale: 2000";

TEST_F(SequenceSensorsTest, SpadCyclesSpreadOverTheExposureSeeThePlaneMove) {
  const double v = 1.0, exposure = 0.1;
  const int S = 8;
  writeScene(v);
  const std::string seq = "sequence: {times: [0 s], exposure_samples: 8}\n";
  const fs::path moving = run(config(seq, kTime, kSpad + ", exposure_time: 100 ms}"), "moving");
  const fs::path still = run(config(seq, kTime, kSpad + "}"), "still");
  const auto centre = [](const fs::path& out) {
    const io::NpyArray c = io::readNpy(out / "frame_00000/sensors/spad/spad_counts.npy");
    const std::size_t T = c.shape.at(2);
    return momentsOf(c.data.data() + kCentre * T, T, 13e-9, 10e-12);
  };
  const Moments m = centre(moving), s = centre(still);
  ASSERT_GT(m.total, 2e4);  // enough counts for the moments below
  // The exposure's samples: arrivals tau_m, weights 1 / d_m^2.
  double w = 0.0, w1 = 0.0, w2 = 0.0;
  for (int k = 0; k < S; ++k) {
    const double d = (kD0 + v * (k + 0.5) / S * exposure) * kOffAxis, tau = 2.0 * d / kC;
    w += 1.0 / (d * d);
    w1 += tau / (d * d);
    w2 += tau * tau / (d * d);
  }
  const double mean = w1 / w, sd = std::sqrt(w2 / w - mean * mean);
  EXPECT_NEAR(m.mean_s, mean, 10e-12);  // one bin
  EXPECT_NEAR(m.sd_s, sd, 0.05 * sd);
  // At the frame's time alone the plane is at d0: 33 bins earlier, one peak.
  EXPECT_NEAR(s.mean_s, 2.0 * kD0 * kOffAxis / kC, 10e-12);
  EXPECT_LT(s.sd_s, 10e-12);
  EXPECT_GT(mean - s.mean_s, 30 * 10e-12);
  // The sensor's JSON says when it took the light.
  const nlohmann::json doc =
      nlohmann::json::parse(std::ifstream(moving / "frame_00000/sensors/spad/spad_counts.json"));
  ASSERT_EQ(doc.at("sensor").at("sample_times_s").size(), 8u);
  EXPECT_DOUBLE_EQ(doc.at("sensor").at("sample_times_s")[0].get<double>(), 0.5 / 8 * 0.1);
}

const std::string kStreak =
    "{type: streak, name: streak, rows: [1, 4, 6], shot_noise: false, channel_weights: [1, 1, 1], "
    "saturation: 1e30";

TEST_F(SequenceSensorsTest, AScanningStreakCameraRecordsEachRowAtItsOwnTime) {
  const double v = 1.0;
  writeScene(v);
  const std::string seq = "sequence: {times: [0 s]}\n";
  const fs::path scan = run(config(seq, kTime, kStreak + ", row_time: 250 ms}"), "scan");
  const fs::path still = run(config(seq, kTime, kStreak + "}"), "still");
  const int rows[] = {1, 4, 6};
  for (int i = 0; i < 3; ++i) {
    const std::string name =
        "frame_00000/sensors/streak/streak_row00" + std::to_string(rows[i]) + ".exr";
    const auto peakAt = [&](const fs::path& out) {
      const Image image = io::readExr(out / name);  // (T, W)
      const auto T = static_cast<std::size_t>(image.height);
      const auto W = static_cast<std::size_t>(image.width);
      std::size_t peak = 0;
      for (std::size_t t = 0; t < T; ++t) {
        if (image.data[t * W + 4] > image.data[peak * W + 4]) peak = t;
      }
      return peak;
    };
    const auto binOf = [&](double d) {
      return static_cast<std::size_t>(
          std::floor((2.0 * d * offAxis(4, rows[i]) / kC - 13e-9) / 10e-12));
    };
    EXPECT_EQ(peakAt(scan), binOf(kD0 + v * 0.25 * i)) << "row " << rows[i];
    EXPECT_EQ(peakAt(still), binOf(kD0)) << "row " << rows[i];
  }
  const nlohmann::json doc =
      nlohmann::json::parse(std::ifstream(scan / "frame_00000/sensors/streak/streak_row006.json"));
  EXPECT_EQ(doc.at("sensor").at("sample_times_s"), nlohmann::json({0.0, 0.25, 0.5}));
}

TEST_F(SequenceSensorsTest, SceneAndOpticalFlowToTheNextFrameAreThePlanesMotion) {
  const double v = 1.0, dt = 0.5;
  writeScene(v);
  const fs::path out = run(config("sequence: {times: [0 s, 0.5 s]}\n", kTime), "seq");
  const io::NpyArray scene = io::readNpy(out / "frame_00000/scene_flow.npy");
  const io::NpyArray optical = io::readNpy(out / "frame_00000/optical_flow.npy");
  ASSERT_EQ(scene.shape, (io::NpyShape{8, 8, 3}));
  ASSERT_EQ(optical.shape, (io::NpyShape{8, 8, 2}));
  const double ratio = kD0 / (kD0 + v * dt) - 1.0;  // the image's scale about its centre, less 1
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * 8 + x;
      EXPECT_NEAR(scene.data[i * 3 + 0], 0.0, 1e-5);
      EXPECT_NEAR(scene.data[i * 3 + 1], 0.0, 1e-5);
      EXPECT_NEAR(scene.data[i * 3 + 2], -v * dt, 1e-5);
      EXPECT_NEAR(optical.data[i * 2 + 0], (x - 3.5) * ratio, 1e-4) << x << ", " << y;
      EXPECT_NEAR(optical.data[i * 2 + 1], (y - 3.5) * ratio, 1e-4) << x << ", " << y;
    }
  }
  // The last frame has no next frame to move to.
  EXPECT_FALSE(fs::exists(out / "frame_00001/scene_flow.npy"));
  const nlohmann::json record =
      nlohmann::json::parse(std::ifstream(out / "frame_00000/frame.json"));
  EXPECT_EQ(record.at("motion_to_time_s"), 0.5);
}

// Each frame's bytes, the sensors' over their sample times included, do not
// depend on the threads or on how the memory budget cuts the volume.
TEST_F(SequenceSensorsTest, FramesAreTheSameBytesAcrossThreadsAndMemoryBudgets) {
  writeScene(1.0);
  const std::string seq = "sequence: {times: [0 s, 0.5 s], exposure_samples: 2}\n";
  const config::RunConfig c =
      config(seq, kTime, kSpad + ", exposure_time: 100 ms, plot_pixels: [[4, 4]]}");
  const fs::path a = run(c, "a");
  config::RunConfig other = c;
  other.cpu_threads = 1;
  other.render.memory_budget_bytes = 64 << 10;  // a few rows of the 8 x 8 x 800 x 3 volume at once
  const fs::path b = run(other, "b");
  for (const char* f :
       {"frame_00000/transient.npy", "frame_00001/transient.npy",
        "frame_00000/sensors/spad/spad_counts.npy", "frame_00001/sensors/spad/spad_counts.npy",
        "frame_00000/scene_flow.npy", "frame_00000/optical_flow.npy", "depth_sequence.npy"}) {
    const std::string bytes = bytesOf(a / f);
    EXPECT_FALSE(bytes.empty()) << f;
    EXPECT_EQ(bytes, bytesOf(b / f)) << f;
  }
}

}  // namespace
}  // namespace tofsim::pipeline
