#pragma once
// Issue 42, item 2: the homogeneous medium filling the scene attenuates every
// leg of a path by exp(-sigma_t x) over its geometric length x. A render's
// components (direct, indirect, bounce1..N) as whole-image volumes, and the
// closed form of a purely absorbing medium per time bin: with point sampling
// (render.pixel_footprint: false) every contribution in bin b has an optical
// path in [start + b w, start + (b + 1) w], so the bin's value with the
// medium over its value without lies between exp(-sigma_a x path / eta) at
// the bin's two edges, channel by channel.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "support/MediumPoints.h"
#include "support/TestJobs.h"
#include "tofsim/capture/Renderer.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::test {

/// Every named component of the streamed segments, whole-image volumes in
/// pixel order.
struct ComponentVolumes : capture::SegmentSink {
  explicit ComponentVolumes(std::size_t floatsPerPixel) : floatsPerPixel(floatsPerPixel) {}
  void consume(const capture::Segment& segment) override {
    for (const capture::SegmentComponent& c : segment.components) {
      std::vector<float>& v = volumes[std::string(c.name)];
      v.insert(v.end(), c.values, c.values + segment.pixelCount * floatsPerPixel);
    }
  }
  const std::vector<float>& at(const std::string& name) const { return volumes.at(name); }
  std::size_t floatsPerPixel;
  std::map<std::string, std::vector<float>> volumes;
};

inline ComponentVolumes renderComponents(const capture::Renderer& renderer,
                                         const capture::RenderJob& job) {
  ComponentVolumes out(static_cast<std::size_t>(job.settings.time.bins) * capture::kChannels);
  renderer.render(job, out);
  return out;
}

/// The job with a purely absorbing medium of sigma_a per channel (1/m).
inline capture::RenderJob withAbsorbingMedium(capture::RenderJob job, const glm::vec3& sigmaA) {
  job.settings.medium.sigma_a_per_m = sigmaA;
  return job;
}

/// How many of the bins that carry light (above 1e-6 of the brightest) hold
/// withMedium / without within the band exp(-sigma_a path / eta) over the
/// bin's optical paths (and a hundredth of a bin either side for the float
/// rounding of the binning), per channel; every such bin must. Returns the
/// number of bins checked (so that a test can insist there are some).
inline std::size_t expectAbsorbedPerBin(const std::vector<float>& without,
                                        const std::vector<float>& withMedium, const TimeAxis& axis,
                                        const glm::vec3& sigmaA, const std::string& what) {
  EXPECT_EQ(without.size(), withMedium.size()) << what;
  if (without.size() != withMedium.size()) return 0;
  float brightest = 0.0f;
  for (const float v : without) brightest = std::max(brightest, v);
  const double start = axis.start_m(), width = axis.bin_width_m();
  const double eta = axis.index_of_refraction;
  const auto bins = static_cast<std::size_t>(axis.bins);
  std::size_t checked = 0, failed = 0;
  for (std::size_t i = 0; i < without.size(); ++i) {
    if (!(without[i] > 1e-6f * brightest)) continue;
    const std::size_t channel = i % capture::kChannels;
    const std::size_t bin = (i / capture::kChannels) % bins;
    const double lo = (start + (static_cast<double>(bin) - 0.01) * width) / eta;
    const double hi = (start + (static_cast<double>(bin) + 1.01) * width) / eta;
    const double sigma = sigmaA[static_cast<int>(channel)];
    const double ratio = static_cast<double>(withMedium[i]) / without[i];
    const double most = std::exp(-sigma * lo) * (1.0 + 1e-5);
    const double least = std::exp(-sigma * hi) * (1.0 - 1e-5);
    ++checked;
    if (ratio > most || ratio < least) {
      if (++failed <= 5) {
        ADD_FAILURE() << what << ": value " << i << " (bin " << bin << ", channel " << channel
                      << "): ratio " << ratio << " outside [" << least << ", " << most << "]";
      }
    }
  }
  EXPECT_EQ(failed, 0u) << what << ": of " << checked << " bins";
  return checked;
}

