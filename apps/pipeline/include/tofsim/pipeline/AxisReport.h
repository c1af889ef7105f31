#pragma once
// Light cut off by a time window, said out loud. Before a render the scene's
// arrival bounds (capture/ArrivalBounds.h) can prove that the time axis misses
// the light, or show that it may; after a render the light that landed before
// the first bin or after the last is measured. More than 0.1 % of the total
// off the axis (or off a sensor's instrument window) is a warning on stderr,
// shown even with -q, that names the axis that would hold it all; with
// render.strict (--strict) it is an error instead.

#include <cstdint>
#include <string>

#include "tofsim/capture/ArrivalBounds.h"
#include "tofsim/capture/RenderJob.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::pipeline {

/// Fraction of the light off the render axis above which a run warns.
inline constexpr double kWindowLossWarning = 0.001;

/// Surface vertices a path of the configured renderer can have: instant
/// radiosity 1, or 1 + render.indirect.bounces with indirect light; the
/// reference its bounces.
int32_t surfaceVertices(const config::RunConfig& config);

/// What the arrival bounds say about the render axis, before rendering.
struct AxisPrediction {
  enum class Verdict {
    Holds,   ///< every possible path lies on the axis
    MayCut,  ///< the axis starts after the shortest or ends before the longest bound
    Cuts,    ///< proven: the axis ends before the shortest or starts after the longest
  };
  Verdict verdict = Verdict::Holds;
  std::string message;  ///< one line for people; empty when the axis holds
};
AxisPrediction predictAxisCut(const config::RunConfig& config, const capture::RenderJob& job);

/// Before anything is written: an axis whose one bin is far wider than all
/// of the scene's arrivals together is an InputError (time.bin_width); a
/// proven cut is a warning on stderr, or with config.strict an InputError;
/// `notes` also prints a possible cut as a note (`tofsim validate`).
void checkAxisBeforeRender(const config::RunConfig& config, const capture::RenderJob& job,
                           bool notes);

/// Light off the axis as fractions of all the light (binned + off the axis);
/// 0 when nothing arrived. Needs result.onAxisEnergy.
struct AxisLossFractions {
  double before = 0.0;
  double after = 0.0;
};
AxisLossFractions axisLossFractions(const capture::RenderResult& result);

/// After rendering, before the outputs are committed: warns (config.strict:
/// throws InputError) when the axis lost more than kWindowLossWarning of the
/// light (result.onAxisEnergy filled in). (The sensors' windows are checked
/// as they stream: SensorStreams::checkWindows.)
void checkAxisAfterRender(const config::RunConfig& config, const capture::RenderJob& job,
                          const capture::RenderResult& result);

/// Sensor `index` of the config, whose window drops the fraction `lost` of
/// its light from a volume with time axis `axis`: warns (config.strict:
/// throws InputError) when that is more than kWindowLossWarning.
void checkSensorWindow(const config::RunConfig& config, std::size_t index, double lost,
                       const TimeAxis& axis);

}  // namespace tofsim::pipeline
