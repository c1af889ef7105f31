#include "tofsim/sensors/RunSensor.h"

#include <type_traits>

#include "tofsim/util/Error.h"

namespace tofsim::sensors {

const char* sensorTypeName(const SensorParams& params) {
  return std::visit(
      [](const auto& p) -> const char* {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, StreakParams>) return "streak";
        if constexpr (std::is_same_v<P, SpadParams>) return "spad";
        return "cwtof";
      },
      params);
}

const SensorOutput* findOutput(const std::vector<SensorOutput>& outputs, const std::string& name,
                               SensorOutput::Kind kind) {
  for (const SensorOutput& o : outputs) {
    if (o.name == name && o.kind == kind) return &o;
  }
  return nullptr;
}

std::vector<SensorOutput> runSensor(const SensorSpec& spec, const SensorInputs& in) {
  TOFSIM_CHECK(in.volume != nullptr);
  return std::visit(
      [&](const auto& p) -> std::vector<SensorOutput> {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, StreakParams>) return runStreak(*in.volume, p, in.seed);
        if constexpr (std::is_same_v<P, SpadParams>) return runSpad(*in.volume, p, in.seed);
        if constexpr (std::is_same_v<P, CwTofParams>) {
          return runCwTof(*in.volume, p, in.seed,
                          CwTofReferences{in.groundTruthDepth_m, in.directOnly});
        }
      },
      spec.params);
}

}  // namespace tofsim::sensors