/// With footprints (render.pixel_footprint: true) a contribution spreads over
/// the bins about its path, so a bin no longer bounds its paths: instead each
/// pixel's energy per channel with the medium is that without, bin by bin
/// times exp(-sigma_a x the bin centre's path / eta), within `tolerance`
/// relative: a sample is attenuated at its own path, while its kernel
/// spreads its light over the paths across its footprint, where exp bends
/// (about (sigma h)^2 / 6 for a kernel of half-width h: 0.4 % at the
/// corner's far grazing pixels, blue).
/// Returns the number of (pixel, channel) pairs checked.
inline std::size_t expectAbsorbedPerPixel(const std::vector<float>& without,
                                          const std::vector<float>& withMedium,
                                          const TimeAxis& axis, const glm::vec3& sigmaA,
                                          double tolerance, const std::string& what) {
  EXPECT_EQ(without.size(), withMedium.size()) << what;
  if (without.size() != withMedium.size()) return 0;
  const auto bins = static_cast<std::size_t>(axis.bins);
  const std::size_t perPixel = bins * capture::kChannels;
  const double start = axis.start_m(), width = axis.bin_width_m();
  const double eta = axis.index_of_refraction;
  std::vector<double> expected, got, total;
  for (std::size_t p = 0; p < without.size() / perPixel; ++p) {
    for (std::size_t c = 0; c < capture::kChannels; ++c) {
      double e = 0.0, g = 0.0, t = 0.0;
      for (std::size_t b = 0; b < bins; ++b) {
        const std::size_t i = p * perPixel + b * capture::kChannels + c;
        const double path = (start + (static_cast<double>(b) + 0.5) * width) / eta;
        e += without[i] * std::exp(-static_cast<double>(sigmaA[static_cast<int>(c)]) * path);
        g += withMedium[i];
        t += without[i];
      }
      expected.push_back(e), got.push_back(g), total.push_back(t);
    }
  }
  const double brightest = *std::max_element(total.begin(), total.end());
  std::size_t checked = 0, failed = 0;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    if (!(total[k] > 1e-4 * brightest)) continue;
    ++checked;
    if (std::abs(got[k] - expected[k]) > tolerance * expected[k] && ++failed <= 5) {
      ADD_FAILURE() << what << ": pixel " << k / capture::kChannels << " channel "
                    << k % capture::kChannels << ": " << got[k] << ", expected " << expected[k];
    }
  }
  EXPECT_EQ(failed, 0u) << what << ": of " << checked << " pixel channels";
  return checked;
}

/// sigma_a of the tests' absorbing medium, 1/m: different per channel, so
/// that a channel mix-up shows.
inline const glm::vec3 kMediumSigmaA(0.15f, 0.4f, 0.8f);

using MakeRenderer = std::function<std::unique_ptr<capture::Renderer>()>;

/// The corner with one-bounce light, point-sampled pixels, in water's eta
/// (a leg's geometric length is its optical path / eta), 1 cm bins.
inline CornerJob absorbingCornerJob(int32_t side = 16) {
  CornerJob s(side);
  s.job.settings.indirect.rsm_resolution = 16;
  s.job.settings.pixel_footprint = false;
  s.job.settings.time.index_of_refraction = 1.33;
  s.job.settings.time.bins = 1500;  // 15 m of optical path: no light past the axis
  return s;
}

/// The corner's direct and one-bounce light (side x side pixels), with ISMs
/// and exact visibility: every bin absorbed by its path.
inline void expectCornerAbsorbedPerBin(const MakeRenderer& make, int32_t side = 16,
                                       const glm::vec3& sigmaA = kMediumSigmaA) {
  for (const capture::Visibility visibility :
       {capture::Visibility::Ism, capture::Visibility::Exact}) {
    SCOPED_TRACE(visibility == capture::Visibility::Ism ? "ISM" : "exact");
    CornerJob s = absorbingCornerJob(side);
    s.job.settings.indirect.visibility = visibility;
    const ComponentVolumes vacuum = renderComponents(*make(), s.job);
    const ComponentVolumes fog = renderComponents(*make(), withAbsorbingMedium(s.job, sigmaA));
    const TimeAxis& axis = s.job.settings.time;
    for (const char* part : {"direct", "indirect"}) {
      EXPECT_GT(expectAbsorbedPerBin(vacuum.at(part), fog.at(part), axis, sigmaA, part), 100u);
    }
  }
}

/// 2 x 2 sub-pixel samples (merged where `merge`:
/// render.indirect.merge_pixel_samples, a CPU option; only at edges where
/// `adaptive`: render.adaptive_pixel_samples), point-sampled (bin by bin) and
/// with footprints (pixel by pixel, weighed by the bins: a kernel spreads a
/// few bins about its path).
inline void expectSubPixelSamplesAbsorbed(const MakeRenderer& make, bool merge, int32_t side = 16,
                                          bool adaptive = false) {
  CornerJob s = absorbingCornerJob(side);
  s.job.settings.pixel_samples = 2;
  s.job.settings.indirect.merge_pixel_samples = merge;
  s.job.settings.adaptive_pixel_samples = adaptive;
  const TimeAxis& axis = s.job.settings.time;
  for (const bool footprint : {false, true}) {
    SCOPED_TRACE(footprint ? "footprints" : "point pixels");
    s.job.settings.pixel_footprint = footprint;
    const ComponentVolumes vacuum = renderComponents(*make(), s.job);
    const ComponentVolumes fog =
        renderComponents(*make(), withAbsorbingMedium(s.job, kMediumSigmaA));
    for (const char* part : {"direct", "indirect"}) {
      const std::size_t checked =
          footprint
              ? expectAbsorbedPerPixel(vacuum.at(part), fog.at(part), axis, kMediumSigmaA, 1e-2,
                                       part)
              : expectAbsorbedPerBin(vacuum.at(part), fog.at(part), axis, kMediumSigmaA, part);
      EXPECT_GT(checked, 100u) << part;
    }
  }
}

