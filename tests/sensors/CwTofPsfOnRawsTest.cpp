// The lens's PSF inside the CW-ToF stream (StreamOptions::psfOnRaws): the
// raws and depths of the sharp volume with the PSF on the sensor's signal
// charges equal those of the volume convolved bin by bin (linearity), to
// the float rounding of the convolved volume; the ambient is not blurred;
// cwtof_psf_error is the same whether the stream blurs its raws or is given
// the light before the PSF (consumeBeforePsf); a fixed-pattern delay with
// a PSF on the raws is an InputError.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "TestVolumes.h"
#include "tofsim/optics/PsfConvolution.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {
namespace {

using test::array;
using test::makeVolume;
using test::output;

constexpr int32_t kW = 11, kH = 9, kBins = 160;

// Pixels of their own return each, one bright spot (the stray light's source).
TransientVolume scene() {
  TransientVolume v = makeVolume(kW, kH, 0.0, 50e-12, kBins, 3);
  for (int32_t y = 0; y < kH; ++y) {
    for (int32_t x = 0; x < kW; ++x) {
      const bool spot = x == 5 && y == 4;
      const int32_t bin = spot ? 20 : 100 + (3 * x + 5 * y) % 40;
      for (int32_t c = 0; c < 3; ++c) v.at(y, x, bin, c) = spot ? 400.0f : 2.0f + 0.1f * c;
    }
  }
  return v;
}

const optics::PsfKernel& kernel() {
  static const optics::PsfKernel k =
      optics::PsfKernel::parametric({0.5, 0.2, optics::HaloProfile::Gaussian, 1.5});
  return k;
}

CwTofParams params(int32_t taps) {
  CwTofParams p;
  p.shot_noise = false;
  p.frequencies_Hz = {20e6, 50e6};
  p.ambient_e = 500.0;
  p.common.channel.weights = {1.0, 1.0, 1.0};
  p.taps = taps;
  return p;
}

std::vector<SensorOutput> run(const CwTofParams& p, const TransientVolume& v,
                              const StreamOptions& options, const TransientVolume* sharp) {
  const auto stream = openCwTof(p, shapeOf(v), options);
  if (sharp) stream->consumeBeforePsf(wholeVolume(*sharp));
  stream->consume(wholeVolume(v));
  return stream->finish(nullptr);
}

double worstRelative(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(double(a[i]) - b[i]) / std::abs(double(b[i])));
  }
  return worst;
}

double worstAbsolute(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, double(std::abs(a[i] - b[i])));
  return worst;
}

TEST(CwTofPsfOnRawsTest, EqualsThePsfOnEveryBin) {
  const TransientVolume sharp = scene();
  TransientVolume blurred = sharp;
  const std::size_t perPixel = std::size_t(kBins) * 3;
  optics::applyPsf(kernel(), blurred.data(), perPixel, {kW, kH, perPixel, 1});
  for (int32_t taps : {1, 2}) {
    const CwTofParams p = params(taps);
    StreamOptions onRaws;
    onRaws.psfOnRaws = &kernel();
    StreamOptions before;
    before.beforePsf = true;
    const auto a = run(p, sharp, onRaws, nullptr);
    const auto b = run(p, blurred, before, &sharp);
    const double raw = worstRelative(array(a, "cwtof_raw").data, array(b, "cwtof_raw").data);
    const double depth =
        worstAbsolute(output(a, "cwtof_depth").data, output(b, "cwtof_depth").data);
    const double psf =
        worstAbsolute(output(a, "cwtof_psf_error").data, output(b, "cwtof_psf_error").data);
    const auto& error = output(a, "cwtof_psf_error").data;
    const double largest = std::abs(*std::min_element(error.begin(), error.end()));
    std::printf("taps %d: raws %.2e relative, depth %.2e m, psf error %.2e m (largest %.3f m)\n",
                taps, raw, depth, psf, largest);
    // The convolved volume's float rounding, 6e-8 a value (two taps: A - B, a
    // difference of two such charges).
    EXPECT_LT(raw, 1e-5);
    EXPECT_LT(depth, 1e-6);
    EXPECT_LT(psf, 1e-6);
    EXPECT_GT(largest, 0.05);  // the spot pulls its neighbours by decimetres
    // The sharp stream's own depth: the error is blurred - sharp.
    const auto sharpRun = run(p, sharp, {}, nullptr);
    EXPECT_EQ(findOutput(sharpRun, "cwtof_psf_error", SensorOutput::Kind::Image), nullptr);
    const auto& d = output(a, "cwtof_depth").data;
    const auto& s = output(sharpRun, "cwtof_depth").data;
    for (std::size_t i = 0; i < d.size(); ++i) EXPECT_NEAR(error[i], d[i] - s[i], 1e-5) << i;
  }
}

TEST(CwTofPsfOnRawsTest, TheAmbientIsNotBlurred) {
  // A dark volume: only the ambient. Blurred, the border would lose the
  // share of it the kernel throws off the image.
  const TransientVolume dark = makeVolume(kW, kH, 0.0, 50e-12, kBins, 3);
  StreamOptions onRaws;
  onRaws.psfOnRaws = &kernel();
  const auto a = run(params(1), dark, onRaws, nullptr);
  for (float raw : array(a, "cwtof_raw").data) EXPECT_EQ(raw, 250.0f);  // 0.5 ambient
}

TEST(CwTofPsfOnRawsTest, AFixedPatternDelayNeedsThePsfOnTheTransient) {
  CwTofParams p = params(1);
  p.delay_sigma_s = 20e-12;
  p.fpn_seed = 3;
  StreamOptions onRaws;
  onRaws.psfOnRaws = &kernel();
  EXPECT_THROW(openCwTof(p, shapeOf(scene()), onRaws), InputError);
}

}  // namespace
}  // namespace tofsim::sensors
