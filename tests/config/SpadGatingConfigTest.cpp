// The config side of the SPAD's gate shape, gated 1-bit frames, TDC
// non-linearity and dark count map: located errors (file:line:col, key)
// before anything is rendered or written.

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/io/Npy.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/util/Error.h"

namespace tofsim::config {
namespace {

// 32 x 24 pixels, a TDC window of 100 bins of 1 ps from 1 ns (the render's).
const char* kRun = R"(scene: scene.gltf
camera:
  position: [0, 0, 2]
  look_at: [0, 0, 0]
  fov_y: 45 deg
  resolution: [32, 24]
light:
  type: spot
  position: [0, 1, 2]
  direction: [0, 0, -1]
  cone_angle: 0.5 rad
  intensity: [1, 2, 3]
time:
  start: 1 ns
  bin_width: 1 ps
  bins: 100
sensors:
  - type: spad
)";

class SpadGatingConfigTest : public test::TempDirTest {
 protected:
  std::filesystem::path write(const std::string& spadKeys) {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    const auto path = dir_ / "test.yaml";
    std::ofstream(path) << kRun << spadKeys;
    return path;
  }
  sensors::SpadParams load(const std::string& spadKeys) {
    const RunConfig c = loadRunConfig(write(spadKeys));
    return std::get<sensors::SpadParams>(c.sensors.front().params);
  }
  std::string errorOf(const std::string& spadKeys) {
    try {
      loadRunConfig(write(spadKeys));
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no error for:\n" << spadKeys;
    return "";
  }
  void expectError(const std::string& spadKeys, const std::string& key, const std::string& words) {
    const std::string message = errorOf(spadKeys);
    EXPECT_NE(message.find("test.yaml:"), std::string::npos) << message;
    EXPECT_NE(message.find("sensors[0]." + key + ": "), std::string::npos) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
  }
};

TEST_F(SpadGatingConfigTest, GateShapeNeedsAGateAndRampsThatDoNotOverlap) {
  const sensors::SpadParams p = load(
      "    gate_start: 1.01 ns\n    gate_width: 50 ps\n    gate_rise: 10 ps\n"
      "    gate_fall: 6 ps\n    gate_skew_sigma: 2 ps\n    fpn_seed: 3\n");
  EXPECT_DOUBLE_EQ(p.gate_rise_s, 10e-12);
  EXPECT_DOUBLE_EQ(p.gate_fall_s, 6e-12);
  EXPECT_DOUBLE_EQ(p.gate_skew_sigma_s, 2e-12);
  expectError("    gate_rise: 10 ps\n", "gate_rise", "set `gate_width`");
  expectError("    gate_skew_sigma: 1 ps\n", "gate_skew_sigma", "set `gate_width`");
  expectError(
      "    gate_start: 1.01 ns\n    gate_width: 10 ps\n    gate_rise: 15 ps\n"
      "    gate_fall: 6 ps\n",
      "gate_rise", "ramps overlap");
  expectError("    gate_start: 1.01 ns\n    gate_width: 10 ps\n    gate_rise: -1 ps\n", "gate_rise",
              "must be >= 0");
}

TEST_F(SpadGatingConfigTest, GatedFramesNeedAGateAndASweepInsideTheWindow) {
  const sensors::SpadParams p = load(
      "    gate_start: 1.01 ns\n    gate_width: 20 ps\n    gated_frames: 255\n"
      "    pulses_per_frame: 40\n    gate_step: 1 ps\n    gate_positions: 30\n"
      "    counter_bits: 8\n");
  EXPECT_EQ(p.gated_frames, 255);
  EXPECT_EQ(p.pulses_per_frame, 40);
  EXPECT_DOUBLE_EQ(p.gate_step_s, 1e-12);
  EXPECT_EQ(p.gate_positions, 30);
  EXPECT_EQ(p.counter_bits, 8);
  expectError("    gated_frames: 10\n", "gated_frames", "need a gate");
  expectError("    gate_positions: 10\n", "gate_positions", "set `gated_frames`");
  expectError("    pulses_per_frame: 10\n", "pulses_per_frame", "set `gated_frames`");
  expectError("    counter_bits: 40\n", "counter_bits", "must be in [0, 32]");
  // The window is [1, 1.1) ns: the 100th position of 1 ps steps from 1.09 ns is outside.
  expectError(
      "    gate_start: 1.09 ns\n    gate_width: 5 ps\n    gated_frames: 10\n"
      "    gate_step: 1 ps\n    gate_positions: 100\n",
      "gate_step", "last gate position");
}

}  // namespace
}  // namespace tofsim::config
