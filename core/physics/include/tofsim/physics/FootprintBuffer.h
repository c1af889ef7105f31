#pragma once
// The two buffer passes around the footprint kernel (FootprintKernel.h), as
// the CPU gather runs them and as the reference the GL passes are tested
// against: deposit one contribution into a pixel's difference buffer, and the
// final per-pixel double prefix sum that turns the buffer into bin integrals.
//
// Layout: one pixel's difference buffer is bins x 3 doubles, (bin, channel),
// the volume's order; zeroed before the pixel's first contribution. Doubles
// because the double prefix sum amplifies an entry's rounding error by the
// distance to the end of the axis (core/physics/footprint_kernel.md).

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "tofsim/physics/FootprintKernel.h"

namespace tofsim::physics {

/// Mass of a contribution off the time axis, per unit of energy.
struct FootprintOffAxis {
  double before = 0.0;
  double after = 0.0;
};

/// Adds a contribution of `energy` (per channel) spread by `kernel` to one
/// pixel's difference buffer `diff` (bins x 3). Writes at most FOOTPRINT_SLOTS
/// bins, whatever the kernel's width, each once, in increasing bin order.
/// Returns the fraction of the energy before and after the axis, which the
/// caller books as off-axis energy (it is not in the buffer).
inline FootprintOffAxis depositFootprint(double* diff, int32_t bins, const vec3& kernel,
                                         const vec3& energy) {
  // footprintSlotBin and footprintSlotValue with the kinks and their bins
  // computed once, and each slot's sum over the four kinks taken only over
  // the kinks within reach of its bin: the others' weights are exactly 0, so
  // the entries have the same bits at a fraction of the work. Each kink's
  // weights at its three bins are computed once, in a fixed order (no
  // branches that depend on how the kinks' bins overlap), and each slot
  // takes those of the kinks within reach.
  double knot[4];
  int knotBin[4];
  for (int j = 0; j < 4; ++j) {
    knot[j] = footprintKnot(kernel, j);
    knotBin[j] = footprintKnotBin(kernel, j, bins);
  }
  if (knot[3] < 0.0 || knot[0] >= static_cast<double>(bins)) {
    return {footprintMassBefore(kernel), footprintMassAfter(kernel, bins)};  // wholly off
  }
  const double wide = static_cast<double>(kernel.y);
  const bool fromCdf = knot[0] < 2.0 || wide < 1.0;
  const bool step = static_cast<double>(kernel.z) < static_cast<double>(1e-6f);
  const double scale = step ? 1.0 / wide : 1.0 / (wide * static_cast<double>(kernel.z));
  double weight[4][3];  // footprintKinkWeight(knot[i], knotBin[i] + o, step)
  if (!fromCdf) {
    for (int i = 0; i < 4; ++i) {
      for (int o = 0; o < 3; ++o) weight[i][o] = footprintKinkWeight(knot[i], knotBin[i] + o, step);
    }
  }
  for (int j = 0; j < 4; ++j) {
    for (int o = 0; o < 3; ++o) {
      const int bin = knotBin[j] + o;
      if (bin >= bins || (j > 0 && bin <= knotBin[j - 1] + 2)) continue;
      double value;
      if (fromCdf) {
        value = footprintSlotValue(kernel, bin);
      } else {
        double w[4];
        for (int i = 0; i < 4; ++i) {
          const int reach = bin - knotBin[i];  // kink i's weight is 0 outside its three bins
          w[i] = reach >= 0 && reach <= 2 ? weight[i][reach] : 0.0;
        }
        value = step ? scale * (w[0] - w[3]) : scale * (w[0] - w[1] - w[2] + w[3]);
      }
      double* entry = diff + static_cast<std::size_t>(bin) * 3;
      for (int c = 0; c < 3; ++c) entry[c] += value * static_cast<double>(energy[c]);
    }
  }
  // F(0) is exactly 0 when the kernel starts on the axis, 1 - F(bins) when it ends on it.
  return {knot[0] >= 0.0 ? 0.0 : footprintMassBefore(kernel),
          knot[3] < static_cast<double>(bins) ? 0.0 : footprintMassAfter(kernel, bins)};
}

/// Light of one pixel's contributions that fell off the axis, summed over
/// channels, as the gathers book it (AxisLoss).
struct OffAxisSums {
  float before = 0.0f;
  float after = 0.0f;
};

/// Adds `mass` of a contribution `energy` to bin k of a pixel's float
/// histogram, or to the light off the axis: a narrow kernel's share of a bin,
/// or with mass 1 a point sample's whole contribution (1 x e is e exactly).
/// The gathers' depositInBin (shaders/bin_deposit.glsl) is its twin.
inline void depositInBin(float* histogram, int32_t bins, int k, float mass, const vec3& energy,
                         OffAxisSums& lost) {
  if (k < 0 || k >= bins) {
    (k < 0 ? lost.before : lost.after) += mass * (energy.r + energy.g + energy.b);
    return;
  }
  float* out = histogram + static_cast<std::size_t>(k) * 3;
  out[0] += mass * energy.r;
  out[1] += mass * energy.g;
  out[2] += mass * energy.b;
}

/// A wide kernel's contribution: into the difference buffer, and its mass
/// off the axis into `lost`.
inline void depositWide(double* diff, int32_t bins, const vec3& kernel, const vec3& energy,
                        OffAxisSums& lost) {
  const float total = energy.r + energy.g + energy.b;
  const FootprintOffAxis off = depositFootprint(diff, bins, kernel, energy);
  if (off.before > 0.0) lost.before += static_cast<float>(off.before) * total;
  if (off.after > 0.0) lost.after += static_cast<float>(off.after) * total;
}

/// A narrow kernel's contribution (footprintIsNarrow): its bin masses
/// straight into the float histogram, or off the axis into `lost`.
inline void depositNarrow(float* histogram, int32_t bins, const vec3& kernel, const vec3& energy,
                          OffAxisSums& lost) {
  const int first = footprintNarrowFirstBin(kernel, bins);
  const int count = footprintNarrowBinCount(kernel);
  // Each edge's CDF once, carried to the next bin: footprintNarrowMass's values.
  float lower = 0.0f;
  for (int j = 0; j < count; ++j) {
    const float upper = footprintNarrowEdgeCdf(kernel, j);
    depositInBin(histogram, bins, first + j, upper - lower, energy, lost);
    lower = upper;
  }
}

/// Adds one contribution of `energy` spread by `kernel` to a pixel: narrow
/// into its float `histogram`, wide into its difference buffer `diff` (zero
/// before the pixel's first wide kernel); the part off the axis into `lost`.
/// Returns whether `diff` was written (the pixel then needs
/// integrateFootprint). The GL gathers' footprint_deposit.glsl does the same.
inline bool depositContribution(float* histogram, double* diff, int32_t bins, const vec3& kernel,
                                const vec3& energy, OffAxisSums& lost) {
  if (footprintIsNarrow(kernel)) {
    depositNarrow(histogram, bins, kernel, energy, lost);
    return false;
  }
  depositWide(diff, bins, kernel, energy, lost);
  return true;
}

/// The final pass for one pixel: adds the bin integrals held by `diff`
/// (bins x 3, as depositFootprint left it) to `histogram` (bins x 3 floats).
/// Running sums in double, each channel's bins in increasing order: the GL
/// pass must keep this order to give the same bytes. The three channels'
/// sums are independent, so one pass runs them side by side (three chains of
/// dependent additions at once, not one after the other; the same additions).
inline void integrateFootprint(const double* diff, int32_t bins, float* histogram) {
  double slope[3] = {0.0, 0.0, 0.0};  // first prefix sum: I_k - I_(k-1)
  double value[3] = {0.0, 0.0, 0.0};  // second prefix sum: I_k
  for (int32_t k = 0; k < bins; ++k) {
    const std::size_t i = static_cast<std::size_t>(k) * 3;
    for (int c = 0; c < 3; ++c) {
      slope[c] += diff[i + c];
      value[c] += slope[c];
      histogram[i + c] += static_cast<float>(value[c]);
    }
  }
}

}  // namespace tofsim::physics
