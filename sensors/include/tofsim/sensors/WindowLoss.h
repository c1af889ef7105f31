#pragma once
// How much of the light a sensor is given falls outside its instrument
// window (InstrumentBins) and is dropped by it, so a run can say so.

#include <cstdint>
#include <vector>

#include "tofsim/sensors/SensorSpec.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::sensors {

/// Fraction in [0, 1] of the volume's energy as the sensor sees it (its channel
/// selection; for a streak camera its rows) that lies outside its window, each
/// render bin's energy spread uniformly over its interval as resampleEnergy
/// does. 0 for a sensor without a window (CW-ToF integrates every bin), for a
/// volume without energy, and for a channel selection that does not fit the
/// volume (runSensor reports that).
double windowLossFraction(const SensorParams& params, const TransientVolume& volume);

/// The same for one model's parts: its channel selection, instrument bins and
/// rows (all rows when empty). What SensorType<>::windowLossFraction calls.
double instrumentWindowLoss(const SensorCommon& common, const InstrumentBins& bins,
                            const std::vector<int32_t>& rows, const TransientVolume& volume);

}  // namespace tofsim::sensors
