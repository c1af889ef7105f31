#pragma once
// What a sensor model is given: the volume and, for the CW-ToF multipath
// errors, the optional references.

#include <cstdint>
#include <vector>

#include "tofsim/volume/TransientVolume.h"  // TransientVolume, Image

namespace tofsim::sensors {

struct SensorInputs {
  const TransientVolume* volume = nullptr;      ///< required
  const Image* groundTruthDepth_m = nullptr;    ///< optional (H, W, 1), metres (CW-ToF MPI error)
  const TransientVolume* directOnly = nullptr;  ///< optional direct component (CW-ToF MPI error)
  /// Optional bounces 1..N of the render, with directOnly (CW-ToF error by bounce order).
  const std::vector<const TransientVolume*>* bounces = nullptr;
  uint64_t seed = 0;
};

}  // namespace tofsim::sensors