/// A volume summed over its bins, per pixel and channel.
inline std::vector<double> pixelSums(const std::vector<float>& v, int32_t bins) {
  const std::size_t perPixel = static_cast<std::size_t>(bins) * capture::kChannels;
  std::vector<double> sums(v.size() / static_cast<std::size_t>(bins), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i) {
    sums[(i / perPixel) * capture::kChannels + i % capture::kChannels] += v[i];
  }
  return sums;
}

/// camera_unwarp moves each contribution to the bin of its path without the
/// camera leg; its energy stays the warped render's, attenuation and all
/// (and below the vacuum's).
inline void expectUnwarpKeepsAttenuation(const MakeRenderer& make, int32_t side = 16) {
  const CornerJob s = absorbingCornerJob(side);
  const capture::RenderJob fog = withAbsorbingMedium(s.job, kMediumSigmaA);
  capture::RenderJob fogUnwarped = fog, vacuumUnwarped = s.job;
  fogUnwarped.settings.time.camera_unwarp = vacuumUnwarped.settings.time.camera_unwarp = true;
  const ComponentVolumes warped = renderComponents(*make(), fog);
  const ComponentVolumes unwarped = renderComponents(*make(), fogUnwarped);
  const ComponentVolumes vacuum = renderComponents(*make(), vacuumUnwarped);
  const int32_t bins = s.job.settings.time.bins;
  for (const char* part : {"direct", "indirect"}) {
    SCOPED_TRACE(part);
    const std::vector<double> a = pixelSums(warped.at(part), bins);
    const std::vector<double> b = pixelSums(unwarped.at(part), bins);
    const std::vector<double> v = pixelSums(vacuum.at(part), bins);
    const double brightest = *std::max_element(v.begin(), v.end());
    std::size_t lit = 0, failed = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      if (!(v[k] > 1e-4 * brightest)) continue;
      ++lit;
      if ((std::abs(b[k] - a[k]) > 1e-4 * a[k] || !(b[k] < v[k])) && ++failed <= 5) {
        ADD_FAILURE() << "pixel " << k / 3 << " channel " << k % 3 << ": unwarped " << b[k]
                      << ", warped " << a[k] << ", vacuum " << v[k];
      }
    }
    EXPECT_EQ(failed, 0u);
    EXPECT_GT(lit, 100u);
  }
}

/// Given medium points (support/MediumPoints.h: a point-set imager's samples
/// of VERTEX_MEDIUM) lit directly: each point's light is exp(-sigma_a (|l - x|
/// + |x - origin|)) of the vacuum's, both legs exactly. `render` renders a
/// job with the given samples.
inline void expectMediumPointsAbsorbed(
    const std::function<ComponentVolumes(const capture::RenderJob&, const ir::SurfaceImage&)>&
        render) {
  const MediumPoints m;
  const ir::SurfaceImage given = m.samples(physics::VERTEX_MEDIUM, glm::vec3(0.0f));
  const ComponentVolumes vacuum = render(m.job, given);
  const ComponentVolumes fog = render(withAbsorbingMedium(m.job, kMediumSigmaA), given);
  const std::vector<double> a = pixelSums(vacuum.at("direct"), m.job.settings.time.bins);
  const std::vector<double> b = pixelSums(fog.at("direct"), m.job.settings.time.bins);
  for (std::size_t p = 0; p < m.points.size(); ++p) {
    const float legs =
        glm::length(m.job.light.position_world - m.points[p]) + glm::length(m.points[p] - m.origin);
    for (int c = 0; c < 3; ++c) {
      const std::size_t k = p * capture::kChannels + static_cast<std::size_t>(c);
      ASSERT_GT(a[k], 0.0) << "point " << p;
      EXPECT_NEAR(b[k], a[k] * std::exp(-kMediumSigmaA[c] * legs), 1e-5 * a[k])
          << "point " << p << " channel " << c;
    }
  }
}

}  // namespace tofsim::test
