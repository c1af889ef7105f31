// The CPU gather's footprint deposit (core/cpu/src/FootprintDeposit.h: AVX2
// where the CPU has it) against the scalar reference it must match bit for
// bit, physics::depositContribution, contribution by contribution in the
// same order: narrow kernels of every bin count on and off the axis, wide
// ones with their kinks apart and sharing bins, boxes, kernels near the
// axis start (the CDF's slots) and past its end, and non-finite energies.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "FootprintDeposit.h"
#include "tofsim/physics/FootprintBuffer.h"

namespace tofsim::cpu {
namespace {

constexpr int32_t kBins = 200;

struct Contribution {
  glm::vec3 kernel;
  glm::vec3 energy;
};

// Kernels of every kind the deposit branches on, in a random order.
std::vector<Contribution> contributions(std::size_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<Contribution> out;
  while (out.size() < count) {
    const int kind = static_cast<int>(unit(rng) * 6.0f);
    const float centre = -30.0f + unit(rng) * (kBins + 60.0f);
    float wide = 0.0f, narrow = 0.0f;
    switch (kind) {
      case 0:  // narrow: 1 to 16 bins
        wide = unit(rng) * 15.0f;
        narrow = unit(rng) * wide;
        break;
      case 1:  // a spike, or a box one bin wide at most
        wide = unit(rng) < 0.5f ? 0.0f : unit(rng);
        break;
      case 2:  // wide, kinks apart or sharing bins
        wide = 8.0f + unit(rng) * 20.0f;
        narrow = unit(rng) * wide;
        break;
      case 3:  // wide boxes (narrow under 1e-6 bins)
        wide = 16.0f + unit(rng) * 40.0f;
        narrow = unit(rng) < 0.5f ? 0.0f : 1e-7f;
        break;
      case 4:  // wide with the narrow ramps under three bins
        wide = 16.0f + unit(rng) * 30.0f;
        narrow = unit(rng) * 3.0f;
        break;
      default:  // wider than the axis
        wide = 100.0f + unit(rng) * 400.0f;
        narrow = unit(rng) * wide;
        break;
    }
    const glm::vec3 energy(unit(rng), unit(rng) * 2.0f, unit(rng) * 0.5f);
    out.push_back({glm::vec3(centre, wide, narrow), energy});
  }
  // Non-finite energies: the same entries must turn non-finite.
  out[count / 3].energy.g = std::numeric_limits<float>::infinity();
  out[2 * count / 3].energy.b = std::numeric_limits<float>::quiet_NaN();
  return out;
}

TEST(FootprintDeposit, MatchesTheScalarDepositBitForBit) {
  const std::vector<Contribution> all = contributions(20000, 7);
  const std::size_t stride = static_cast<std::size_t>(kBins) * 3;
  std::vector<float> histogram(stride, 0.0f), expectedHistogram(stride, 0.0f);
  std::vector<double> diff(stride, 0.0), expectedDiff(stride, 0.0);
  physics::OffAxisSums lost, expectedLost;
  int32_t first = INT32_MAX, last = -1;
  auto terms = std::make_unique<VplTerms>();
  std::vector<BlockPair> pairs;
  // Two samples per pixel, lanes in blocks: the pairs name (sample, lane).
  auto samples = std::make_unique<VplTerms[]>(2);
  for (std::size_t start = 0; start < all.size(); start += 2 * kVplBlock) {
    pairs.clear();
    for (std::size_t k = start; k < std::min(all.size(), start + 2 * kVplBlock); ++k) {
      const auto s = static_cast<uint32_t>((k - start) % 2);
      const auto lane = static_cast<uint32_t>((k - start) / 2);
      VplTerms& t = samples[s];
      const glm::vec3 kernel = all[k].kernel;
      t.centre[lane] = kernel.x, t.wide[lane] = kernel.y, t.narrow[lane] = kernel.z;
      t.r[lane] = all[k].energy.r, t.g[lane] = all[k].energy.g, t.b[lane] = all[k].energy.b;
      t.first[lane] = physics::footprintNarrowFirstBin(kernel, kBins);
      t.count[lane] =
          physics::footprintIsNarrow(kernel) ? physics::footprintNarrowBinCount(kernel) : 0;
      // As vplKernels fills them: the narrow kernel's shape, checked with
      // the deposit against the scalar physics.
      const NarrowShape shape = narrowShapeOf(kernel);
      t.frac[lane] = shape.frac, t.last[lane] = shape.last;
      t.perRamps[lane] = shape.perRamps, t.perWide[lane] = shape.perWide;
      pairs.push_back({s, lane});
      physics::depositContribution(expectedHistogram.data(), expectedDiff.data(), kBins, kernel,
                                   all[k].energy, expectedLost);
    }
    depositFootprints(samples.get(), pairs.data(), pairs.size(), kBins, histogram.data(),
                      diff.data(), lost, first, last);
  }
  EXPECT_EQ(std::memcmp(histogram.data(), expectedHistogram.data(), stride * sizeof(float)), 0);
  EXPECT_EQ(std::memcmp(diff.data(), expectedDiff.data(), stride * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&lost, &expectedLost, sizeof lost), 0);
  // The written bins' range holds every entry that is not +0.
  for (int32_t bin = 0; bin < kBins; ++bin) {
    if (bin >= first && bin <= last) continue;
    for (int c = 0; c < 3; ++c) {
      const double entry = diff[static_cast<std::size_t>(bin) * 3 + c];
      EXPECT_TRUE(entry == 0.0 && !std::signbit(entry)) << "bin " << bin;
    }
  }
}

TEST(FootprintDeposit, NarrowKernelMatchesDepositNarrowForEveryBinCount) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int trial = 0; trial < 5000; ++trial) {
    const float wide = unit(rng) * 15.0f;
    const glm::vec3 k(-20.0f + unit(rng) * 240.0f, wide, unit(rng) * wide);
    if (!physics::footprintIsNarrow(k)) continue;
    const glm::vec3 energy(1.0f, 0.5f, 0.25f);
    std::vector<float> a(kBins * 3, 0.0f), b(kBins * 3, 0.0f);
    physics::OffAxisSums lostA, lostB;
    depositNarrowKernel(a.data(), kBins, k, physics::footprintNarrowFirstBin(k, kBins),
                        physics::footprintNarrowBinCount(k), energy, lostA);
    physics::depositNarrow(b.data(), kBins, k, energy, lostB);
    ASSERT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0)
        << "kernel " << k.x << " " << k.y << " " << k.z;
    ASSERT_EQ(std::memcmp(&lostA, &lostB, sizeof lostA), 0);
  }
}

}  // namespace
}  // namespace tofsim::cpu
