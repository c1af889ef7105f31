// The reference's continuation on glossy surfaces (render.materials: gltf):
// the cosine + GGX visible-normal mixture (ContinuationSampling::BrdfMixture)
// against cosine sampling weighted by pi f, on the floor + wall corner with a
// glossy metal floor. Both are unbiased, so their means over seeds agree; the
// mixture's per-pixel variance of the indirect light is lower at the same
// sample count. On Lambertian scenes the setting changes no byte.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "RenderReference.h"

namespace tofsim::reference {
namespace {

using namespace capture;

// Steady indirect radiance of every pixel (sum over bins and channels).
std::vector<double> steadyIndirect(const VolumeCollector& v) {
  std::vector<double> out;
  for (int y = 0; y < v.indirect.height(); ++y) {
    for (int x = 0; x < v.indirect.width(); ++x) {
      double sum = 0.0;
      for (int t = 0; t < v.indirect.bins(); ++t) {
        for (int c = 0; c < 3; ++c) sum += v.indirect.at(y, x, t, c);
      }
      out.push_back(sum);
    }
  }
  return out;
}

struct PixelMoments {
  double meanOfMeans = 0.0;      ///< over pixels and seeds
  double meanOfVariances = 0.0;  ///< per-pixel variance over seeds, averaged over pixels
  double renders = 0.0;          ///< pixels x seeds: independent estimates
};

PixelMoments momentsOverSeeds(test::CornerJob& s, ContinuationSampling sampling, int seeds) {
  ReferenceSettings settings;
  settings.pixel_filter = PixelFilter::Point;
  settings.samples_per_pixel = 16;
  settings.threads = 2;
  settings.sampling = sampling;
  std::vector<double> sum, sum2;
  for (int seed = 1; seed <= seeds; ++seed) {
    s.job.settings.seed = static_cast<uint64_t>(seed);
    const std::vector<double> px = steadyIndirect(test::renderReference(s.job, settings));
    sum.resize(px.size(), 0.0);
    sum2.resize(px.size(), 0.0);
    for (std::size_t i = 0; i < px.size(); ++i) {
      sum[i] += px[i];
      sum2[i] += px[i] * px[i];
    }
  }
  PixelMoments m;
  m.renders = static_cast<double>(sum.size()) * seeds;
  for (std::size_t i = 0; i < sum.size(); ++i) {
    const double mean = sum[i] / seeds;
    m.meanOfMeans += mean / sum.size();
    m.meanOfVariances += (sum2[i] - seeds * mean * mean) / (seeds - 1) / sum.size();
  }
  return m;
}

TEST(ReferenceGlossySampling, MixtureHasLowerVarianceThanCosineAndTheSameMean) {
  test::CornerJob s(16);
  s.scene.materials.at(0).metallic = 1.0f;  // the floor: a rough metal
  s.scene.materials.at(0).roughness = 0.3f;
  s.job.settings.materials = MaterialModel::Gltf;
  s.job.settings.pixel_footprint = false;
  constexpr int kSeeds = 16;
  const PixelMoments mixture = momentsOverSeeds(s, ContinuationSampling::BrdfMixture, kSeeds);
  const PixelMoments cosine = momentsOverSeeds(s, ContinuationSampling::Cosine, kSeeds);
  const double ratio = cosine.meanOfVariances / mixture.meanOfVariances;
  std::printf(
      "indirect: mean %.6g (mixture) vs %.6g (cosine); per-pixel variance %.4g vs %.4g, "
      "cosine / mixture = %.2f\n",
      mixture.meanOfMeans, cosine.meanOfMeans, mixture.meanOfVariances, cosine.meanOfVariances,
      ratio);
  EXPECT_GT(ratio, 3.0);
  // Unbiased both: the image means agree within 4 standard errors of their
  // difference (pixels and seeds are independent estimates).
  const double standardError = std::sqrt(mixture.meanOfVariances / mixture.renders +
                                         cosine.meanOfVariances / cosine.renders);
  EXPECT_NEAR(mixture.meanOfMeans, cosine.meanOfMeans, 4.0 * standardError);
}

TEST(ReferenceGlossySampling, LambertianBytesDoNotDependOnTheSampling) {
  test::CornerJob s(12);
  ReferenceSettings settings;
  settings.samples_per_pixel = 8;
  settings.threads = 2;
  const VolumeCollector mixture = test::renderReference(s.job, settings);
  settings.sampling = ContinuationSampling::Cosine;
  const VolumeCollector cosine = test::renderReference(s.job, settings);
  EXPECT_EQ(mixture.indirect.values(), cosine.indirect.values());
  EXPECT_EQ(mixture.direct.values(), cosine.direct.values());
}

}  // namespace
}  // namespace tofsim::reference
