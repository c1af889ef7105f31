// Bounce-resolved output of the IR driver (output.components: bounce1 ..
// bounceN) on the CPU backend: the bounce volumes add up to indirect exactly
// (the float sum in bounce order), bounce 1 of a multi-bounce render is the
// one-bounce render's indirect light bit for bit, one bounce names indirect
// as bounce1, and every component keeps its bytes across memory budgets and
// threads.

#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "support/TestJobs.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"

namespace tofsim::cpu {
namespace {

using namespace capture;

// Every named component of the streamed segments, whole-image volumes in
// pixel order, and the names in the order of the first segment.
struct Components : SegmentSink {
  explicit Components(std::size_t floatsPerPixel) : floatsPerPixel(floatsPerPixel) {}
  void consume(const Segment& segment) override {
    if (names.empty()) {
      for (const SegmentComponent& c : segment.components) names.emplace_back(c.name);
    }
    for (const SegmentComponent& c : segment.components) {
      std::vector<float>& v = volumes[std::string(c.name)];
      v.insert(v.end(), c.values, c.values + segment.pixelCount * floatsPerPixel);
    }
  }
  std::size_t floatsPerPixel;
  std::vector<std::string> names;
  std::map<std::string, std::vector<float>> volumes;
};

struct Rendered {
  std::unique_ptr<Components> components;
  RenderResult result;
};

Rendered render(RenderJob job, int32_t bounces, int threads = 2) {
  job.settings.indirect.bounces = bounces;
  Rendered out{
      std::make_unique<Components>(static_cast<std::size_t>(job.settings.time.bins) * kChannels),
      {}};
  out.result = ir::IrRenderer(std::make_unique<CpuBackend>(CpuBackendOptions{threads, true}))
                   .render(job, *out.components);
  return out;
}

// Bitwise equality (EXPECT_EQ on floats would pass -0 == 0).
bool sameBytes(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

double energy(const std::vector<float>& v) {
  double sum = 0.0;
  for (const float x : v) sum += x;
  return sum;
}

TEST(BounceComponentsTest, BouncesAddUpToIndirectExactlyInBounceOrder) {
  for (const Visibility visibility : {Visibility::Ism, Visibility::Exact}) {
    test::CornerJob s(16);
    s.job.settings.indirect.rsm_resolution = 16;
    s.job.settings.indirect.visibility = visibility;
    const Rendered r = render(s.job, 3);
    const auto& v = r.components->volumes;
    EXPECT_EQ(r.components->names,
              (std::vector<std::string>{"direct", "indirect", "bounce1", "bounce2", "bounce3"}));
    std::vector<float> sum = v.at("bounce1");
    for (const char* k : {"bounce2", "bounce3"}) {
      for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += v.at(k)[i];
    }
    EXPECT_TRUE(sameBytes(sum, v.at("indirect")));
    // Each bounce carries light, less than the one before in an open corner.
    const double e1 = energy(v.at("bounce1")), e2 = energy(v.at("bounce2")),
                 e3 = energy(v.at("bounce3"));
    EXPECT_GT(e2, 0.0);
    EXPECT_GT(e3, 0.0);
    EXPECT_LT(e2, e1);
    EXPECT_LT(e3, e2);
    // Bounce 1 is gathered alone from zero, in the same VPL order as a
    // one-bounce render: the same bytes.
    const Rendered one = render(s.job, 1);
    EXPECT_TRUE(sameBytes(v.at("bounce1"), one.components->volumes.at("indirect")));
    EXPECT_TRUE(sameBytes(v.at("direct"), one.components->volumes.at("direct")));
  }
}

TEST(BounceComponentsTest, OneBounceNamesItsIndirectLightBounce1) {
  test::CornerJob s(16);
  const Rendered r = render(s.job, 1);
  EXPECT_EQ(r.components->names, (std::vector<std::string>{"direct", "indirect", "bounce1"}));
  EXPECT_TRUE(sameBytes(r.components->volumes.at("bounce1"), r.components->volumes.at("indirect")));
  EXPECT_GT(energy(r.components->volumes.at("bounce1")), 0.0);
}

TEST(BounceComponentsTest, TwoBouncesGiveTheSameBytesWhateverTheBudgetAndThreads) {
  test::CornerJob s(16);  // ISM visibility, pixel footprint: the default job
  s.job.settings.indirect.rsm_resolution = 16;
  const Rendered a = render(s.job, 2, 1);
  RenderJob tight = s.job;
  tight.settings.memory_budget_bytes = std::size_t{2} << 20;
  const Rendered b = render(tight, 2, 3);
  EXPECT_GT(b.result.vplBatches, 1u);
  EXPECT_GT(b.result.segments, 1u);
  EXPECT_EQ(a.components->names, b.components->names);
  for (const auto& [name, volume] : a.components->volumes) {
    EXPECT_TRUE(sameBytes(volume, b.components->volumes.at(name))) << name;
  }
}

}  // namespace
}  // namespace tofsim::cpu
