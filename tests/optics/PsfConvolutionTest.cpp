// optics::applyPsf: a lit pixel's image is the kernel, the separable passes
// and the FFT equal the direct sum, a plane's light is kept where the kernel
// stays in the image and what leaves the border is lost (exactly the kernel's
// mass off the sensor), and the memory layout and thread count change no bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <vector>

#include "tofsim/optics/PsfConvolution.h"

namespace tofsim::optics {
namespace {

const PsfKernel& gaussianHalo() {
  static const PsfKernel k = PsfKernel::parametric({0.9, 0.2, HaloProfile::Gaussian, 2.5});
  return k;
}
const PsfKernel& exponentialHalo() {
  static const PsfKernel k = PsfKernel::parametric({0.6, 0.1, HaloProfile::Exponential, 1.5});
  return k;
}
const PsfKernel& measured() {  // asymmetric, so a flipped kernel would show
  static const PsfKernel k = PsfKernel::fromImage(
      {0, 1, 0, 0, 0, 2, 8, 1, 0, 0, 1, 3, 40, 5, 1, 0, 0, 2, 9, 1, 0, 0, 0, 1, 4}, 5, 5);
  return k;
}

std::vector<double> randomPlane(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> p(static_cast<std::size_t>(w) * h);
  for (double& v : p) v = u(rng);
  return p;
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

double maxAbsDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

std::vector<double> convolved(const PsfKernel& k, std::vector<double> plane, int w, int h,
                              PsfMethod method) {
  applyPsf(k, plane.data(), 1, PlaneLayout{w, h, 1, plane.size()}, {method, 1});
  return plane;
}

TEST(PsfConvolutionTest, ALitPixelImagesTheKernel) {
  constexpr int w = 41, h = 37, x0 = 23, y0 = 17;  // off centre: the kernel must not flip
  for (const PsfKernel* k : {&gaussianHalo(), &exponentialHalo(), &measured()}) {
    for (const PsfMethod m : {PsfMethod::Auto, PsfMethod::Direct, PsfMethod::Fft}) {
      std::vector<double> plane(w * h, 0.0);
      plane[y0 * w + x0] = 1.0;
      const std::vector<double> out = convolved(*k, plane, w, h, m);
      double worst = 0.0;
      for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
          worst = std::max(worst, std::abs(out[y * w + x] - k->at(x - x0, y - y0)));
        }
      }
      EXPECT_LT(worst, 1e-15) << "method " << int(m);
    }
  }
}

// out(x, y) = sum over the image's pixels (x', y') of K(x - x', y - y') in(x', y'),
// written as the definition reads: the oracle of the direct sum.
std::vector<double> bruteForce(const PsfKernel& k, const std::vector<double>& in, int w, int h) {
  std::vector<double> out(in.size(), 0.0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int y1 = 0; y1 < h; ++y1) {
        for (int x1 = 0; x1 < w; ++x1) out[y * w + x] += k.at(x - x1, y - y1) * in[y1 * w + x1];
      }
    }
  }
  return out;
}

TEST(PsfConvolutionTest, SeparableAndFftEqualTheDirectSum) {
  constexpr int w = 23, h = 19;
  const std::vector<double> plane = randomPlane(w, h, 7);
  // The last one reaches far past the image (radius 48): cropped, it must
  // give the same pixels.
  const PsfKernel wide = PsfKernel::parametric({0.5, 0.3, HaloProfile::Exponential, 4.0});
  ASSERT_GT(wide.radiusX(), w);
  for (const PsfKernel* k : {&gaussianHalo(), &exponentialHalo(), &measured(), &wide}) {
    const std::vector<double> direct = convolved(*k, plane, w, h, PsfMethod::Direct);
    EXPECT_LT(maxAbsDifference(direct, bruteForce(*k, plane, w, h)),
              1e-12 * *std::max_element(direct.begin(), direct.end()));
    const double scale = *std::max_element(direct.begin(), direct.end());
    const double sep = maxAbsDifference(convolved(*k, plane, w, h, PsfMethod::Auto), direct);
    const double fft = maxAbsDifference(convolved(*k, plane, w, h, PsfMethod::Fft), direct);
    std::printf("auto vs direct %.2e, fft vs direct %.2e (relative to the peak)\n", sep / scale,
                fft / scale);
    EXPECT_LT(sep, 1e-12 * scale);
    EXPECT_LT(fft, 1e-12 * scale);
    EXPECT_GT(maxAbsDifference(direct, plane), 1e-3 * scale);  // the kernel does something
  }
}

