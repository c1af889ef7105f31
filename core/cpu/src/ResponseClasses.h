#pragma once
// The CPU's delayed response classes (core/physics/temporal_response.md): per
// delayed class and pixel of a segment, a difference buffer (bins x 3
// doubles, footprint_kernel.md's layout) that the class's contributions are
// deposited into, and the stage that, at the pixel's integrate step, sums it
// into bin integrals, filters them by the cascade of the class's kernels
// (physics::applyResponse) and adds them to the pixel's histogram. Class 0,
// the instant one, is not here: it is the backend's float histograms and
// footprint buffer of before. Without delayed classes (every render today)
// nothing is allocated and integrateInto returns at once.
//
// One writer per pixel, as the gathers: deposits and the integrate step of
// pixel i touch only pixel i's entries.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "tofsim/physics/FootprintBuffer.h"
#include "tofsim/physics/TemporalResponse.h"
#include "tofsim/util/ZeroedBuffer.h"

namespace tofsim::cpu {

class ResponseClasses {
 public:
  /// Class c >= 1 filters by the cascade delayed[c - 1] (its members'
  /// filters in order, physics::classStages); room for `pixels` pixels of
  /// `bins` bins each (zeroed). An empty list frees everything.
  void configure(std::vector<std::vector<physics::ResponseTaps>> delayed, std::size_t pixels,
                 int32_t bins);
  bool empty() const { return stages_.empty(); }
  /// Delayed classes (the ids 1 .. count()).
  std::size_t count() const { return stages_.size(); }

  /// Adds a contribution of `energy` spread by footprint `kernel` (a spike
  /// with widths 0) of delayed class `responseClass` (1 .. count()) to
  /// pixel i: its exact bin integrals, however narrow, into the class's
  /// difference buffer (physics::depositWide); its light off the axis into
  /// `lost`.
  void deposit(std::size_t i, uint32_t responseClass, const glm::vec3& kernel,
               const glm::vec3& energy, physics::OffAxisSums& lost);
  /// deposit of a point sample (render.pixel_footprint: false) in bin `bin`:
  /// a spike at the bin's centre (its sub-bin position is not kept, as in
  /// the instant light's physics::depositInBin; core/physics/temporal_response.md).
  void depositInBin(std::size_t i, uint32_t responseClass, int32_t bin, const glm::vec3& energy,
                    physics::OffAxisSums& lost) {
    deposit(i, responseClass, glm::vec3(static_cast<float>(bin) + 0.5f, 0.0f, 0.0f), energy, lost);
  }
  /// The integrate step of pixel i: every delayed class's light, filtered by
  /// its kernel, added to `histogram` (bins x 3 floats) in class order; the
  /// light the kernels carry past the last bin into lost.after. Leaves the
  /// pixel's buffers zero.
  void integrateInto(std::size_t i, float* histogram, physics::OffAxisSums& lost);
  /// Zeroes every pixel's buffers (a segment left unfinished).
  void clear();

 private:
  double* diffOf(std::size_t i, uint32_t responseClass);

  std::vector<std::vector<physics::ResponseTaps>> stages_;
  bool cascades_ = false;  ///< some class has several stages (a scratch per thread)
  std::size_t pixels_ = 0;
  int32_t bins_ = 0;
  util::ZeroedBuffer<double> diff_;  ///< [class - 1][pixel][bin][channel]
  /// Per (class - 1, pixel): the first bin written, bins_ when none.
  std::vector<int32_t> first_;
};

}  // namespace tofsim::cpu
