#pragma once
// How much of the light a sensor is given falls outside its instrument
// window (InstrumentBins) and is dropped by it, so a run can say so. Measured
// as the volume streams (WindowLossMeter) or on a whole volume.

#include <cstdint>
#include <optional>
#include <vector>

#include "tofsim/sensors/SensorSpec.h"
#include "tofsim/sensors/SensorStream.h"
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
/// rows (all rows when empty).
double instrumentWindowLoss(const SensorCommon& common, const InstrumentBins& bins,
                            const std::vector<int32_t>& rows, const TransientVolume& volume);

/// The model's window (SensorType<>::window); none for CW-ToF.
std::optional<InstrumentWindow> instrumentWindow(const SensorParams& params);

/// windowLossFraction fed span by span (SensorStream.h): it keeps the energy
/// per render bin, summed over the pixels the sensor sees. Without a window
/// the fraction is 0.
class WindowLossMeter {
 public:
  WindowLossMeter(std::optional<InstrumentWindow> window, const VolumeShape& shape);
  void consume(const PixelSpan& span);
  /// After the last span (earlier: the fraction of what came so far).
  double fraction() const;

 private:
  std::optional<InstrumentWindow> window_;
  VolumeShape shape_;
  bool fits_ = false;
  std::vector<int32_t> rowWeight_;  // how often each image row is counted
  std::vector<double> perBin_, signal_;
};

}  // namespace tofsim::sensors