TEST(PsfConvolutionTest, KeepsThePlanesLightInsideAndLosesWhatLeavesTheBorder) {
  constexpr int w = 64, h = 48;
  for (const PsfKernel* k : {&gaussianHalo(), &exponentialHalo(), &measured()}) {
    const int rx = k->radiusX(), ry = k->radiusY();
    ASSERT_LT(2 * rx + 8, w);
    ASSERT_LT(2 * ry + 8, h);
    // Lit only where the whole kernel lands in the image.
    std::vector<double> plane = randomPlane(w, h, 11);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (x < rx || x >= w - rx || y < ry || y >= h - ry) plane[y * w + x] = 0.0;
      }
    }
    for (const PsfMethod m : {PsfMethod::Auto, PsfMethod::Direct, PsfMethod::Fft}) {
      const double before = sum(plane), after = sum(convolved(*k, plane, w, h, m));
      std::printf("method %d: plane sum kept to %.1e relative\n", int(m),
                  std::abs(after - before) / before);
      EXPECT_NEAR(after, before, 1e-12 * before) << "method " << int(m);
    }
    // A pixel in the corner: what stays is the kernel's mass on the sensor.
    std::vector<double> corner(w * h, 0.0);
    corner[1 * w + 2] = 1.0;
    double kept = 0.0;
    for (int dy = -ry; dy <= ry; ++dy) {
      for (int dx = -rx; dx <= rx; ++dx) {
        if (2 + dx >= 0 && 1 + dy >= 0) kept += k->at(dx, dy);
      }
    }
    EXPECT_LT(kept, 0.999);
    EXPECT_NEAR(sum(convolved(*k, corner, w, h, PsfMethod::Auto)), kept, 1e-14);
  }
}

TEST(PsfConvolutionTest, TransientLayoutThreadsAndFloatsGiveTheSameValues) {
  // (H, W, T, C) with T = 5, C = 3: plane t C + c, bins 1 and 4 dark.
  constexpr int w = 17, h = 13, T = 5, C = 3;
  std::vector<std::vector<double>> planes(T * C);
  for (int j = 0; j < T * C; ++j) {
    planes[j] =
        (j / C == 1 || j / C == 4) ? std::vector<double>(w * h, 0.0) : randomPlane(w, h, 100 + j);
  }
  std::vector<float> volume(static_cast<std::size_t>(w) * h * T * C);
  for (int j = 0; j < T * C; ++j) {
    for (int p = 0; p < w * h; ++p) volume[p * T * C + j] = float(planes[j][p]);
  }
  const PlaneLayout layout{w, h, T * C, 1};
  for (const PsfKernel* k : {&gaussianHalo(), &exponentialHalo()}) {
    std::vector<float> one = volume, three = volume;
    applyPsf(*k, one.data(), T * C, layout, {PsfMethod::Auto, 1});
    applyPsf(*k, three.data(), T * C, layout, {PsfMethod::Auto, 3});
    EXPECT_EQ(one, three);
    for (int j = 0; j < T * C; ++j) {
      std::vector<double> p(w * h);
      for (int i = 0; i < w * h; ++i) p[i] = double(float(planes[j][i]));
      const std::vector<double> expected = convolved(*k, p, w, h, PsfMethod::Direct);
      for (int i = 0; i < w * h; ++i) {
        ASSERT_NEAR(one[i * T * C + j], expected[i], 1e-7 * std::abs(expected[i]) + 1e-30)
            << "plane " << j << " pixel " << i;
      }
    }
  }
}

// The cost the lens adds, printed: a 128 x 128 CW-ToF camera's 9 raw images
// and 64 lit bins x 3 channels of a 128 x 128 transient, on one thread.
TEST(PsfConvolutionTest, PrintsItsCost) {
  constexpr int w = 128, h = 128;
  for (const auto& [name, kernel] :
       {std::pair{"core 0.7 + gaussian halo 8 px",
                  PsfKernel::parametric({0.7, 0.1, HaloProfile::Gaussian, 8.0}, 127)},
        std::pair{"core 0.7 + exponential halo 8 px",
                  PsfKernel::parametric({0.7, 0.1, HaloProfile::Exponential, 8.0}, 127)}}) {
    for (const int planes : {9, 192}) {
      std::vector<float> data(static_cast<std::size_t>(planes) * w * h, 1.0f);
      const auto t0 = std::chrono::steady_clock::now();
      applyPsf(kernel, data.data(), planes, h, w);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("%s: %d planes of 128 x 128 in %.3f s (%.2f ms a plane)\n", name, planes, s,
                  1e3 * s / planes);
      EXPECT_LT(s, 30.0);
    }
  }
}

}  // namespace
}  // namespace tofsim::optics
