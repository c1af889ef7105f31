// The pixel footprint kernel (shaders/footprint_kernel.glsl through
// tofsim/physics/FootprintKernel.h): its bin integrals against an independent
// quadrature of the linear path over the pixel, energy conservation, the cost
// of a deposit, and a grazing plane against a fine sub-pixel quadrature of the
// exact direct term.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tofsim/physics/FootprintBuffer.h"

namespace tofsim::physics {
namespace {

struct Axis {
  float start_m = 0.0f;
  float binWidth_m = 0.003f;
  int32_t bins = 1024;
};

// One channel's bin integrals of a unit contribution, deposited and integrated.
std::vector<double> footprintHistogram(const vec3& kernel, int32_t bins,
                                       FootprintOffAxis* off = nullptr) {
  std::vector<double> diff(static_cast<std::size_t>(bins) * 3, 0.0);
  const FootprintOffAxis o = depositFootprint(diff.data(), bins, kernel, vec3(1.0f, 2.0f, 0.5f));
  if (off) *off = o;
  std::vector<float> h(diff.size(), 0.0f);
  integrateFootprint(diff.data(), bins, h.data());
  std::vector<double> out(static_cast<std::size_t>(bins));
  for (int32_t k = 0; k < bins; ++k) {
    out[k] = h[static_cast<std::size_t>(k) * 3];
    // The channels carry the energies 1, 2, 0.5 of the same kernel.
    EXPECT_NEAR(h[static_cast<std::size_t>(k) * 3 + 1], 2.0 * out[k], 1e-6);
    EXPECT_NEAR(h[static_cast<std::size_t>(k) * 3 + 2], 0.5 * out[k], 1e-6);
  }
  return out;
}

// Independent quadrature of path = p0 + a u + b v over (u, v) in [-1/2, 1/2]^2:
// `rows` midpoint rows in v; along u (the wider direction) the path sweeps an interval whose
// overlap with each bin is exact (a zero-width sweep lands in the bin floor picks).
std::vector<double> quadratureHistogram(double p0, double a, double b, const Axis& axis, int rows) {
  // Sweep exactly along the wider direction: the row integrals are then
  // continuous in v, and the midpoint rule converges as 1 / rows^2.
  if (std::abs(b) > std::abs(a)) std::swap(a, b);
  std::vector<double> h(static_cast<std::size_t>(axis.bins), 0.0);
  const double w = axis.binWidth_m;
  const double rowMass = 1.0 / rows;
  for (int j = 0; j < rows; ++j) {
    const double v = (j + 0.5) / rows - 0.5;
    const double mid = (p0 + b * v - axis.start_m) / w;  // bins
    const double half = 0.5 * std::abs(a) / w;
    if (half == 0.0) {
      const double k = std::floor(mid);
      if (k >= 0 && k < axis.bins) h[static_cast<std::size_t>(k)] += rowMass;
      continue;
    }
    const double lo = mid - half, hi = mid + half;
    const int32_t k0 = static_cast<int32_t>(std::max(0.0, std::floor(lo)));
    const int32_t k1 = static_cast<int32_t>(std::min<double>(axis.bins - 1, std::floor(hi)));
    for (int32_t k = k0; k <= k1; ++k) {
      const double overlap = std::min<double>(hi, k + 1) - std::max<double>(lo, k);
      if (overlap > 0.0) h[static_cast<std::size_t>(k)] += rowMass * overlap / (hi - lo);
    }
  }
  return h;
}

vec3 kernelOf(double p0, double a, double b, const Axis& axis) {
  return footprintKernel(static_cast<float>(p0), vec2(static_cast<float>(a), static_cast<float>(b)),
                         axis.start_m, axis.binWidth_m);
}

TEST(FootprintKernel, BinIntegralsMatchAQuadratureOfTheLinearPath) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int trial = 0; trial < 400; ++trial) {
    Axis axis;
    axis.binWidth_m = static_cast<float>(0.001 + 0.02 * unit(rng));
    axis.start_m = static_cast<float>(0.5 * unit(rng));
    axis.bins = 1024;
    const double w = axis.binWidth_m;
    // Widths from a small fraction of a bin to hundreds of bins, some exactly 0.
    const auto width = [&](int kind) {
      if (kind == 0) return 0.0;
      if (kind == 1) return (unit(rng) - 0.5) * 0.8 * w;
      if (kind == 2) return (unit(rng) - 0.5) * 20.0 * w;
      return (unit(rng) - 0.5) * 800.0 * w;
    };
    const double a = width(trial % 4);
    const double b = width((trial / 4) % 4);
    const double p0 = axis.start_m + w * (420.0 + 180.0 * unit(rng));  // wholly on the axis
    const vec3 kernel = kernelOf(p0, a, b, axis);
    const std::vector<double> got = footprintHistogram(kernel, axis.bins);
    // The kernel's centre is the float quotient (path - start) / width that
    // point sampling floors (its rounding, up to 1e-4 bins, would move a
    // narrow kernel's mass by more than the tolerance): the quadrature is
    // centred on the same bin position.
    const double p0f = axis.start_m + static_cast<double>(kernel.x) * w;
    const std::vector<double> want = quadratureHistogram(p0f, a, b, axis, 20000);
    for (int32_t k = 0; k < axis.bins; ++k) {
      worst = std::max(worst, std::abs(got[k] - want[k]));
      ASSERT_NEAR(got[k], want[k], 1e-6)
          << "trial " << trial << " bin " << k << " a " << a << " b " << b << " w " << w;
    }
  }
  std::printf("largest bin error vs quadrature: %.2e of the energy\n", worst);
}

