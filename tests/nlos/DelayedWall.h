#pragma once
// The hidden patch's relay wall with a scattering delay (issue 41's last
// item): the laser spot stands on the wall, so a hidden surface's light
// meets the wall's kernel twice, once leaving the spot and once at the
// sensor point. Shared by the CPU and GL backends' tests.

#include <cmath>
#include <cstddef>
#include <vector>

#include "HiddenPatch.h"
#include "tofsim/physics/TemporalResponse.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::pipeline::test {

// A lifetime of 5 bins (5 cm of path at the hidden patch's 1 cm bins), half
// the wall's light delayed.
constexpr double kWallLifetime_m = 0.05, kWallFraction = 0.5;

inline physics::ResponseKernel wallKernel() {
  physics::ResponseKernel k;
  k.lifetime_s = kWallLifetime_m / kSpeedOfLight_m_per_s;
  k.fraction = kWallFraction;
  return k;
}

// The hidden patch whose wall ("quad0", material 0) delays by wallKernel().
inline scene::Scene hiddenPatchBehindADelayedWall() {
  scene::Scene s = hiddenPatch();
  s.materials[0].scatteringDelay = wallKernel();
  return s;
}

// Point `point`'s histogram of `instant` (bin integrals of undelayed light)
// through the wall's kernel `times` times in cascade: the stage's own
// filter (physics::applyResponse) on the bin integrals as a difference buffer.
inline std::vector<double> throughTheWall(const NlosVolume& instant, std::size_t point, int times) {
  const auto bins = static_cast<std::size_t>(instant.axis.bins);
  const std::size_t points = instant.H.size() / bins;
  std::vector<double> diff(bins * 3, 0.0), scratch(bins * 3, 0.0);
  // x[n] = H[n] in channel 0: its second differences, which the stage sums twice.
  const auto x = [&](std::ptrdiff_t n) {
    return n < 0 ? 0.0 : double(instant.H[static_cast<std::size_t>(n) * points + point]);
  };
  for (std::size_t n = 0; n < bins; ++n) {
    const auto i = static_cast<std::ptrdiff_t>(n);
    diff[n * 3] = x(i) - 2.0 * x(i - 1) + x(i - 2);
  }
  const std::vector<physics::ResponseTaps> stages(
      static_cast<std::size_t>(times),
      physics::responseTaps(wallKernel(), instant.axis.bin_width_s));
  std::vector<float> histogram(bins * 3, 0.0f);
  physics::applyResponse(diff.data(), scratch.data(), static_cast<int32_t>(bins), 0, stages,
                         histogram.data());
  std::vector<double> out(bins);
  for (std::size_t n = 0; n < bins; ++n) out[n] = histogram[n * 3];
  return out;
}

// The largest difference of point `point`'s histogram in `delayed` from
// `expected`, relative to the histogram's peak.
inline double worstRelativeBin(const NlosVolume& delayed, std::size_t point,
                               const std::vector<double>& expected) {
  const auto bins = static_cast<std::size_t>(delayed.axis.bins);
  const std::size_t points = delayed.H.size() / bins;
  double peak = 0.0, worst = 0.0;
  for (std::size_t n = 0; n < bins; ++n) peak = std::max(peak, expected[n]);
  for (std::size_t n = 0; n < bins; ++n) {
    worst = std::max(worst, std::abs(double(delayed.H[n * points + point]) - expected[n]));
  }
  return worst / peak;
}

}  // namespace tofsim::pipeline::test
