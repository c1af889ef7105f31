// Streaming sensors: each model fed the volume in uneven spans (cutting rows
// in the middle) gives exactly the bytes of the whole volume in one span,
// with spad_counts streamed out instead of held; the window-loss meter fed
// in spans agrees with the whole-volume fraction.

#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <memory>
#include <random>

#include "TestVolumes.h"
#include "tofsim/sensors/RunSensor.h"
#include "tofsim/sensors/WindowLoss.h"

namespace tofsim::sensors {
namespace {

// Keeps what a stream sends out, by output name.
class CapturedArrays final : public ArrayStreams {
 public:
  std::map<std::string, std::vector<float>> values;
  std::map<std::string, bool> closed;

  std::unique_ptr<ArrayWriter> open(const std::string& name, const std::vector<int64_t>&) override {
    struct Writer final : ArrayWriter {
      CapturedArrays* owner;
      std::string name;
      void append(const float* v, std::size_t n) override {
        owner->values[name].insert(owner->values[name].end(), v, v + n);
      }
      void close() override { owner->closed[name] = true; }
    };
    auto w = std::make_unique<Writer>();
    w->owner = this;
    w->name = name;
    return w;
  }
};

// A 7x5 volume of 3 channels, two returns per pixel of random height, and
// its direct component (the first return).
struct Scene {
  TransientVolume volume = test::makeVolume(7, 5, 0.0, 20e-12, 64, 3);
  TransientVolume direct = test::makeVolume(7, 5, 0.0, 20e-12, 64, 3);
  Image depth{7, 5, 1};
  Scene() {
    std::mt19937 gen(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int32_t y = 0; y < 5; ++y) {
      for (int32_t x = 0; x < 7; ++x) {
        const int32_t first = 10 + (x + 2 * y) % 20;
        for (int32_t c = 0; c < 3; ++c) {
          direct.at(y, x, first, c) = volume.at(y, x, first, c) = 50.0f * u(gen);
          volume.at(y, x, first + 15, c) = 20.0f * u(gen);
        }
        depth.at(y, x, 0) = static_cast<float>(volume.axis().depthOf_m((first + 0.5) * 20e-12));
      }
    }
  }
};

bool sameBytes(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

void expectStreamsAsInMemory(const SensorSpec& spec) {
  const Scene s;
  SensorInputs in;
  in.volume = &s.volume;
  in.directOnly = &s.direct;
  in.groundTruthDepth_m = &s.depth;
  in.seed = 42;
  const std::vector<SensorOutput> whole = runSensor(spec, in);

  CapturedArrays arrays;
  StreamOptions options;
  options.seed = 42;
  options.directOnly = true;
  options.arrays = &arrays;
  options.threads = 3;
  const std::unique_ptr<SensorStream> stream = openSensor(spec, shapeOf(s.volume), options);
  const std::size_t floats = shapeOf(s.volume).pixelFloats();
  std::size_t first = 0;
  for (std::size_t n : {1u, 5u, 9u, 3u, 17u}) {  // 35 pixels, rows of 7 cut anywhere
    stream->consume({first, n, s.volume.data() + first * floats, s.direct.data() + first * floats});
    first += n;
  }
  ASSERT_EQ(first, 35u);
  const std::vector<SensorOutput> streamed = stream->finish(&s.depth);

  ASSERT_EQ(streamed.size(), whole.size());
  for (std::size_t i = 0; i < whole.size(); ++i) {
    const SensorOutput& a = whole[i];
    const SensorOutput& b = streamed[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.shape, b.shape);
    EXPECT_FALSE(a.streamed);
    if (b.streamed) {
      EXPECT_TRUE(b.data.empty()) << b.name;
      EXPECT_TRUE(arrays.closed[b.name]) << b.name;
      EXPECT_TRUE(sameBytes(a.data, arrays.values[b.name])) << b.name;
    } else {
      EXPECT_TRUE(sameBytes(a.data, b.data)) << b.name;
    }
  }
}

TEST(SensorStreamTest, SpadInSpansIsByteIdenticalAndStreamsItsCounts) {
  SpadParams p;
  p.common.channel.weights = {1.0, 1.0, 1.0};
  p.cycles = 5000;
  p.pde = 0.5;
  p.jitter_fwhm_s = 30e-12;
  p.ambient_rate_per_s = 1e8;
  p.plot_pixels = {{6, 4}, {0, 0}, {3, 2}};
  expectStreamsAsInMemory({"spad", p});
  p.mode = SpadMode::FreeRunning;
  p.dead_time_s = 100e-12;
  expectStreamsAsInMemory({"spad", p});
}

TEST(SensorStreamTest, StreakInSpansIsByteIdentical) {
  StreakParams p;
  p.common.channel.index = 1;
  p.rows = {3, 0, 3, 4};  // out of order and twice: outputs follow the list
  p.time_fwhm_s = 40e-12;
  p.spatial_fwhm_px = 1.5;
  p.read_noise_e = 2.0;
  expectStreamsAsInMemory({"streak", p});
}

TEST(SensorStreamTest, CwTofInSpansIsByteIdenticalWithBothMultipathErrors) {
  CwTofParams p;
  p.common.channel.weights = {0.5, 1.0, 0.25};
  p.frequencies_Hz = {20e6, 50e6, 100e6};
  p.read_noise_e = 1.0;
  p.ambient_e = 10.0;
  expectStreamsAsInMemory({"cwtof", p});
}

TEST(SensorStreamTest, WindowLossMeterInSpansMatchesTheWholeVolume) {
  const Scene s;
  StreakParams p;
  p.rows = {1, 1, 4};
  p.bins.count = 20;  // ends before the second returns of most pixels
  const double whole = windowLossFraction(p, s.volume);
  EXPECT_GT(whole, 0.1);
  WindowLossMeter meter(instrumentWindow(p), shapeOf(s.volume));
  const std::size_t floats = shapeOf(s.volume).pixelFloats();
  for (std::size_t first = 0; first < 35; first += 4) {
    const std::size_t n = std::min<std::size_t>(4, 35 - first);
    meter.consume({first, n, s.volume.data() + first * floats, nullptr});
  }
  EXPECT_DOUBLE_EQ(meter.fraction(), whole);
}

}  // namespace
}  // namespace tofsim::sensors
