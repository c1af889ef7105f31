#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "ConfigNode.h"
#include "SensorConfigType.h"
#include "tofsim/config/SensorConfig.h"

namespace tofsim::config {
namespace {

using namespace tofsim::sensors;

std::vector<SensorSpec> parse(const std::string& text) {
  const ConfigNode root(YAML::Load(text), "test.yaml");
  return parseSensors(root.child("sensors"));
}

/// The message of the InputError that parsing `text` throws ("" if none).
std::string errorOf(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The config side of the descriptors: a parameter struct without parse, emit
// and checkImage fails the check SensorConfigType.h makes for SensorParams.
struct UndescribedParams {};
static_assert(ConfiguredSensor<sensors::StreakParams> && ConfiguredSensor<sensors::SpadParams> &&
              ConfiguredSensor<sensors::CwTofParams>);
static_assert(!ConfiguredSensor<UndescribedParams>);
static_assert(!detail::allConfigured(
    static_cast<const std::variant<sensors::SpadParams, UndescribedParams>*>(nullptr)));

TEST(SensorConfigTest, ParsesEveryModelWithUnits) {
  const auto specs = parse(R"(sensors:
  - type: streak
    rows: [3, 7]
    bin_width: 2 ps
    bins: 512
    time_fwhm: 10 ps
    spatial_fwhm: 1.5
    read_noise: 2
  - type: spad
    name: lidar
    mode: free_running
    cycles: 100000
    pulse_fwhm: 100 ps
    jitter_fwhm: 50 ps
    jitter_tail_fraction: 0.1
    jitter_tail: 200 ps
    pde: 0.25
    ambient_rate: 2 MHz
    dark_count_rate: 100
    dead_time: 20 ns
    plot_pixels: [[1, 2], [3, 4]]
    channel_weights: [0.2, 0.7, 0.1]
  - type: cwtof
    frequencies: ["80 MHz", "100 MHz"]
    waveform: square
    phase_steps: 5
    wavelength: 0.85 um
)");
  ASSERT_EQ(specs.size(), 3u);
  const auto& s = std::get<StreakParams>(specs[0].params);
  EXPECT_EQ(specs[0].name, "streak");
  EXPECT_EQ(s.rows, (std::vector<int32_t>{3, 7}));
  EXPECT_DOUBLE_EQ(s.bins.bin_width_s, 2e-12);
  EXPECT_EQ(s.bins.count, 512);
  EXPECT_DOUBLE_EQ(s.time_fwhm_s, 10e-12);
  EXPECT_DOUBLE_EQ(s.spatial_fwhm_px, 1.5);
  EXPECT_TRUE(s.shot_noise);
  const auto& p = std::get<SpadParams>(specs[1].params);
  EXPECT_EQ(specs[1].name, "lidar");
  EXPECT_EQ(p.mode, SpadMode::FreeRunning);
  EXPECT_EQ(p.cycles, 100000);
  EXPECT_DOUBLE_EQ(p.ambient_rate_per_s, 2e6);
  EXPECT_DOUBLE_EQ(p.dark_count_rate_per_s, 100.0);
  EXPECT_DOUBLE_EQ(p.dead_time_s, 20e-9);
  EXPECT_EQ(p.plot_pixels.size(), 2u);
  EXPECT_EQ(p.plot_pixels[1][1], 4);
  EXPECT_EQ(p.common.channel.weights.size(), 3u);
  const auto& c = std::get<CwTofParams>(specs[2].params);
  EXPECT_EQ(c.frequencies_Hz, (std::vector<double>{80e6, 100e6}));
  EXPECT_EQ(c.waveform, Waveform::Square);
  EXPECT_EQ(c.phase_steps, 5);
  EXPECT_DOUBLE_EQ(c.common.radiometry.wavelength_m, 0.85e-6);
}

TEST(SensorConfigTest, BadValuesGiveLocatedErrors) {
  struct Case {
    std::string yaml, where, key, words;
  };
  const std::vector<Case> cases = {
      {"sensors:\n  - type: streak\n    time_fwhm: -5 ps\n", "test.yaml:3:16",
       "sensors[0].time_fwhm", "must be >= 0"},
      {"sensors:\n  - type: spad\n    bins: 0\n", "test.yaml:3:11", "sensors[0].bins",
       "must be an integer in [1"},
      {"sensors:\n  - type: spad\n    bin_width: 0 ps\n", "test.yaml:3:16", "sensors[0].bin_width",
       "must be > 0"},
      {"sensors:\n  - type: spad\n    pulse_fwhm: -1 ns\n", "test.yaml:3:17",
       "sensors[0].pulse_fwhm", "must be >= 0"},
      {"sensors:\n  - type: cwtof\n    frequencies: [20 MHz, 0 MHz]\n", "test.yaml:3:27",
       "sensors[0].frequencies[1]", "frequency must be > 0"},
      {"sensors:\n  - type: cwtof\n    frequencies: [-20 MHz]\n", "test.yaml:3:19",
       "sensors[0].frequencies[0]", "frequency must be > 0"},
      {"sensors:\n  - type: lidar\n", "test.yaml:2:11", "sensors[0].type", "unknown sensor type"},
      {"sensors:\n  - type: spad\n    pdee: 0.3\n", "test.yaml:3:5", "sensors[0].pdee",
       "unknown key"},
      {"sensors:\n  - type: spad\n    pde: 1.5\n", "test.yaml:3:10", "sensors[0].pde",
       "must be in [0, 1]"},
      {"sensors:\n  - type: spad\n    mode: async\n", "test.yaml:3:11", "sensors[0].mode",
       "synchronous or free_running"},
      {"sensors:\n  - type: cwtof\n    phase_steps: 2\n", "test.yaml:3:18",
       "sensors[0].phase_steps", "must be >= 3"},
      {"sensors:\n  - type: streak\n    gain: 0\n", "test.yaml:3:11", "sensors[0].gain",
       "must be > 0"},
      {"sensors:\n  - type: streak\n  - type: spad\n    cycles: 0\n", "test.yaml:4:13",
       "sensors[1].cycles", "must be an integer in [1"},
      {"sensors:\n  - type: cwtof\n    frequencies: [20 parsecs]\n", "test.yaml:3:19",
       "sensors[0].frequencies[0]", "unknown frequency unit"},
  };
  for (const Case& c : cases) {
    const std::string message = errorOf(c.yaml);
    EXPECT_NE(message.find(c.where + ": " + c.key + ": "), std::string::npos)
        << c.yaml << " -> " << message;
    EXPECT_NE(message.find(c.words), std::string::npos) << c.yaml << " -> " << message;
  }
}

TEST(SensorConfigTest, EffectiveConfigRoundTrips) {
  const auto specs = parse(R"(sensors:
  - type: streak
    rows: [1]
    bin_offset: 0.3 ns
    time_fwhm: 12.5 ps
  - type: spad
    plot_pixels: [[0, 1]]
    jitter_fwhm: 33 ps
    dead_time: 15 ns
    ambient_rate: 1.5e5
  - type: cwtof
    frequencies: [20 MHz, 110.5 MHz]
    max_depth: 12 m
    multipath_by_order: true
)");
  YAML::Node doc;
  doc["sensors"] = sensorsToYaml(specs);
  const std::string text = YAML::Dump(doc);
  const auto again = parse(text);
  ASSERT_EQ(again.size(), 3u);
  const auto& s0 = std::get<StreakParams>(specs[0].params);
  const auto& s1 = std::get<StreakParams>(again[0].params);
  EXPECT_EQ(s1.rows, s0.rows);
  EXPECT_EQ(s1.bins.offset_s, s0.bins.offset_s);  // both unset, or both the same value
  EXPECT_DOUBLE_EQ(s1.time_fwhm_s, s0.time_fwhm_s);
  EXPECT_EQ(s1.bins.count, 0);
  const auto& p0 = std::get<SpadParams>(specs[1].params);
  const auto& p1 = std::get<SpadParams>(again[1].params);
  EXPECT_DOUBLE_EQ(p1.jitter_fwhm_s, p0.jitter_fwhm_s);
  EXPECT_DOUBLE_EQ(p1.dead_time_s, p0.dead_time_s);
  EXPECT_DOUBLE_EQ(p1.ambient_rate_per_s, 1.5e5);
  EXPECT_DOUBLE_EQ(p1.pde, p0.pde);
  EXPECT_EQ(p1.cycles, p0.cycles);
  EXPECT_EQ(p1.plot_pixels, p0.plot_pixels);
  const auto& c1 = std::get<CwTofParams>(again[2].params);
  EXPECT_EQ(c1.frequencies_Hz, (std::vector<double>{20e6, 110.5e6}));
  EXPECT_DOUBLE_EQ(c1.max_depth_m, 12.0);
  EXPECT_TRUE(c1.multipath_by_order);
  EXPECT_NE(text.find("time_fwhm: 12.5 ps"), std::string::npos) << text;
}

}  // namespace
}  // namespace tofsim::config

namespace tofsim::config {
namespace {
// Neither `channel` nor `channel_weights`: the sum of the channels, kept so
// through the effective config; `channel: 0` still picks the red channel.
TEST(SensorConfigTest, NoChannelKeyMeansTheSumOfTheChannels) {
  const auto specs =
      parse("sensors:\n  - type: spad\n  - type: spad\n    name: red\n    channel: 0\n");
  const auto& sum = std::get<SpadParams>(specs[0].params).common.channel;
  EXPECT_TRUE(sum.weights.empty());
  EXPECT_EQ(sum.index, ChannelSelection::kSumOfChannels);
  EXPECT_EQ(std::get<SpadParams>(specs[1].params).common.channel.index, 0);
  YAML::Node doc;
  doc["sensors"] = sensorsToYaml(specs);
  const auto again = parse(YAML::Dump(doc));
  EXPECT_EQ(std::get<SpadParams>(again[0].params).common.channel.index,
            ChannelSelection::kSumOfChannels);
  EXPECT_EQ(std::get<SpadParams>(again[1].params).common.channel.index, 0);
  EXPECT_NE(errorOf("sensors:\n  - type: spad\n    channel: -1\n").find("must be >= 0"),
            std::string::npos);
}
}  // namespace
}  // namespace tofsim::config
