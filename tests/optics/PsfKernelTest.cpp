// optics::PsfKernel: every kernel sums to 1, the parametric one is
// (1 - s) core + s halo with the closed-form pixel-integrated Gaussian (erf)
// and exponential profiles, and bad parameters or kernel images are errors.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numeric>
#include <string>

#include "tofsim/optics/PsfKernel.h"
#include "tofsim/util/Error.h"

namespace tofsim::optics {
namespace {

double total(const PsfKernel& k) {
  const std::vector<double> image = k.image();
  return std::accumulate(image.begin(), image.end(), 0.0);
}

// The share of a pixel-integrated unit Gaussian in pixel i, unnormalised.
double gaussianMass(int i, double sigma) {
  const double k = 1.0 / (sigma * std::sqrt(2.0));
  return 0.5 * (std::erf((i + 0.5) * k) - std::erf((i - 0.5) * k));
}

TEST(PsfKernelTest, EveryKindSumsToOne) {
  const PsfKernel kernels[] = {
      PsfKernel(),
      PsfKernel::parametric({0.7, 0.0, HaloProfile::Gaussian, 0.0}),
      PsfKernel::parametric({0.0, 0.2, HaloProfile::Gaussian, 6.0}),
      PsfKernel::parametric({1.3, 0.05, HaloProfile::Exponential, 4.0}),
      PsfKernel::fromImage({1, 2, 3, 4, 5, 6, 7, 8, 9, 1, 1, 1, 1, 1, 1}, 3, 5),
  };
  for (const PsfKernel& k : kernels) EXPECT_NEAR(total(k), 1.0, 1e-13);
}

TEST(PsfKernelTest, ParametricIsCorePlusHaloInClosedForm) {
  const double sigma = 0.8, s = 0.15, halo = 3.0;
  const PsfKernel g = PsfKernel::parametric({sigma, s, HaloProfile::Gaussian, halo});
  // The Gaussians' normalisations over their cut supports, summed here.
  const int rc = static_cast<int>(std::ceil(5.0 * sigma)), rh = static_cast<int>(15.0);
  double zc = 0.0, zh = 0.0;
  for (int i = -rc; i <= rc; ++i) zc += gaussianMass(i, sigma);
  for (int i = -rh; i <= rh; ++i) zh += gaussianMass(i, halo);
  EXPECT_EQ(g.radiusX(), rh);
  for (const auto& [dx, dy] : {std::pair{0, 0}, {1, 0}, {2, -3}, {-4, 1}, {10, 12}}) {
    const double core = std::abs(dx) <= rc && std::abs(dy) <= rc
                            ? gaussianMass(dx, sigma) * gaussianMass(dy, sigma) / (zc * zc)
                            : 0.0;
    const double expected =
        (1.0 - s) * core + s * gaussianMass(dx, halo) * gaussianMass(dy, halo) / (zh * zh);
    EXPECT_NEAR(g.at(dx, dy), expected, 1e-15) << dx << ", " << dy;
  }
  // Exponential halo: exp(-r / R) over the disc r <= 12 R.
  const double R = 2.5;
  const PsfKernel e = PsfKernel::parametric({0.0, s, HaloProfile::Exponential, R});
  double z = 0.0;
  for (int dy = -30; dy <= 30; ++dy) {
    for (int dx = -30; dx <= 30; ++dx) {
      const double r = std::hypot(dx, dy);
      if (r <= 12.0 * R) z += std::exp(-r / R);
    }
  }
  EXPECT_NEAR(e.at(0, 0), 1.0 - s + s / z, 1e-15);
  EXPECT_NEAR(e.at(3, -4), s * std::exp(-5.0 / R) / z, 1e-15);
  EXPECT_DOUBLE_EQ(e.at(30, 0), s * std::exp(-30.0 / R) / z);
  EXPECT_EQ(e.at(22, 22), 0.0);  // r = 31.1 > 12 R
}

TEST(PsfKernelTest, CroppingKeepsTheValuesItKeeps) {
  const PsfParams p{0.5, 0.3, HaloProfile::Exponential, 5.0};
  const PsfKernel full = PsfKernel::parametric(p), cropped = PsfKernel::parametric(p, 7);
  EXPECT_EQ(cropped.radiusX(), 7);
  EXPECT_EQ(full.radiusX(), 60);
  for (int d = -7; d <= 7; ++d) EXPECT_EQ(cropped.at(d, 3), full.at(d, 3));
  EXPECT_LT(total(cropped), 1.0);
}

TEST(PsfKernelTest, ImageIsNormalisedAndKeepsItsOrientation) {
  // 3 rows x 5 columns: K(dx, dy) is row dy + 1, column dx + 2.
  const PsfKernel k = PsfKernel::fromImage({0, 0, 0, 0, 0, 0, 0, 2, 6, 0, 0, 0, 0, 0, 2}, 3, 5);
  EXPECT_EQ(k.radiusX(), 2);
  EXPECT_EQ(k.radiusY(), 1);
  EXPECT_DOUBLE_EQ(k.at(0, 0), 0.2);
  EXPECT_DOUBLE_EQ(k.at(1, 0), 0.6);
  EXPECT_DOUBLE_EQ(k.at(2, 1), 0.2);
  EXPECT_EQ(k.at(-1, 0), 0.0);
}

void expectError(const std::function<void()>& f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no error; expected '" << fragment << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(PsfKernelTest, BadParametersAndImagesAreErrors) {
  expectError(
      [] {
        PsfKernel::parametric({0.0, 1.0, HaloProfile::Gaussian, 5.0});
      },
      "weight must be in [0, 1)");
  expectError(
      [] {
        PsfKernel::parametric({0.0, -0.1, HaloProfile::Gaussian, 5.0});
      },
      "weight must be in [0, 1)");
  expectError(
      [] {
        PsfKernel::parametric({-1.0, 0.0, HaloProfile::Gaussian, 0.0});
      },
      "sigma must be >= 0");
  expectError(
      [] {
        PsfKernel::parametric({0.0, 0.1, HaloProfile::Exponential, 0.0});
      },
      "radius must be > 0");
  expectError([] { PsfKernel::fromImage({1, 1, 1, 1}, 2, 2); }, "odd sizes");
  expectError(
      [] {
        PsfKernel::fromImage({1, 1, 1, 1, -0.5, 1, 1, 1, 1}, 3, 3);
      },
      "(y, x) = (1, 1) is negative");
  expectError([] { PsfKernel::fromImage({0, 0, 0}, 1, 3); }, "must not all be 0");
}

}  // namespace
}  // namespace tofsim::optics
