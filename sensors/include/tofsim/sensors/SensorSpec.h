#pragma once
// One configured sensor: a name and the parameters of one model.

#include <string>
#include <variant>

#include "tofsim/sensors/SensorType.h"

namespace tofsim::sensors {

/// Every model, once. A new alternative needs a SensorType<> specialisation
/// (checked here) and a config descriptor (checked in apps/config).
using SensorParams = std::variant<StreakParams, SpadParams, CwTofParams, ApdParams>;

namespace detail {
template <typename... P>
constexpr bool allDescribed(const std::variant<P...>*) {
  return (SensorModel<P> && ...);
}
}  // namespace detail
static_assert(detail::allDescribed(static_cast<const SensorParams*>(nullptr)),
              "every SensorParams alternative needs a complete SensorType<> (SensorType.h)");

struct SensorSpec {
  std::string name;  ///< label for logs and output folders; defaults to the type
  SensorParams params;
};

/// The model's SensorType<>::name: "streak", "spad", "cwtof" or "apd".
const char* sensorTypeName(const SensorParams& params);

/// Upper estimate of the bytes a sensor's files take (SensorType<>::outputBytes).
std::uintmax_t sensorOutputBytes(const SensorParams& params, int32_t width, int32_t height,
                                 const TimeAxis& render);

}  // namespace tofsim::sensors
