#pragma once
// One configured sensor: a name and the parameters of one model.

#include <string>
#include <variant>

#include "tofsim/sensors/CwTof.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/sensors/Streak.h"

namespace tofsim::sensors {

using SensorParams = std::variant<StreakParams, SpadParams, CwTofParams>;

struct SensorSpec {
  std::string name;  ///< label for logs and output folders; defaults to the type
  SensorParams params;
};

/// "streak", "spad" or "cwtof".
const char* sensorTypeName(const SensorParams& params);

}  // namespace tofsim::sensors