TEST(FootprintKernel, BruteForceSubSamplesAgree) {
  // 1000 x 1000 sub-samples of a generic pixel: each bin within the lattice's
  // own discretisation error (one row of 1000 samples, 1e-3 of the energy).
  Axis axis;
  const double p0 = 1.5, a = 0.37, b = -0.11;
  const std::vector<double> got = footprintHistogram(kernelOf(p0, a, b, axis), axis.bins);
  std::vector<double> brute(static_cast<std::size_t>(axis.bins), 0.0);
  const int n = 1000;
  const double p0f = static_cast<float>(p0);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double path = p0f + a * ((i + 0.5) / n - 0.5) + b * ((j + 0.5) / n - 0.5);
      brute[static_cast<std::size_t>(std::floor((path - axis.start_m) / axis.binWidth_m))] +=
          1.0 / (static_cast<double>(n) * n);
    }
  }
  double l1 = 0.0;
  for (int32_t k = 0; k < axis.bins; ++k) {
    EXPECT_NEAR(got[k], brute[k], 1e-4) << k;
    l1 += std::abs(got[k] - brute[k]);
  }
  EXPECT_LT(l1, 1e-3);
}

TEST(FootprintKernel, BinsSumToTheEnergyAndOffAxisMassIsBooked) {
  Axis axis;
  axis.bins = 300;
  const double w = axis.binWidth_m;
  // Wholly on the axis: the sum is the energy to float rounding.
  {
    const std::vector<double> h = footprintHistogram(kernelOf(150 * w, 90 * w, 7 * w, axis), 300);
    double sum = 0.0;
    for (double v : h) sum += v;
    EXPECT_NEAR(sum, 1.0, 1e-6);
  }
  // Across either end: on-axis + before + after = 1, and the parts match the CDF.
  for (double centre : {-10.0, 5.0, 295.0, 310.0}) {
    FootprintOffAxis off;
    const vec3 k = kernelOf(centre * w, 40 * w, 13 * w, axis);
    const std::vector<double> h = footprintHistogram(k, 300, &off);
    double sum = 0.0;
    for (double v : h) sum += v;
    EXPECT_NEAR(sum + off.before + off.after, 1.0, 1e-6) << centre;
    EXPECT_NEAR(off.before, footprintCdf(k, 0.0), 1e-12);
    const std::vector<double> want =
        quadratureHistogram(static_cast<float>(centre * w), 40 * w, 13 * w, axis, 20000);
    for (int32_t b = 0; b < 300; ++b) ASSERT_NEAR(h[b], want[b], 1e-6) << centre << " " << b;
  }
  // Wholly off the axis: nothing written, all of it booked.
  FootprintOffAxis off;
  const std::vector<double> h =
      footprintHistogram(kernelOf(-100 * w, 10 * w, 3 * w, axis), 300, &off);
  for (double v : h) EXPECT_EQ(v, 0.0);
  EXPECT_DOUBLE_EQ(off.before, 1.0);
}

