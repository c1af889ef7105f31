// Stray light as ToF users see it: a bright near patch before a dark far
// wall. The PSF acts on every time bin with the light's delay kept, so a
// wall pixel's CW-ToF phasor (computed here from the convolved transient,
// sum over bins of v(t) e^(-i w t)) is the closed form
//   p = p_wall + s S (p_patch - p_wall),  S = sum over patch pixels x' of K_s(x - x'),
// (the patch's scattered light added, the wall light the patch hides
// removed), and the wall's depth error is that phasor's.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include "tofsim/optics/PsfConvolution.h"

namespace tofsim::optics {
namespace {

using Complex = std::complex<double>;

constexpr int kW = 61, kH = 61, kBins = 200;
constexpr double kBin_s = 50e-12;
constexpr double kOmega = 2.0 * std::numbers::pi * 20e6;  // 20 MHz modulation
constexpr double kC = 299792458.0;

bool inPatch(int x, int y) { return std::abs(x - 30) <= 1 && std::abs(y - 30) <= 1; }

// Each pixel's pulse: three bins (1, 2, 1) x amplitude around its arrival bin.
std::vector<double> transient(double wallAmp, int wallBin, double patchAmp, int patchBin) {
  std::vector<double> v(static_cast<std::size_t>(kW) * kH * kBins, 0.0);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const bool patch = inPatch(x, y);
      const double a = patch ? patchAmp : wallAmp;
      const int t = patch ? patchBin : wallBin;
      double* px = &v[(static_cast<std::size_t>(y) * kW + x) * kBins];
      px[t - 1] = a;
      px[t] = 2.0 * a;
      px[t + 1] = a;
    }
  }
  return v;
}

Complex phasor(const double* bins) {
  Complex p = 0.0;
  for (int t = 0; t < kBins; ++t) p += bins[t] * std::polar(1.0, -kOmega * (t + 0.5) * kBin_s);
  return p;
}

double depth_m(Complex p) {
  double phi = -std::arg(p);
  if (phi < 0.0) phi += 2.0 * std::numbers::pi;
  return kC * phi / (2.0 * kOmega);
}

TEST(PsfPhasorTest, BrightNearPatchBiasesTheWallByTheClosedForm) {
  const double s = 0.08, R = 2.0;
  const PsfKernel kernel = PsfKernel::parametric({0.0, s, HaloProfile::Exponential, R});
  ASSERT_EQ(kernel.radiusX(), 24);
  const int wallBin = 150, patchBin = 40;  // 5.5 ns apart: 0.82 m
  std::vector<double> v = transient(0.02, wallBin, 5.0, patchBin);
  // Unconvolved phasors of a wall and a patch pixel.
  const Complex pWall = phasor(&v[0]);
  const Complex pPatch = phasor(&v[(30 * kW + 30) * static_cast<std::size_t>(kBins)]);
  applyPsf(kernel, v.data(), kBins, PlaneLayout{kW, kH, kBins, 1});
  // K_s in closed form: exp(-r / R) over the disc r <= 12 R, normalised.
  double z = 0.0;
  for (int dy = -24; dy <= 24; ++dy) {
    for (int dx = -24; dx <= 24; ++dx) {
      if (std::hypot(dx, dy) <= 12.0 * R) z += std::exp(-std::hypot(dx, dy) / R);
    }
  }
  // Wall pixels whose kernel support lies inside the image (|x - 30| <= 6).
  double worstPhasor = 0.0, worstDepth = 0.0, largestError = 0.0;
  for (const auto& [x, y] : {std::pair{33, 30}, {36, 32}, {30, 24}, {25, 35}, {32, 32}}) {
    ASSERT_FALSE(inPatch(x, y));
    double S = 0.0;
    for (int py = 29; py <= 31; ++py) {
      for (int px = 29; px <= 31; ++px) {
        const double r = std::hypot(x - px, y - py);
        if (r <= 12.0 * R) S += std::exp(-r / R) / z;
      }
    }
    const Complex expected = pWall + s * S * (pPatch - pWall);
    const Complex got = phasor(&v[(static_cast<std::size_t>(y) * kW + x) * kBins]);
    worstPhasor = std::max(worstPhasor, std::abs(got - expected) / std::abs(expected));
    const double error_m = depth_m(got) - depth_m(pWall);
    const double closedForm_m = depth_m(expected) - depth_m(pWall);
    worstDepth = std::max(worstDepth, std::abs(error_m - closedForm_m));
    largestError = std::max(largestError, std::abs(error_m));
    std::printf("wall pixel (%d, %d): S = %.4e, depth error %.4f m (closed form %.4f m)\n", x, y, S,
                error_m, closedForm_m);
  }
  EXPECT_LT(worstPhasor, 1e-9);
  EXPECT_LT(worstDepth, 1e-9);
  // The effect is there: the near patch pulls the wall by decimetres (a PSF
  // off, or one applied to the steady image at the wall's delay, gives 0).
  EXPECT_GT(largestError, 0.1);
}

}  // namespace
}  // namespace tofsim::optics
