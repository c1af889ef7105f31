#pragma once
// Runs any configured sensor model on a volume.

#include <cstdint>
#include <vector>

#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/sensors/SensorSpec.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::sensors {

struct SensorInputs {
  const TransientVolume* volume = nullptr;      ///< required
  const Image* groundTruthDepth_m = nullptr;    ///< optional (H, W, 1), metres (CW-ToF MPI error)
  const TransientVolume* directOnly = nullptr;  ///< optional direct component (CW-ToF MPI error)
  uint64_t seed = 0;
};

/// Throws InputError when the spec does not fit the inputs (channel out of
/// range, rows outside the image, ...).
std::vector<SensorOutput> runSensor(const SensorSpec& spec, const SensorInputs& inputs);

}  // namespace tofsim::sensors