TEST(FootprintKernel, ASpikeLandsInThePointSampledBin) {
  // Both widths 0: all the energy in the bin binOfPath-style flooring picks,
  // including a path exactly on a bin edge.
  Axis axis;
  for (float path : {0.0f, 0.003f * 17.0f, 0.0451f, 1.2345f}) {
    const vec3 k = footprintKernel(path, vec2(0.0f), axis.start_m, axis.binWidth_m);
    const int32_t want = static_cast<int32_t>(std::floor((path - axis.start_m) / axis.binWidth_m));
    const std::vector<double> h = footprintHistogram(k, axis.bins);
    for (int32_t b = 0; b < axis.bins; ++b) EXPECT_NEAR(h[b], b == want ? 1.0 : 0.0, 1e-7) << path;
  }
}

TEST(FootprintKernel, ADepositTouchesAFixedNumberOfEntriesWhateverItsWidth) {
  Axis axis;
  axis.bins = 2000;
  const double w = axis.binWidth_m;
  for (double wide : {0.3, 5.0, 500.0, 1500.0}) {
    const vec3 k = kernelOf(1000 * w, wide * w, 0.4 * wide * w, axis);
    std::vector<double> diff(static_cast<std::size_t>(axis.bins) * 3, 0.0);
    depositFootprint(diff.data(), axis.bins, k, vec3(1.0f));
    int written = 0;
    int lastBin = -1;
    for (int slot = 0; slot < FOOTPRINT_SLOTS; ++slot) {
      const int bin = footprintSlotBin(k, slot, axis.bins);
      if (bin < 0) continue;
      EXPECT_GT(bin, lastBin) << "each bin once, in increasing order";
      lastBin = bin;
      ++written;
    }
    int nonZero = 0;
    for (std::size_t i = 0; i < diff.size(); i += 3) nonZero += diff[i] != 0.0;
    EXPECT_LE(written, FOOTPRINT_SLOTS) << wide;
    EXPECT_LE(nonZero, written) << wide;
    if (wide == 500.0) std::printf("500-bin kernel: %d difference-buffer entries\n", written);
  }
}

TEST(FootprintKernel, PathDerivativesMatchFiniteDifferences) {
  const vec3 camera(0.1f, 1.0f, -0.2f), light(0.4f, 2.0f, 0.3f);
  const vec3 x(0.3f, 0.0f, -3.0f), n(0.0f, 1.0f, 0.0f);
  const vec3 forward = glm::normalize(vec3(0.1f, -0.3f, -1.0f));
  const vec3 step(0.004f, 0.0f, 0.0004f);
  // The surface step: the hit of the stepped ray on the plane, minus x.
  const vec3 dx = surfaceStepAcrossPixel(x - camera, forward, step, n);
  const float t = dot(x - camera, forward);
  const vec3 dir = (x - camera) / t;
  const auto hit = [&](float h) {
    const vec3 d = dir + h * step;
    return camera + d * (dot(x - camera, n) / dot(d, n));
  };
  const vec3 fd = (hit(1e-2f) - hit(-1e-2f)) / 2e-2f;
  EXPECT_NEAR(glm::length(dx - fd), 0.0f, 1e-3f * glm::length(fd));
  EXPECT_NEAR(dot(dx, n), 0.0f, 1e-6f);
  const float eta = 1.3f;
  const vec3 g = opticalPathGradient(x, light, camera, eta, false);
  const auto path = [&](vec3 p) {
    return eta * (glm::length(p - light) + glm::length(p - camera));
  };
  const vec2 ab = pathStepsAcrossPixel(g, dx, vec3(0.0f, 0.0f, 0.01f));
  EXPECT_NEAR(ab.x, (path(x + 0.01f * dx) - path(x - 0.01f * dx)) / 0.02f, 1e-3f);
  EXPECT_NEAR(ab.y, (path(x + vec3(0, 0, 1e-4f)) - path(x - vec3(0, 0, 1e-4f))) / 2e-2f, 1e-3f);
  const vec3 gUnwarped = opticalPathGradient(x, light, camera, eta, true);
  EXPECT_NEAR(glm::length(gUnwarped), eta, 1e-5f);
}

