// CW-ToF multipath error by bounce order (CwTofParams::multipath_by_order):
// closed-form phasor sums of hand-made returns, order N against the ordinary
// error, and the errors it gives for inputs it cannot use.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstring>

#include "TestVolumes.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/sensors/SensorStream.h"
#include "tofsim/util/Error.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::sensors {
namespace {

using test::makeVolume;
constexpr double kC = kSpeedOfLight_m_per_s;
constexpr double kBin_s = 10e-12;
constexpr double kF_Hz = 20e6;

CwTofParams byOrder() {
  CwTofParams p;
  p.frequencies_Hz = {kF_Hz};
  p.ambient_e = 300.0;  // moves no phase; the noise does not reach the errors
  p.multipath_by_order = true;
  return p;
}

// Pixel 0: direct at bin 200, bounce 1 at bin 300, bounce 2 at bin 420.
// Pixel 1: no direct light (shadowed), bounce 1 only.
struct ThreeOrders {
  TransientVolume direct = makeVolume(2, 1, 0.0, kBin_s, 600);
  TransientVolume b1 = direct, b2 = direct, total = direct;
  Image truth{2, 1, 1};
  std::vector<const TransientVolume*> bounces{&b1, &b2};

  ThreeOrders() {
    direct.at(0, 0, 200, 0) = 1000.0f;
    b1.at(0, 0, 300, 0) = 300.0f;
    b2.at(0, 0, 420, 0) = 120.0f;
    b1.at(0, 1, 350, 0) = 50.0f;
    for (std::size_t i = 0; i < total.values().size(); ++i) {
      total.values()[i] = direct.values()[i] + (b1.values()[i] + b2.values()[i]);
    }
    truth.at(0, 0, 0) = truth.at(0, 1, 0) = static_cast<float>(depthOfBin(200));
  }
  static double depthOfBin(int32_t bin) { return kC * (bin + 0.5) * kBin_s / 2; }
};

// The depth of returns at bin centres (equal bins share the sinc factor).
double phasorDepth(const std::vector<std::pair<int32_t, double>>& returns) {
  std::complex<double> sum = 0.0;
  for (const auto& [bin, e] : returns)
    sum += e * std::polar(1.0, 2 * M_PI * kF_Hz * (bin + 0.5) * kBin_s);
  double phase = std::arg(sum);
  if (phase < 0) phase += 2 * M_PI;
  return kC * phase / (4 * M_PI * kF_Hz);
}

TEST(CwTofByOrderTest, EachOrderIsThePhasorSumOfItsBounces) {
  ThreeOrders s;
  CwTofReferences refs{&s.truth, &s.direct, &s.bounces};
  const auto outs = runCwTof(s.total, byOrder(), 5, refs);
  const SensorOutput& e = test::array(outs, "cwtof_multipath_error_by_order");
  ASSERT_EQ(e.shape, (std::vector<int64_t>{3, 1, 2}));
  const double d = ThreeOrders::depthOfBin(200);
  EXPECT_NEAR(e.data[0], 0.0, 1e-6);  // order 0: the direct return alone
  EXPECT_NEAR(e.data[2], phasorDepth({{200, 1000}, {300, 300}}) - d, 1e-5);
  EXPECT_NEAR(e.data[4], phasorDepth({{200, 1000}, {300, 300}, {420, 120}}) - d, 1e-5);
  // Each later, weaker return pulls the depth further out here: 0 < e1 < e2.
  EXPECT_GT(e.data[2], 0.02);
  EXPECT_GT(e.data[4], e.data[2]);
  // Pixel 1: no direct light, so order 0 has no phase (NaN); order 1 is the bounce's depth.
  EXPECT_TRUE(std::isnan(e.data[1]));
  EXPECT_NEAR(e.data[3], ThreeOrders::depthOfBin(350) - d, 1e-5);
  EXPECT_FLOAT_EQ(e.data[5], e.data[3]);  // bounce 2 adds nothing there
  // One picture per order, the same values.
  for (int k = 0; k < 3; ++k) {
    const SensorOutput& png = test::output(outs, "cwtof_multipath_error_order" + std::to_string(k),
                                           SensorOutput::Kind::ColorMappedImage);
    EXPECT_TRUE(png.signed_values);
    for (int px = 0; px < 2; ++px) {
      const float a = png.data[px], b = e.data[k * 2 + px];
      EXPECT_TRUE((std::isnan(a) && std::isnan(b)) || a == b);
    }
  }
}

TEST(CwTofByOrderTest, LastOrderIsTheOrdinaryMultipathError) {
  ThreeOrders s;
  CwTofReferences refs{&s.truth, &s.direct, &s.bounces};
  const auto outs = runCwTof(s.total, byOrder(), 5, refs);
  const auto& e = test::array(outs, "cwtof_multipath_error_by_order").data;
  const auto& mpi = test::output(outs, "cwtof_mpi_error").data;
  EXPECT_NEAR(e[4], mpi[0], 1e-6);
  EXPECT_NEAR(e[5], mpi[1], 1e-6);
}

TEST(CwTofByOrderTest, SpansCutAnywhereGiveTheSameBytes) {
  ThreeOrders s;
  StreamOptions options;
  options.seed = 5;
  options.directOnly = true;
  options.bounces = 2;
  std::vector<float> bytes[2];
  for (int cut = 0; cut < 2; ++cut) {
    auto stream = openCwTof(byOrder(), shapeOf(s.total), options);
    PixelSpan whole = wholeVolume(s.total, &s.direct, &s.bounces);
    if (cut == 0) {
      stream->consume(whole);
    } else {
      const std::size_t floats = static_cast<std::size_t>(s.total.bins());
      for (std::size_t px = 0; px < 2; ++px) {
        PixelSpan one{px, 1, whole.volume + px * floats, whole.directOnly + px * floats, {}};
        for (const float* b : whole.bounces) one.bounces.push_back(b + px * floats);
        stream->consume(one);
      }
    }
    const auto outs = stream->finish(&s.truth);
    bytes[cut] = test::array(outs, "cwtof_multipath_error_by_order").data;
  }
  ASSERT_EQ(bytes[0].size(), bytes[1].size());
  EXPECT_EQ(0, std::memcmp(bytes[0].data(), bytes[1].data(), bytes[0].size() * sizeof(float)));
}

TEST(CwTofByOrderTest, WithoutBouncesOrTruthItIsAnInputError) {
  ThreeOrders s;
  EXPECT_THROW(runCwTof(s.total, byOrder(), 1, CwTofReferences{&s.truth, &s.direct}), InputError);
  CwTofReferences noTruth{nullptr, &s.direct, &s.bounces};
  EXPECT_THROW(runCwTof(s.total, byOrder(), 1, noTruth), InputError);
  // Zero bounces (a direct-only render): order 0 alone.
  const std::vector<const TransientVolume*> none;
  const auto outs = runCwTof(s.direct, byOrder(), 1, CwTofReferences{&s.truth, &s.direct, &none});
  const SensorOutput& e = test::array(outs, "cwtof_multipath_error_by_order");
  EXPECT_EQ(e.shape, (std::vector<int64_t>{1, 1, 2}));
  EXPECT_NEAR(e.data[0], 0.0, 1e-6);
}

}  // namespace
}  // namespace tofsim::sensors
