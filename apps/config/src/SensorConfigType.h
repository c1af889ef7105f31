#pragma once
// Private to the config module: the config side of each sensor model's
// descriptor (sensors/SensorType.h holds the model side). Parse, emit and the
// checks against the image are declared here once per model; a SensorParams
// alternative without all three does not compile (the static_assert below).
// Definitions: SensorConfigParser.cpp (parse, checkImage) and
// SensorConfigEmitter.cpp (emit), one block per model.

#include <yaml-cpp/yaml.h>

#include <concepts>
#include <variant>

#include "ConfigNode.h"
#include "tofsim/capture/Camera.h"
#include "tofsim/sensors/SensorSpec.h"

namespace tofsim::config {

/// Specialised once per model, below; never defined for anything else.
template <typename Params>
struct SensorConfigType;

template <typename P>
concept ConfiguredSensor = requires(const ConfigNode& node, YAML::Node& yaml, const P& p,
                                    const capture::Camera& camera) {
  /// The model's keys of one `sensors:` entry (type and name are read by the caller).
  { SensorConfigType<P>::parse(node) } -> std::same_as<P>;
  /// Writes them back, defaults filled in, in the keys and units parse reads.
  { SensorConfigType<P>::emit(yaml, p) } -> std::same_as<void>;
  /// Located error for rows or pixels outside the image, before the render.
  { SensorConfigType<P>::checkImage(node, p, camera) } -> std::same_as<void>;
};

#define TOFSIM_SENSOR_CONFIG_TYPE(Params)                                    \
  template <>                                                                \
  struct SensorConfigType<sensors::Params> {                                 \
    static sensors::Params parse(const ConfigNode& node);                    \
    static void emit(YAML::Node& yaml, const sensors::Params& p);            \
    static void checkImage(const ConfigNode& node, const sensors::Params& p, \
                           const capture::Camera& camera);                   \
  }

TOFSIM_SENSOR_CONFIG_TYPE(StreakParams);
TOFSIM_SENSOR_CONFIG_TYPE(SpadParams);
TOFSIM_SENSOR_CONFIG_TYPE(CwTofParams);
TOFSIM_SENSOR_CONFIG_TYPE(ApdParams);
#undef TOFSIM_SENSOR_CONFIG_TYPE

namespace detail {
template <typename... P>
constexpr bool allConfigured(const std::variant<P...>*) {
  return (ConfiguredSensor<P> && ...);
}
}  // namespace detail
static_assert(detail::allConfigured(static_cast<const sensors::SensorParams*>(nullptr)),
              "every SensorParams alternative needs a SensorConfigType<> (SensorConfigType.h)");

}  // namespace tofsim::config