TEST(FootprintKernel, NarrowMassesAreTheExactBinIntegralsInFloat) {
  // The float, branch-free masses of the histogram path against the double
  // CDF's bin integrals, for kernels touching 1 .. FOOTPRINT_DIRECT_BINS bins.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> centre(20.0f, 900.0f), width(0.0f, 6.0f), share(0.0f, 1.0f);
  int checked = 0;
  for (int n = 0; n < 4000; ++n) {
    const float a = width(rng), b = a * share(rng) * (n % 5 == 0 ? 0.0f : 1.0f);
    const vec3 kernel(centre(rng), std::max(a, b), std::min(a, b));
    if (!footprintIsNarrow(kernel)) continue;
    const int first = footprintNarrowFirstBin(kernel, 1024);
    const int count = footprintNarrowBinCount(kernel);
    ASSERT_GE(count, 1);
    ASSERT_LE(count, FOOTPRINT_DIRECT_BINS);
    double sum = 0.0;
    for (int j = 0; j < count; ++j) {
      const double exact = footprintCdf(kernel, first + j + 1.0) - footprintCdf(kernel, first + j);
      const float mass = footprintNarrowMass(kernel, j);
      EXPECT_NEAR(mass, exact, 1e-5) << kernel.x << " " << kernel.y << " " << kernel.z << " j " << j;
      EXPECT_GE(mass, 0.0f);
      sum += mass;
    }
    EXPECT_NEAR(sum, 1.0, 1e-6);
    ++checked;
  }
  EXPECT_GT(checked, 1000);
  // A spike and a kernel inside one bin give exactly their value to that bin.
  EXPECT_EQ(footprintNarrowMass(vec3(37.25f, 0.0f, 0.0f), 0), 1.0f);
  EXPECT_EQ(footprintNarrowBinCount(vec3(37.25f, 0.3f, 0.1f)), 1);
  EXPECT_EQ(footprintNarrowMass(vec3(37.25f, 0.3f, 0.1f), 0), 1.0f);
}

TEST(FootprintKernel, KinkWeightsGiveTheCdfsSecondDifferences) {
  // Wide kernels' slot values from the kinks' B-spline weights against the
  // same second differences from the CDF (which the tests above validate).
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> centre(40.0f, 900.0f), width(1.0f, 300.0f), share(0.0f, 1.0f);
  for (int n = 0; n < 400; ++n) {
    const float a = width(rng), b = n % 7 == 0 ? 0.0f : a * share(rng) * share(rng);
    const vec3 kernel(centre(rng), a, b);
    for (int slot = 0; slot < FOOTPRINT_SLOTS; ++slot) {
      const int bin = footprintSlotBin(kernel, slot, 1024);
      if (bin < 0) continue;
      EXPECT_NEAR(footprintSlotValue(kernel, bin), footprintSlotValueFromCdf(kernel, bin),
                  1e-9 + 1e-9 / (double(a) * std::max(double(b), 1e-3)))
          << kernel.x << " " << a << " " << b << " bin " << bin;
    }
  }
}

TEST(FootprintKernel, FourWidthsKeepTheVarianceAndThePixelsTrapezoid) {
  // Without a VPL patch: exactly the pixel's two boxes.
  const vec2 pixel = footprintWidths(vec4(0.012f, -0.0034f, 0.0f, 0.0f), 0.003f);
  EXPECT_EQ(pixel.x, std::abs(0.012f) / 0.003f);
  EXPECT_EQ(pixel.y, std::abs(-0.0034f) / 0.003f);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> step(-0.05f, 0.05f);
  for (int n = 0; n < 200; ++n) {
    const vec4 steps(step(rng), step(rng), step(rng), step(rng));
    const vec2 w = footprintWidths(steps, 0.003f);
    const vec4 bins = abs(steps) / 0.003f;
    // Variance (A^2 + B^2) / 12 of the trapezoid = that of the four boxes' sum.
    EXPECT_NEAR(w.x * w.x + w.y * w.y, dot(bins, bins), 1e-4 * dot(bins, bins));
    EXPECT_GE(w.x, w.y);
    EXPECT_GE(w.x, std::max(std::max(bins.x, bins.y), std::max(bins.z, bins.w)) * 0.999f);
  }
}

}  // namespace
}  // namespace tofsim::physics
