#pragma once
// The indirect gather's footprint deposit for one pixel and one block of
// VPLs: each visible contribution spread by its footprint kernel (vplTerms'
// centre, wide, narrow), narrow kernels straight into the pixel's float
// histogram, wide ones into its double difference buffer. The same float and
// double operations as physics::depositContribution, contribution by
// contribution in the order given, so the bytes are those of the scalar
// deposit. With AVX2 (chosen at run time) a narrow kernel's bin masses are
// computed eight bins per instruction, and its bins' three channels added with
// three vector additions per eight bins when the kernel lies on the axis.

#include <cstddef>
#include <cstdint>

#include "GatherKernel.h"
#include "tofsim/physics/FootprintBuffer.h"

namespace tofsim::cpu {

/// A visible contribution of a block: lane `lane` of sample `sample`'s terms.
struct BlockPair {
  uint32_t sample = 0;
  uint32_t lane = 0;
};

/// Widens the bins [first, last] of a difference buffer to those
/// physics::depositFootprint may write for the wide kernel `kernel`: from
/// its first kink's bin to two past its last kink's (none past the axis).
void widenToWideKernel(const glm::vec3& kernel, int32_t bins, int32_t& first, int32_t& last);

/// Adds the contributions pairs[0, count), in that order, of `terms` (one
/// VplTerms per sample of the pixel) through their footprint kernels: narrow
/// ones (terms' count > 0) into `histogram` (bins x 3 floats), wide ones into
/// `diff` (bins x 3 doubles, physics::depositWide), the light off the axis
/// into `lost`; [first, last] widened to the bins of `diff` written.
void depositFootprints(const VplTerms* terms, const BlockPair* pairs, std::size_t count,
                       int32_t bins, float* histogram, double* diff, physics::OffAxisSums& lost,
                       int32_t& first, int32_t& last);

/// One narrow kernel's contribution (first = footprintNarrowFirstBin, count =
/// footprintNarrowBinCount): physics::depositNarrow's bytes, with AVX2 where
/// the CPU has it. For the tests.
void depositNarrowKernel(float* histogram, int32_t bins, const glm::vec3& kernel, int32_t first,
                         int32_t count, const glm::vec3& energy, physics::OffAxisSums& lost);

}  // namespace tofsim::cpu
